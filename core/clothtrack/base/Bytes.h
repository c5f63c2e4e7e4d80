#pragma once
// Plain values written to and read from a string of bytes, for results that processes exchange
// (the machines of one run share a byte order). A read past the end throws Error.
#include "Error.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

namespace clothtrack
{
class ByteWriter
{
public:
  template <class T> void put(const T& value)
  {
    static_assert(std::is_trivially_copyable_v<T>, "plain values only");
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void putText(const std::string& text)
  {
    put(static_cast<std::uint32_t>(text.size()));
    bytes_ += text;
  }
  std::string take() { return std::move(bytes_); }

private:
  std::string bytes_;
};

class ByteReader
{
public:
  /// `what` names the message in errors.
  ByteReader(const std::string& bytes, const char* what) : bytes_(bytes), what_(what) {}

  template <class T> T get()
  {
    static_assert(std::is_trivially_copyable_v<T>, "plain values only");
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string getText()
  {
    const auto size = get<std::uint32_t>();
    need(size);
    std::string text = bytes_.substr(at_, size);
    at_ += size;
    return text;
  }
  bool done() const { return at_ == bytes_.size(); }
  /// Throws unless every byte was read.
  void expectEnd() const
  {
    if (!done()) throw Error(std::string(what_) + ": trailing bytes");
  }

private:
  void need(size_t size) const
  {
    if (bytes_.size() - at_ < size) throw Error(std::string(what_) + ": truncated message");
  }
  const std::string& bytes_;
  const char* what_;
  size_t at_ = 0;
};
} // namespace clothtrack

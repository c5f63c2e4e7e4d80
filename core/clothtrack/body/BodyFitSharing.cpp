#include "BodyFitSharing.h"

#include "BodyFit.h"

#include <clothtrack/base/Error.h>

#include <cstdint>
#include <cstring>

namespace clothtrack
{
namespace
{
/// Bumped with any change of the layout below.
constexpr std::uint32_t kLayout = 0x43544231; // "CTB1"

class Writer
{
public:
  template <class T> void put(const T& value)
  {
    const char* p = reinterpret_cast<const char*>(&value);
    bytes_.append(p, sizeof(T));
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

class Reader
{
public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <class T> T get()
  {
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

private:
  void need(size_t size) const
  {
    if (bytes_.size() - at_ < size) throw Error("shared body fit: truncated message");
  }
  const std::string& bytes_;
  size_t at_ = 0;
};

void putFit(Writer& w, const BodyFrameFit& f)
{
  for (int j = 0; j < NumJoints; ++j)
    for (int c = 0; c < 3; ++c) w.put(f.pose.rotations(j, c));
  for (int c = 0; c < 3; ++c) w.put(f.pose.translation[c]);
  w.put(static_cast<std::int32_t>(f.status));
  w.putText(f.message);
  for (double v : {f.energy, f.medianDistance, f.insideFraction, f.frameDistance, f.previousGap})
    w.put(v);
  w.put(static_cast<std::int32_t>(f.extremitiesDetected));
  w.put(static_cast<std::int32_t>(f.extremitiesMatched));
  w.put(static_cast<std::uint8_t>(f.continuesPrevious));
  w.put(static_cast<std::uint32_t>(f.extremities.size()));
  for (const Vec3& e : f.extremities)
    for (int c = 0; c < 3; ++c) w.put(e[c]);
}

BodyFrameFit getFit(Reader& r)
{
  BodyFrameFit f;
  for (int j = 0; j < NumJoints; ++j)
    for (int c = 0; c < 3; ++c) f.pose.rotations(j, c) = r.get<double>();
  for (int c = 0; c < 3; ++c) f.pose.translation[c] = r.get<double>();
  f.status = static_cast<BodyFitStatus>(r.get<std::int32_t>());
  f.message = r.getText();
  for (double* v :
       {&f.energy, &f.medianDistance, &f.insideFraction, &f.frameDistance, &f.previousGap})
    *v = r.get<double>();
  f.extremitiesDetected = r.get<std::int32_t>();
  f.extremitiesMatched = r.get<std::int32_t>();
  f.continuesPrevious = r.get<std::uint8_t>() != 0;
  f.extremities.resize(r.get<std::uint32_t>());
  for (Vec3& e : f.extremities)
    for (int c = 0; c < 3; ++c) e[c] = r.get<double>();
  return f;
}
} // namespace

std::string encodeFrameFits(const std::vector<BodyFrameFit>& fits, const std::vector<int>& frames)
{
  Writer w;
  w.put(kLayout);
  w.put(static_cast<std::uint32_t>(frames.size()));
  for (int i : frames)
  {
    w.put(static_cast<std::int32_t>(i));
    putFit(w, fits.at(i));
  }
  return w.take();
}

void decodeFrameFits(const std::string& bytes, std::vector<BodyFrameFit>& fits)
{
  Reader r(bytes);
  if (r.get<std::uint32_t>() != kLayout) throw Error("shared body fit: message of another layout");
  const auto count = r.get<std::uint32_t>();
  for (std::uint32_t k = 0; k < count; ++k)
  {
    const auto i = r.get<std::int32_t>();
    if (i < 0 || i >= static_cast<std::int32_t>(fits.size()))
      throw Error("shared body fit: frame " + std::to_string(i) + " out of range");
    fits[i] = getFit(r);
  }
  if (!r.done()) throw Error("shared body fit: trailing bytes");
}
} // namespace clothtrack

#include "FileBytes.h"

#include <clothtrack/base/Error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace clothtrack
{
namespace
{
using OpenFile = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

OpenFile openForReading(const std::string& path)
{
  OpenFile file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw Error(path + ": cannot open file (" + std::strerror(errno) + ")");
  return file;
}
} // namespace

void requireNonEmptyFile(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path + ": no such file");
  if (!fs::is_regular_file(path, ec)) throw Error(path + ": not a regular file");
  if (fs::file_size(path, ec) == 0) throw Error(path + ": empty file");
}

std::string readFileBytes(const std::string& path, bool text)
{
  const OpenFile file = openForReading(path);
  std::string bytes;
  // One read of the size the file has; a file that is not seekable (a pipe) or that grows while
  // read is taken in chunks to its end.
  long size = -1;
  if (std::fseek(file.get(), 0, SEEK_END) == 0) size = std::ftell(file.get());
  std::rewind(file.get());
  if (size > 0) bytes.resize(static_cast<size_t>(size));
  size_t used = bytes.size() > 0 ? std::fread(bytes.data(), 1, bytes.size(), file.get()) : 0;
  bytes.resize(used);
  char chunk[65536];
  for (size_t got; (got = std::fread(chunk, 1, sizeof(chunk), file.get())) > 0;)
    bytes.append(chunk, got);
  if (std::ferror(file.get())) throw Error(path + ": read error");
  if (text && bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) bytes.erase(0, 3);
  return bytes;
}

std::string readFileStart(const std::string& path,
                          const std::function<bool(const std::string& bytes)>& enough)
{
  const OpenFile file = openForReading(path);
  std::string bytes;
  char chunk[65536];
  for (size_t got; !enough(bytes) && (got = std::fread(chunk, 1, sizeof(chunk), file.get())) > 0;)
    bytes.append(chunk, got);
  if (std::ferror(file.get())) throw Error(path + ": read error");
  return bytes;
}

std::uintmax_t fileSizeOf(const std::string& path)
{
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(path + ": " + ec.message());
  return size;
}
} // namespace clothtrack

#include "FileContents.h"
#include "FileBytes.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace clothtrack
{
namespace
{
struct ThreadBuffer
{
  std::unique_ptr<char[]> bytes;
  std::size_t capacity = 0;
  bool inUse = false;
};
thread_local ThreadBuffer threadBuffer;
constexpr std::size_t maximumKeptBytes = std::size_t(64) << 20;

#ifdef CLOTHTRACK_EXACT_FILE_BUFFERS
constexpr bool reuseBuffers = false;
#else
constexpr bool reuseBuffers = true;
#endif

/// Reads up to `size` bytes; fewer when the file shrank since its size was taken.
std::size_t readAll(int fd, char* into, std::size_t size, const std::string& path)
{
  std::size_t got = 0;
  while (got < size)
  {
    const ssize_t n = ::read(fd, into + got, size - got);
    if (n == 0) break;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error(path + ": read error (" + std::strerror(errno) + ")");
    got += static_cast<std::size_t>(n);
  }
  return got;
}

/// Closes the file descriptor however the reading ends.
struct FileDescriptor
{
  int fd;
  ~FileDescriptor() { ::close(fd); }
};
} // namespace

FileContents::FileContents(const std::string& path, bool text)
{
  const FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw Error(path + ": cannot open file (" + std::strerror(errno) + ")");
  struct stat status = {};
  const bool sized =
      ::fstat(file.fd, &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0;
  if (!sized)
  {
    // Not a regular file, or one whose size says nothing (/proc): read in chunks to its end.
    const std::string bytes = readFileBytes(path, false);
    own_.reset(new char[bytes.size()]);
    std::copy(bytes.begin(), bytes.end(), own_.get());
    bytes_ = std::string_view(own_.get(), bytes.size());
  }
  else
  {
    const auto size = static_cast<std::size_t>(status.st_size);
    const bool reuse = reuseBuffers && !threadBuffer.inUse && size <= maximumKeptBytes;
    if (reuse && threadBuffer.capacity < size)
    {
      threadBuffer.bytes.reset(new char[size]);
      threadBuffer.capacity = size;
    }
    if (!reuse) own_.reset(new char[size]);
    char* into = reuse ? threadBuffer.bytes.get() : own_.get();
    bytes_ = std::string_view(into, readAll(file.fd, into, size, path));
    holdsThreadBuffer_ = reuse;
    if (reuse) threadBuffer.inUse = true; // only once read: a read error leaves it free
  }
  if (text && bytes_.substr(0, 3) == "\xEF\xBB\xBF") bytes_.remove_prefix(3);
}

FileContents::~FileContents()
{
  if (holdsThreadBuffer_) threadBuffer.inUse = false;
}
} // namespace clothtrack

#include "FileBytes.h"

#include <clothtrack/base/Error.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace clothtrack
{
std::string readFileBytes(const std::string& path, bool text)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open file (" + std::strerror(errno) + ")");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw Error(path + ": read error");
  std::string bytes = buffer.str();
  if (text && bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) bytes.erase(0, 3);
  return bytes;
}
} // namespace clothtrack

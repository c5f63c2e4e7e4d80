#pragma once
// A whole input file in memory, read into a buffer each thread keeps from file to file.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace clothtrack
{
/// The bytes of a file, for the text parsers. A regular file is read with one read() into a
/// buffer the thread keeps for the next file (up to 64 MB): frame after frame lands in the same
/// pages, which spares the page faults of a fresh allocation, the larger share of a parser's time
/// on meshes of a few MB. A larger file, one read while another is held in the same thread, or one
/// that is not regular (a pipe, /proc) gets a buffer of its own. An Error naming the file when it
/// cannot be opened or read. With `text`, a leading UTF-8 byte order mark is left out of bytes().
/// Built with CLOTHTRACK_EXACT_FILE_BUFFERS (the fuzz targets), every file gets a buffer of exactly
/// its size, so that AddressSanitizer sees a read past its last byte.
class FileContents
{
public:
  explicit FileContents(const std::string& path, bool text = true);
  ~FileContents();
  FileContents(const FileContents&) = delete;
  FileContents& operator=(const FileContents&) = delete;

  std::string_view bytes() const { return bytes_; }

private:
  std::unique_ptr<char[]> own_; ///< the bytes when not in the thread's buffer
  bool holdsThreadBuffer_ = false;
  std::string_view bytes_;
};
} // namespace clothtrack

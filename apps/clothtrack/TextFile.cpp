#include "TextFile.h"

#include "Commands.h"

#include <filesystem>

namespace clothtrack::app
{
void writeTextAtomically(const std::string& path, const std::string& text)
{
  AtomicTextFile file(path);
  file << text;
  file.commit();
}

AtomicTextFile::AtomicTextFile(std::string path) : path_(std::move(path)), out_(path_ + ".part") {}

AtomicTextFile::~AtomicTextFile()
{
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(path_ + ".part", ignored);
}

AtomicTextFile& AtomicTextFile::operator<<(std::string_view text)
{
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  written_ += text.size();
  return *this;
}

void AtomicTextFile::commit()
{
  out_.close();
  if (!out_) throw UsageError{path_ + ": cannot write file"};
  std::error_code error;
  std::filesystem::rename(path_ + ".part", path_, error);
  if (error) throw UsageError{path_ + ": cannot write file (" + error.message() + ")"};
  committed_ = true;
}
} // namespace clothtrack::app

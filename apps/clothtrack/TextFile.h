#pragma once
// Writing text outputs (JSON, CSV) so that no half-written file is ever taken for a result:
// write beside, then rename.
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

namespace clothtrack::app
{
/// Writes `text` to path.part then renames it to path; UsageError when it cannot.
void writeTextAtomically(const std::string& path, const std::string& text);

/// The same for a text written piece by piece (a record per frame), so that a long sequence's
/// output is never held whole in memory. Nothing appears at `path` before commit().
class AtomicTextFile
{
public:
  explicit AtomicTextFile(std::string path);
  AtomicTextFile(const AtomicTextFile&) = delete;
  AtomicTextFile& operator=(const AtomicTextFile&) = delete;
  /// Removes the part file when commit() was not reached.
  ~AtomicTextFile();

  AtomicTextFile& operator<<(std::string_view text);
  /// Flushes, closes and renames; UsageError when any write failed.
  void commit();
  /// Bytes written so far: where the next piece starts in the file.
  std::uint64_t written() const { return written_; }

private:
  std::string path_;
  std::ofstream out_;
  bool committed_ = false;
  std::uint64_t written_ = 0;
};
} // namespace clothtrack::app

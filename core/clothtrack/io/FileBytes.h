#pragma once
// A whole input file in memory, for the strict readers that check every declared size against it.
#include <cstdint>
#include <functional>
#include <string>

namespace clothtrack
{
/// The file's bytes; an Error naming the file when it cannot be opened or read. A leading UTF-8
/// byte order mark, which some editors add to text files, is dropped when `text`.
std::string readFileBytes(const std::string& path, bool text = true);

/// The file's first bytes, read in chunks until `enough` says the bytes read so far suffice, or to
/// its end: a header checked without reading the data behind it. Errors as readFileBytes.
std::string readFileStart(const std::string& path,
                          const std::function<bool(const std::string& bytes)>& enough);

/// The file's size in bytes; an Error naming the file when it has none.
std::uintmax_t fileSizeOf(const std::string& path);

/// An Error naming the file unless `path` is an existing, non-empty regular file.
void requireNonEmptyFile(const std::string& path);
} // namespace clothtrack

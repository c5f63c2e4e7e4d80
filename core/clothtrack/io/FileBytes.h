#pragma once
// A whole input file in memory, for the strict readers that check every declared size against it.
#include <string>

namespace clothtrack
{
/// The file's bytes; an Error naming the file when it cannot be opened or read. A leading UTF-8
/// byte order mark, which some editors add to text files, is dropped when `text`.
std::string readFileBytes(const std::string& path, bool text = true);

/// An Error naming the file unless `path` is an existing, non-empty regular file.
void requireNonEmptyFile(const std::string& path);
} // namespace clothtrack

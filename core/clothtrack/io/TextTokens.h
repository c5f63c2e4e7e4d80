#pragma once
// Reading numbers from text lines, shared by the text formats the core parses itself (OBJ, OFF,
// XYZ), so that they accept the same numbers.
#include <string_view>
#include <vector>

namespace clothtrack
{
/// Space, tab or carriage return (a line's own separators).
inline bool isSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r';
}

/// Splits one line into whitespace-separated tokens, views into the line: no allocation once the
/// vector has grown to the longest line.
void tokenize(const char* begin, const char* end, std::vector<std::string_view>& tokens);

/// The whole token as a number, as strtod reads it (std::from_chars first: several times faster,
/// the same rounding). False for anything else or an overflow.
bool parseDouble(std::string_view token, double& value);
} // namespace clothtrack

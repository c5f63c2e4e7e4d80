#include "TextTokens.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace clothtrack
{
void tokenize(const char* begin, const char* end, std::vector<std::string_view>& tokens)
{
  tokens.clear();
  const char* p = begin;
  while (p < end)
  {
    while (p < end && isSpace(*p)) ++p;
    const char* start = p;
    while (p < end && !isSpace(*p)) ++p;
    if (p > start) tokens.emplace_back(start, static_cast<size_t>(p - start));
  }
}

namespace
{
/// strtod's reading of the whole token: the reference for what a coordinate is.
bool parseDoubleSlowly(std::string_view token, double& value)
{
  const std::string s(token);
  char* endp = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &endp);
  // ERANGE also flags an underflow to a denormal or zero, which is a fine coordinate.
  const bool overflow = errno == ERANGE && std::abs(value) > 1.0;
  return endp != s.c_str() && *endp == '\0' && !overflow;
}
} // namespace

std::string lineLocation(const std::string& path, int line)
{
  return path + ":" + std::to_string(line) + ": ";
}

bool parseIndex(std::string_view token, long& value)
{
  const char* begin = token.data();
  const char* end = begin + token.size();
  if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-') ++begin;
  const auto [stop, error] = std::from_chars(begin, end, value);
  return error == std::errc() && stop != begin && (stop == end || *stop == '/');
}

bool parseDouble(std::string_view token, double& value)
{
  // std::from_chars is several times faster than strtod and rounds the same; what it does not
  // take whole (a '+' sign, hexadecimal, out of range) goes to strtod, so both accept the same.
  const char* begin = token.data();
  const char* end = begin + token.size();
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error == std::errc() && stop == end) return true;
  return parseDoubleSlowly(token, value);
}
} // namespace clothtrack

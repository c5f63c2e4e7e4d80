// Object File Format, read word by word from the file's bytes.
#include "FileContents.h"
#include "MeshIO.h"
#include "RowAppender.h"
#include "TextTokens.h"

#include <clothtrack/base/Error.h>

#include <charconv>
#include <cstring>
#include <string_view>
#include <vector>

namespace clothtrack
{
namespace
{
/// The words of an OFF text in order, '#' comments left out, with the line of each.
class OffWords
{
public:
  explicit OffWords(std::string_view text) : p_(text.data()), end_(p_ + text.size()) {}

  /// Moves to the start of the next word; false at the end of the text.
  bool toNextWord()
  {
    while (p_ < end_)
    {
      if (*p_ == '\n')
        ++line_;
      else if (*p_ == '#')
      {
        skipRestOfLine();
        continue;
      }
      else if (!isSpace(*p_))
        break;
      ++p_;
    }
    wordLine_ = line_;
    return p_ < end_;
  }
  /// The next word; empty at the end of the text.
  std::string_view next()
  {
    toNextWord();
    const char* start = p_;
    while (p_ < end_ && !endsWord(p_)) ++p_;
    return {start, static_cast<size_t>(p_ - start)};
  }
  /// The word at the cursor (after toNextWord) as a number: read in place when std::from_chars
  /// takes it whole, else by `parse`, the reference reading (a '+' sign, hexadecimal). False,
  /// with the word, when it is no number.
  template <class T, class Parse> bool readNumber(T& value, Parse parse, std::string_view& word)
  {
    const char* stop = inPlace(value);
    if (stop && (stop == end_ || endsWord(stop)))
    {
      p_ = stop;
      return true;
    }
    word = next();
    return parse(word, value);
  }
  /// The line of the word last returned.
  int line() const { return wordLine_; }
  /// Skips what is left of the current line (a comment, an OFF face's optional colour values).
  void skipRestOfLine()
  {
    const void* eol = std::memchr(p_, '\n', end_ - p_);
    p_ = eol ? static_cast<const char*>(eol) : end_;
  }
  size_t bytesLeft() const { return static_cast<size_t>(end_ - p_); }

private:
  const char* inPlace(double& value) const { return readNumberInPlace(p_, end_, value); }
  const char* inPlace(long& value) const
  {
    const auto [stop, error] = std::from_chars(p_, end_, value);
    return error == std::errc() && stop != p_ ? stop : nullptr;
  }
  static bool endsWord(const char* p) { return isSpace(*p) || *p == '\n' || *p == '#'; }

  const char* p_;
  const char* end_;
  int line_ = 1, wordLine_ = 1;
};

} // namespace

TriangleMesh readOFF(const std::string& path)
{
  const FileContents file(path);
  if (file.bytes().empty()) throw Error(path + ": empty file");
  OffWords words(file.bytes());
  auto truncated = [&](const char* what)
  { return Error(path + ": truncated file: missing " + std::string(what)); };
  auto next = [&](const char* what)
  {
    const std::string_view word = words.next();
    if (word.empty()) throw truncated(what);
    return word;
  };
  const std::string_view header = next("header");
  if (header != "OFF")
    throw Error(path + ": not an OFF file (first word is '" + std::string(header.substr(0, 20)) +
                "', expected 'OFF')");
  long counts[3];
  for (long& c : counts)
  {
    const std::string_view word = next("vertex/face/edge counts");
    if (!parseIndex(word, c) || c < 0)
      throw Error(lineLocation(path, words.line()) + "malformed count '" + std::string(word) + "'");
  }
  // Each value takes two bytes at least (a character and a separator), a vertex 3 values and a
  // face 4: a header that declares more than the file holds is refused before allocating.
  const unsigned long values = (words.bytesLeft() + 1) / 2;
  if (static_cast<unsigned long>(counts[0]) > values / 3 ||
      static_cast<unsigned long>(counts[1]) > (values - 3 * counts[0]) / 4)
    throw Error(path + ": the header declares " + std::to_string(counts[0]) + " vertices and " +
                std::to_string(counts[1]) + " faces, more than the file's " +
                std::to_string(words.bytesLeft()) +
                " remaining bytes hold (truncated file or wrong header)");
  TriangleMesh mesh;
  RowAppender<Points> vertices(mesh.V, counts[0]);
  for (long i = 0; i < counts[0]; ++i)
  {
    double xyz[3];
    for (double& value : xyz)
    {
      std::string_view word;
      if (!words.toNextWord()) throw truncated("vertex coordinates");
      if (!words.readNumber(value, parseDouble, word))
        throw Error(lineLocation(path, words.line()) + "malformed coordinate '" +
                    std::string(word) + "'");
    }
    vertices.add(xyz[0], xyz[1], xyz[2]);
  }
  RowAppender<Triangles> triangles(mesh.F, counts[1]);
  std::vector<int> polygon;
  for (long f = 0; f < counts[1]; ++f)
  {
    const std::string_view countWord = next("faces");
    const int line = words.line();
    long n;
    if (!parseIndex(countWord, n) || n < 3)
      throw Error(lineLocation(path, line) + "face " + std::to_string(f) +
                  " has an invalid vertex count '" + std::string(countWord) + "'");
    polygon.clear();
    for (long k = 0; k < n; ++k)
    {
      std::string_view word;
      long idx;
      if (!words.toNextWord()) throw truncated("face indices");
      if (!words.readNumber(idx, parseIndex, word))
        throw Error(lineLocation(path, words.line()) + "malformed face index '" +
                    std::string(word) + "'");
      if (idx < 0 || idx >= counts[0])
        throw Error(lineLocation(path, words.line()) + "face index " + std::to_string(idx) +
                    " out of range (file has " + std::to_string(counts[0]) + " vertices)");
      polygon.push_back(static_cast<int>(idx));
    }
    // Optional per-face colour values run to the end of the line.
    if (words.line() == line) words.skipRestOfLine();
    addFan(polygon, triangles);
  }
  vertices.finish();
  triangles.finish();
  return mesh;
}
} // namespace clothtrack

#include "TextFile.h"

#include "Commands.h"

#include <filesystem>
#include <fstream>

namespace clothtrack::app
{
void writeTextAtomically(const std::string& path, const std::string& text)
{
  const std::string part = path + ".part";
  {
    std::ofstream out(part);
    out << text;
    if (!out.flush()) throw UsageError{path + ": cannot write file"};
  }
  std::error_code error;
  std::filesystem::rename(part, path, error);
  if (error) throw UsageError{path + ": cannot write file (" + error.message() + ")"};
}
} // namespace clothtrack::app

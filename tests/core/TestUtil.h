#pragma once
// Small helpers shared by the tests: scratch folders and text files.
#include <filesystem>
#include <fstream>
#include <string>

namespace clothtrack::test
{
/// A fresh, empty folder under the build tree's test scratch area.
inline std::string scratchDir(const std::string& name)
{
  const std::filesystem::path dir = std::filesystem::path(CLOTHTRACK_TEST_TMP) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::string writeText(const std::string& path, const std::string& text)
{
  std::ofstream(path, std::ios::binary) << text;
  return path;
}
} // namespace clothtrack::test

#include "FrameList.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <glob.h>

namespace fs = std::filesystem;

namespace clothtrack
{
bool naturalLess(const std::string& a, const std::string& b)
{
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size())
  {
    if (std::isdigit(static_cast<unsigned char>(a[i])) &&
        std::isdigit(static_cast<unsigned char>(b[j])))
    {
      size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie]))) ++ie;
      while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je]))) ++je;
      // Compare by value: strip leading zeros, then by length, then lexically.
      size_t is = i, js = j;
      while (is + 1 < ie && a[is] == '0') ++is;
      while (js + 1 < je && b[js] == '0') ++js;
      if (ie - is != je - js) return ie - is < je - js;
      const int c = a.compare(is, ie - is, b, js, je - js);
      if (c != 0) return c < 0;
      i = ie;
      j = je;
      continue;
    }
    if (a[i] != b[j]) return a[i] < b[j];
    ++i;
    ++j;
  }
  return a.size() - i < b.size() - j;
}

long frameNumberFromName(const std::string& path)
{
  const std::string stem = fs::path(path).stem().string();
  long value = -1;
  for (size_t i = 0; i < stem.size();)
  {
    if (!std::isdigit(static_cast<unsigned char>(stem[i])))
    {
      ++i;
      continue;
    }
    size_t e = i;
    while (e < stem.size() && std::isdigit(static_cast<unsigned char>(stem[e]))) ++e;
    value = std::stol(stem.substr(i, std::min<size_t>(e - i, 18)));
    i = e;
  }
  return value;
}

std::string lowerCaseExtension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

const std::vector<std::string>& supportedMeshExtensions()
{
  static const std::vector<std::string> extensions = {".obj", ".ply", ".stl", ".off",
                                                      ".vtp", ".vtk", ".xyz", ".pcd"};
  return extensions;
}

bool hasSupportedMeshExtension(const std::string& path)
{
  const std::string ext = lowerCaseExtension(path);
  const auto& all = supportedMeshExtensions();
  return std::find(all.begin(), all.end(), ext) != all.end();
}

namespace
{
bool isGlob(const std::string& s)
{
  return s.find_first_of("*?[") != std::string::npos;
}

std::vector<std::string> sorted(std::vector<std::string> files)
{
  std::sort(files.begin(), files.end(),
            [](const std::string& a, const std::string& b)
            {
              return naturalLess(fs::path(a).filename().string(),
                                 fs::path(b).filename().string()) ||
                     (fs::path(a).filename() == fs::path(b).filename() && naturalLess(a, b));
            });
  return files;
}
} // namespace

std::vector<std::string> listFrames(const std::string& spec)
{
  if (spec.empty()) throw Error("no sequence given (empty path)");
  std::vector<std::string> files;
  if (isGlob(spec) && !fs::exists(spec))
  {
    glob_t result{};
    const int rc = ::glob(spec.c_str(), 0, nullptr, &result);
    if (rc == 0)
      for (size_t i = 0; i < result.gl_pathc; ++i)
        if (fs::is_regular_file(result.gl_pathv[i])) files.emplace_back(result.gl_pathv[i]);
    globfree(&result);
    if (files.empty()) throw Error(spec + ": the pattern matches no file");
    return sorted(files);
  }
  std::error_code ec;
  if (!fs::exists(spec, ec)) throw Error(spec + ": no such file or folder");
  if (fs::is_directory(spec, ec))
  {
    for (const auto& entry : fs::directory_iterator(spec, ec))
      if (entry.is_regular_file() && hasSupportedMeshExtension(entry.path().string()))
        files.push_back(entry.path().string());
    if (ec) throw Error(spec + ": cannot list folder (" + ec.message() + ")");
    if (files.empty())
      throw Error(spec + ": folder holds no mesh file (.obj .ply .stl .off .vtp .vtk)");
    return sorted(files);
  }
  if (hasSupportedMeshExtension(spec)) return {spec};
  // A list file: keep its order, as the user wrote it.
  std::ifstream in(spec);
  if (!in) throw Error(spec + ": cannot open frame list");
  const fs::path base = fs::path(spec).parent_path();
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line))
  {
    ++lineNo;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    line = line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
    const fs::path p = fs::path(line).is_absolute() ? fs::path(line) : base / line;
    if (!hasSupportedMeshExtension(p.string()))
      throw Error(spec + ":" + std::to_string(lineNo) + ": '" + line +
                  "' is not a supported mesh file");
    files.push_back(p.string());
  }
  if (files.empty()) throw Error(spec + ": frame list names no frame");
  return files;
}
} // namespace clothtrack

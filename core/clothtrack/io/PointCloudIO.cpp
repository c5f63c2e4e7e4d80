#include "PointCloudIO.h"
#include "FileContents.h"
#include "FrameList.h"
#include "TextTokens.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace clothtrack
{

PointCloud cloudFromArrays(Points positions, const std::vector<double>& normals,
                           const std::vector<double>& colours)
{
  const long n = static_cast<long>(positions.rows());
  PointCloud cloud;
  cloud.P = std::move(positions);
  if (static_cast<long>(normals.size()) == 3 * n && n > 0)
  {
    cloud.N = Eigen::Map<const Points>(normals.data(), n, 3);
    for (long i = 0; i < n; ++i)
    {
      const double length = cloud.N.row(i).norm();
      if (length > 0) cloud.N.row(i) /= length;
    }
  }
  if (static_cast<long>(colours.size()) == 3 * n && n > 0)
  {
    cloud.C.resize(n, 3);
    for (long i = 0; i < 3 * n; ++i)
      cloud.C.data()[i] = static_cast<std::uint8_t>(std::clamp(colours[i], 0.0, 255.0) + 0.5);
  }
  return cloud;
}

PointCloud readXYZ(const std::string& path)
{
  const FileContents file(path);
  const std::string_view data = file.bytes();
  std::vector<double> coords, normals;
  std::vector<std::string_view> tokens;
  size_t columns = 0;
  int lineNo = 0;
  const char* p = data.data();
  const char* end = p + data.size();
  while (p < end)
  {
    const char* lineEnd = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!lineEnd) lineEnd = end;
    ++lineNo;
    const char* hash = static_cast<const char*>(std::memchr(p, '#', lineEnd - p));
    tokenize(p, hash ? hash : lineEnd, tokens);
    p = lineEnd + 1;
    if (tokens.empty()) continue;
    auto at = [&] { return lineLocation(path, lineNo); };
    if (tokens.size() != 3 && tokens.size() != 6)
      throw Error(at() + "an XYZ line holds 3 (x y z) or 6 (x y z nx ny nz) numbers, not " +
                  std::to_string(tokens.size()));
    if (columns == 0) columns = tokens.size();
    if (tokens.size() != columns)
      throw Error(at() + std::to_string(tokens.size()) + " numbers where the first line had " +
                  std::to_string(columns));
    double values[6];
    for (size_t k = 0; k < tokens.size(); ++k)
      if (!parseDouble(tokens[k], values[k]))
        throw Error(at() + "'" + std::string(tokens[k]) + "' is not a number");
    coords.insert(coords.end(), values, values + 3);
    if (columns == 6) normals.insert(normals.end(), values + 3, values + 6);
  }
  const auto n = static_cast<Eigen::Index>(coords.size() / 3);
  return cloudFromArrays(Eigen::Map<const Points>(coords.data(), n, 3), normals, {});
}

void writePLYPoints(const std::string& path, const PointCloud& cloud)
{
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path + ": cannot write file");
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << cloud.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n";
  if (cloud.hasNormals()) out << "property float nx\nproperty float ny\nproperty float nz\n";
  if (cloud.hasColours()) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out << "end_header\n";
  std::vector<char> record;
  for (int i = 0; i < cloud.size(); ++i)
  {
    record.clear();
    auto put = [&](float v)
    {
      char bytes[4];
      std::memcpy(bytes, &v, 4);
      record.insert(record.end(), bytes, bytes + 4);
    };
    for (int k = 0; k < 3; ++k) put(static_cast<float>(cloud.P(i, k)));
    if (cloud.hasNormals())
      for (int k = 0; k < 3; ++k) put(static_cast<float>(cloud.N(i, k)));
    if (cloud.hasColours())
      for (int k = 0; k < 3; ++k) record.push_back(static_cast<char>(cloud.C(i, k)));
    out.write(record.data(), static_cast<std::streamsize>(record.size()));
  }
  if (!out) throw Error(path + ": write failed");
}

void writeXYZ(const std::string& path, const PointCloud& cloud)
{
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) throw Error(path + ": cannot write file");
  for (int i = 0; i < cloud.size(); ++i)
  {
    std::fprintf(file, "%.9g %.9g %.9g", cloud.P(i, 0), cloud.P(i, 1), cloud.P(i, 2));
    if (cloud.hasNormals())
      std::fprintf(file, " %.6g %.6g %.6g", cloud.N(i, 0), cloud.N(i, 1), cloud.N(i, 2));
    std::fputc('\n', file);
  }
  const bool failed = std::ferror(file);
  if (std::fclose(file) != 0 || failed) throw Error(path + ": write failed");
}

bool isPointCloudFile(const std::string& path)
{
  const std::string ext = lowerCaseExtension(path);
  if (ext == ".xyz" || ext == ".pcd") return true;
  return ext == ".ply" && !plyDeclaresFaces(path);
}

int dropInvalidPoints(PointCloud& cloud, const std::string& name, int minimumPoints)
{
  if (cloud.size() == 0) throw Error(name + ": the point cloud is empty");
  std::vector<bool> keep(cloud.size());
  int kept = 0;
  for (int i = 0; i < cloud.size(); ++i)
  {
    keep[i] = cloud.P.row(i).allFinite() && cloud.P.row(i).cwiseAbs().maxCoeff() < 1e6;
    kept += keep[i];
  }
  if (kept == 0)
    throw Error(name + ": no point of the cloud has finite coordinates (all " +
                std::to_string(cloud.size()) + " are NaN or infinite)");
  const int dropped = cloud.size() - kept;
  if (dropped > 0) cloud = selectPoints(cloud, keep);
  if (cloud.hasNormals())
    for (int i = 0; i < cloud.size(); ++i)
      if (!cloud.N.row(i).allFinite()) cloud.N.row(i).setZero();
  if (kept < minimumPoints)
    throw Error(name + ": the point cloud has " + std::to_string(kept) +
                " valid points, too few to reconstruct a surface from (at least " +
                std::to_string(minimumPoints) + ")");
  return dropped;
}
} // namespace clothtrack

#include "PcdIO.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FileBytes.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>

namespace clothtrack
{
namespace
{
bool hasField(const pcl::PCLPointCloud2& blob, const std::string& name)
{
  return std::any_of(blob.fields.begin(), blob.fields.end(),
                     [&](const pcl::PCLPointField& f) { return f.name == name; });
}

/// PCL prints its own errors; the message the user sees is ours, naming the file.
struct QuietPcl
{
  pcl::console::VERBOSITY_LEVEL previous = pcl::console::getVerbosityLevel();
  QuietPcl() { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }
  ~QuietPcl() { pcl::console::setVerbosityLevel(previous); }
};
} // namespace

PointCloud readPCD(const std::string& path)
{
  requireNonEmptyFile(path);
  pcl::PCLPointCloud2 blob;
  {
    QuietPcl quiet;
    pcl::PCDReader reader;
    int result = -1;
    try
    {
      result = reader.read(path, blob);
    }
    catch (const std::exception& e)
    {
      throw Error(path + ": not a readable PCD file (" + e.what() + ")");
    }
    if (result < 0) throw Error(path + ": not a readable PCD file (malformed header or data)");
  }
  if (!hasField(blob, "x") || !hasField(blob, "y") || !hasField(blob, "z"))
    throw Error(path + ": the PCD file has no x, y and z fields");
  const long n = static_cast<long>(blob.width) * blob.height;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::fromPCLPointCloud2(blob, xyz);
  PointCloud cloud;
  cloud.P.resize(n, 3);
  for (long i = 0; i < n; ++i) cloud.P.row(i) << xyz[i].x, xyz[i].y, xyz[i].z;
  if (hasField(blob, "normal_x") && hasField(blob, "normal_y") && hasField(blob, "normal_z"))
  {
    pcl::PointCloud<pcl::Normal> normals;
    pcl::fromPCLPointCloud2(blob, normals);
    cloud.N.resize(n, 3);
    for (long i = 0; i < n; ++i)
      cloud.N.row(i) << normals[i].normal_x, normals[i].normal_y, normals[i].normal_z;
  }
  if (hasField(blob, "rgb") || hasField(blob, "rgba"))
  {
    pcl::PointCloud<pcl::PointXYZRGB> colours;
    pcl::fromPCLPointCloud2(blob, colours);
    cloud.C.resize(n, 3);
    for (long i = 0; i < n; ++i) cloud.C.row(i) << colours[i].r, colours[i].g, colours[i].b;
  }
  return cloud;
}

namespace
{
template <class PointT>
void write(const std::string& path, const pcl::PointCloud<PointT>& points, PcdEncoding encoding)
{
  QuietPcl quiet;
  pcl::PCDWriter writer;
  int result = -1;
  if (encoding == PcdEncoding::Ascii)
    result = writer.writeASCII(path, points, 9);
  else if (encoding == PcdEncoding::Binary)
    result = writer.writeBinary(path, points);
  else
    result = writer.writeBinaryCompressed(path, points);
  if (result < 0) throw Error(path + ": cannot write the PCD file");
}

template <class PointT> pcl::PointCloud<PointT> pclPoints(const PointCloud& cloud)
{
  pcl::PointCloud<PointT> points;
  points.resize(cloud.size());
  for (int i = 0; i < cloud.size(); ++i)
  {
    PointT& p = points[i];
    p.x = static_cast<float>(cloud.P(i, 0));
    p.y = static_cast<float>(cloud.P(i, 1));
    p.z = static_cast<float>(cloud.P(i, 2));
    if constexpr (pcl::traits::has_normal_v<PointT>)
    {
      p.normal_x = static_cast<float>(cloud.N(i, 0));
      p.normal_y = static_cast<float>(cloud.N(i, 1));
      p.normal_z = static_cast<float>(cloud.N(i, 2));
    }
    if constexpr (pcl::traits::has_color_v<PointT>)
    {
      p.r = cloud.C(i, 0);
      p.g = cloud.C(i, 1);
      p.b = cloud.C(i, 2);
    }
  }
  return points;
}
} // namespace

void writePCD(const std::string& path, const PointCloud& cloud, PcdEncoding encoding)
{
  if (cloud.hasNormals() && cloud.hasColours())
    write(path, pclPoints<pcl::PointXYZRGBNormal>(cloud), encoding);
  else if (cloud.hasNormals())
    write(path, pclPoints<pcl::PointNormal>(cloud), encoding);
  else if (cloud.hasColours())
    write(path, pclPoints<pcl::PointXYZRGB>(cloud), encoding);
  else
    write(path, pclPoints<pcl::PointXYZ>(cloud), encoding);
}
} // namespace clothtrack

#include "ctPointCloudFile.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/io/PointCloudIO.h>
#ifdef CLOTHTRACK_HAVE_PCD
#include <clothtrack/pcd/PcdIO.h>
#endif

#include <filesystem>

namespace fs = std::filesystem;

namespace clothtrack
{
#ifndef CLOTHTRACK_HAVE_PCD
namespace
{
[[noreturn]] void noPcdHere(const std::string& path)
{
  throw Error(path + ": PCD files are read through PCL's io library, which links another VTK "
                     "and is not loaded inside ParaView; convert the cloud to .ply with "
                     "'clothtrack reconstruct' or PCL's pcl_pcd2ply");
}
} // namespace
#endif

bool isPointCloudPath(const std::string& path)
{
  return isPointCloudFile(path);
}

PointCloud readPointCloudFile(const std::string& path)
{
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Error(path + ": no such file");
  if (fs::file_size(path, ec) == 0) throw Error(path + ": empty file");
  const std::string ext = lowerCaseExtension(path);
  try
  {
    if (ext == ".xyz") return readXYZ(path);
    if (ext == ".ply") return readPLYPoints(path);
    if (ext == ".pcd")
    {
#ifdef CLOTHTRACK_HAVE_PCD
      return readPCD(path);
#else
      noPcdHere(path);
#endif
    }
  }
  catch (const std::bad_alloc&)
  {
    throw Error(path + ": the file declares more points than memory holds (corrupt header?)");
  }
  throw Error(path + ": unsupported point-cloud type '" + ext + "' (use .pcd .ply .xyz)");
}

PointCloud loadPointCloud(const std::string& path, const FrameConventions& conventions)
{
  PointCloud cloud = readPointCloudFile(path);
  toMetresYUp(cloud.P, conventions);
  if (cloud.hasNormals()) toMetresYUp(cloud.N, FrameConventions{1.0, conventions.upAxis});
  return cloud;
}

void writePointCloudFile(const std::string& path, const PointCloud& cloud)
{
  const std::string ext = lowerCaseExtension(path);
  const std::string tmp = path + ".part";
  if (ext == ".xyz")
    writeXYZ(tmp, cloud);
  else if (ext == ".ply")
    writePLYPoints(tmp, cloud);
  else if (ext == ".pcd")
  {
#ifdef CLOTHTRACK_HAVE_PCD
    writePCD(tmp, cloud);
#else
    noPcdHere(path);
#endif
  }
  else
    throw Error(path + ": unsupported point-cloud type '" + ext + "' (use .pcd .ply .xyz)");
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw Error(path + ": cannot rename temporary file (" + ec.message() + ")");
}
} // namespace clothtrack

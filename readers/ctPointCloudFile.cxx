#include "ctPointCloudFile.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FileBytes.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/io/PointCloudIO.h>
#ifdef CLOTHTRACK_HAVE_PCD
#include <clothtrack/pcd/PcdIO.h>
#endif

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

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

PointCloud readPointCloudFile(const std::string& path)
{
  requireNonEmptyFile(path);
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

vtkSmartPointer<vtkPolyData> toPolyData(const PointCloud& cloud)
{
  const vtkIdType n = cloud.size();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
    points->SetPoint(i, cloud.P(i, 0), cloud.P(i, 1), cloud.P(i, 2));
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(n + 1);
  connectivity->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i <= n; ++i) offsets->SetValue(i, i);
  for (vtkIdType i = 0; i < n; ++i) connectivity->SetValue(i, i);
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetVerts(verts);
  if (cloud.hasNormals())
  {
    vtkNew<vtkDoubleArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) normals->SetTuple(i, cloud.N.row(i).data());
    out->GetPointData()->SetNormals(normals);
  }
  if (cloud.hasColours())
  {
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("Colors");
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(n);
    std::copy(cloud.C.data(), cloud.C.data() + 3 * n, colours->GetPointer(0));
    out->GetPointData()->SetScalars(colours);
  }
  return out;
}

PointCloud toPointCloud(vtkPolyData* polyData, const std::string& name)
{
  if (!polyData || !polyData->GetPoints()) throw Error(name + ": no points");
  const vtkIdType n = polyData->GetNumberOfPoints();
  PointCloud cloud;
  cloud.P.resize(n, 3);
  for (vtkIdType i = 0; i < n; ++i) polyData->GetPoint(i, cloud.P.row(i).data());
  vtkDataArray* normals = polyData->GetPointData()->GetNormals();
  if (!normals) normals = polyData->GetPointData()->GetArray("Normals");
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == n)
  {
    cloud.N.resize(n, 3);
    for (vtkIdType i = 0; i < n; ++i) normals->GetTuple(i, cloud.N.row(i).data());
  }
  for (const char* colourName : {"Colors", "RGB"})
  {
    auto* colours =
        vtkUnsignedCharArray::SafeDownCast(polyData->GetPointData()->GetArray(colourName));
    if (colours && colours->GetNumberOfComponents() == 3 && colours->GetNumberOfTuples() == n)
    {
      cloud.C.resize(n, 3);
      std::copy(colours->GetPointer(0), colours->GetPointer(0) + 3 * n, cloud.C.data());
      break;
    }
  }
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

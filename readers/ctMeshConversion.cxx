#include "ctMeshConversion.h"

#include "ctGuardedPolyDataReader.h"
#include "ctVtkMessageCapture.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FileBytes.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/io/MeshIO.h>
#include <clothtrack/io/ReaderPrechecks.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <vector>

namespace fs = std::filesystem;

namespace clothtrack
{
namespace
{
// Collects the error messages a VTK reader or writer emits instead of letting them go to the
// console, so that they can be reported once with the file name.
struct ErrorCollector
{
  std::string message;
  vtkNew<vtkCallbackCommand> command;

  ErrorCollector()
  {
    command->SetClientData(this);
    command->SetCallback(
        [](vtkObject*, unsigned long, void* client, void* callData)
        {
          auto* self = static_cast<ErrorCollector*>(client);
          if (self->message.empty() && callData)
            self->message = plainVtkMessage(static_cast<const char*>(callData));
        });
  }
  void watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, command);
    object->AddObserver(vtkCommand::WarningEvent, command);
  }
};

template <class Reader> vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path)
{
  vtkNew<Reader> reader;
  ErrorCollector errors;
  errors.watch(reader);
  reader->SetFileName(path.c_str());
  VtkMessageCapture others; // the reader's executive, arrays and parser
  reader->Update();
  // The first message came from where the reading went wrong; the reader's own follows it.
  const std::string message =
      others.firstMessage().empty() ? errors.message : others.firstMessage();
  if (!message.empty()) throw Error(path + ": " + message);
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  if (!out) throw Error(path + ": the file could not be read");
  return out;
}
} // namespace

TriangleMesh toTriangleMesh(vtkPolyData* polyData, const std::string& name)
{
  if (!polyData || !polyData->GetPoints() || polyData->GetNumberOfPoints() == 0)
    throw Error(name + ": empty mesh (no vertex)");
  const vtkIdType np = polyData->GetNumberOfPoints();
  TriangleMesh mesh;
  mesh.V.resize(np, 3);
  for (vtkIdType i = 0; i < np; ++i) polyData->GetPoints()->GetPoint(i, mesh.V.row(i).data());

  std::vector<int> faces;
  auto checked = [&](vtkIdType id)
  {
    if (id < 0 || id >= np)
      throw Error(name + ": a cell uses point index " + std::to_string(id) + ", out of range [0, " +
                  std::to_string(np) + ")");
    return static_cast<int>(id);
  };
  if (vtkCellArray* polys = polyData->GetPolys())
  {
    auto it = vtk::TakeSmartPointer(polys->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 1; k + 1 < n; ++k)
        faces.insert(faces.end(), {checked(ids[0]), checked(ids[k]), checked(ids[k + 1])});
    }
  }
  if (vtkCellArray* strips = polyData->GetStrips())
  {
    auto it = vtk::TakeSmartPointer(strips->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 2 < n; ++k)
      {
        // Alternate the winding so that every triangle of the strip faces the same way.
        if (k % 2 == 0)
          faces.insert(faces.end(), {checked(ids[k]), checked(ids[k + 1]), checked(ids[k + 2])});
        else
          faces.insert(faces.end(), {checked(ids[k + 1]), checked(ids[k]), checked(ids[k + 2])});
      }
    }
  }
  mesh.F =
      Eigen::Map<const Triangles>(faces.data(), static_cast<Eigen::Index>(faces.size() / 3), 3);
  return mesh;
}

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh)
{
  vtkNew<vtkDoubleArray> coords;
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(mesh.numVertices());
  std::copy(mesh.V.data(), mesh.V.data() + mesh.V.size(), coords->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coords);

  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(3 * static_cast<vtkIdType>(mesh.numFaces()));
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(mesh.numFaces() + 1);
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    offsets->SetValue(f, 3 * static_cast<vtkIdType>(f));
    for (int k = 0; k < 3; ++k)
      connectivity->SetValue(3 * static_cast<vtkIdType>(f) + k, mesh.F(f, k));
  }
  offsets->SetValue(mesh.numFaces(), 3 * static_cast<vtkIdType>(mesh.numFaces()));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

namespace
{
TriangleMesh readMeshFileUnguarded(const std::string& path)
{
  requireNonEmptyFile(path);
  const std::string ext = lowerCaseExtension(path);
  if (ext == ".obj") return readOBJ(path);
  if (ext == ".off") return readOFF(path);
  vtkSmartPointer<vtkPolyData> data;
  if (ext == ".ply") // VTK's PLY reader crashes on truncated headers: use the strict one
    return readPLY(path);
  if (ext == ".stl")
  {
    checkSTLFile(path);
    data = readWithVtk<vtkSTLReader>(path);
  }
  else if (ext == ".vtp")
  {
    checkVTKXMLFile(path);
    data = readWithVtk<ctGuardedPolyDataReader>(path);
  }
  else if (ext == ".vtk") // VTK's legacy reader trusts the declared counts and the version line
    return readLegacyVTK(path);
  else if (ext == ".xyz" || ext == ".pcd")
    throw Error(path +
                ": a point cloud, not a mesh: reconstruct it first ('clothtrack reconstruct'; "
                "'clothtrack align' does it by itself)");
  else
    throw Error(path + ": unsupported file type '" + ext + "' (use .obj .ply .stl .off .vtp .vtk)");
  return toTriangleMesh(data, path);
}
} // namespace

vtkSmartPointer<vtkPolyData> readVTPFile(const std::string& path)
{
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Error(path + ": no such file");
  checkVTKXMLFile(path);
  return readWithVtk<ctGuardedPolyDataReader>(path);
}

TriangleMesh readMeshFile(const std::string& path)
{
  try
  {
    return readMeshFileUnguarded(path);
  }
  catch (const std::bad_alloc&)
  {
    throw Error(path + ": the file declares more data than memory holds (corrupt header?)");
  }
}

void writeMeshFile(const std::string& path, vtkPolyData* polyData)
{
  const std::string ext = lowerCaseExtension(path);
  // The extension stays last: VTK's PLY writer appends ".ply" to a name that does not end so.
  const std::string tmp = path.substr(0, path.size() - ext.size()) + ".part" + ext;
  ErrorCollector errors;
  auto run = [&](auto writer)
  {
    errors.watch(writer);
    writer->SetInputData(polyData);
    writer->SetFileName(tmp.c_str());
    if (!writer->Write() && errors.message.empty()) errors.message = "write failed";
  };
  if (ext == ".obj" || ext == ".off")
  {
    const TriangleMesh mesh = toTriangleMesh(polyData, path);
    ext == ".obj" ? writeOBJ(tmp, mesh) : writeOFF(tmp, mesh);
  }
  else if (ext == ".vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetDataModeToAppended();
    // LZ4: a quarter of zlib's time for a quarter more bytes (a 10k-vertex aligned frame: 8
    // against 34 ms, 1.2 against 1.0 MB); writing is on the fit's path, once per frame.
    writer->SetCompressorTypeToLZ4();
    run(writer.Get());
  }
  else if (ext == ".vtk")
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetFileTypeToBinary();
    run(writer.Get());
  }
  else if (ext == ".ply")
  {
    vtkNew<vtkPLYWriter> writer;
    writer->SetFileTypeToBinary();
    run(writer.Get());
  }
  else if (ext == ".stl")
  {
    vtkNew<vtkSTLWriter> writer;
    writer->SetFileTypeToBinary();
    run(writer.Get());
  }
  else
    throw Error(path + ": unsupported output type '" + ext + "'");
  if (!errors.message.empty())
  {
    std::remove(tmp.c_str());
    throw Error(path + ": " + errors.message);
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw Error(path + ": cannot rename temporary file (" + ec.message() + ")");
}

void toMetresYUp(Points& points, const FrameConventions& conventions)
{
  if (conventions.unitScale != 1.0) points *= conventions.unitScale;
  if (conventions.upAxis == 2) // (x, y, z) -> (x, z, -y)
  {
    const Eigen::VectorXd y = points.col(1);
    points.col(1) = points.col(2);
    points.col(2) = -y;
  }
  else if (conventions.upAxis == 0) // (x, y, z) -> (-y, x, z)
  {
    const Eigen::VectorXd x = points.col(0);
    points.col(0) = -points.col(1);
    points.col(1) = x;
  }
}

TriangleMesh loadFrame(const std::string& path, const FrameConventions& conventions,
                       std::vector<std::string>* warnings)
{
  TriangleMesh mesh = readMeshFile(path);
  toMetresYUp(mesh.V, conventions);
  const CleaningReport report = validateAndClean(mesh, path);
  if (warnings)
    for (const auto& w : report.warnings) warnings->push_back(path + ": " + w);
  return mesh;
}

std::string writeCollectionFrame(const std::string& pvdPath, int index, vtkPolyData* frame,
                                 bool alsoOBJ)
{
  const fs::path pvd(pvdPath);
  const std::string stem = pvd.stem().string();
  const fs::path folder = pvd.parent_path() / stem;
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw Error(folder.string() + ": cannot create folder (" + ec.message() + ")");
  char suffix[32];
  std::snprintf(suffix, sizeof(suffix), "_%04d", index);
  const std::string name = stem + suffix;
  writeMeshFile((folder / (name + ".vtp")).string(), frame);
  if (alsoOBJ) writeMeshFile((folder / (name + ".obj")).string(), frame);
  return stem + "/" + name + ".vtp";
}

void writeCollection(const std::string& pvdPath,
                     const std::vector<std::pair<double, std::string>>& entries)
{
  const std::string tmp = pvdPath + ".part";
  {
    std::ofstream out(tmp);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  "
           "<Collection>\n";
    out.precision(17);
    for (const auto& [time, file] : entries)
      out << "    <DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << file << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    if (!out) throw Error(pvdPath + ": cannot write collection file");
  }
  std::error_code ec;
  fs::rename(tmp, pvdPath, ec);
  if (ec) throw Error(pvdPath + ": cannot rename temporary file (" + ec.message() + ")");
}
} // namespace clothtrack

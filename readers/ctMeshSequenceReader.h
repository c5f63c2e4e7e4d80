/**
 * @class ctMeshSequenceReader
 * @brief Reads a captured mesh sequence: one independent mesh file per frame.
 *
 * FileName is a folder (every .obj .ply .stl .off .vtp .vtk .pcd .xyz file in it), a glob
 * pattern (`frames/mesh_*.obj`), a text file listing one frame per line, or a single mesh file.
 * Point clouds (.pcd, .xyz, and .ply without faces) are read as points with one vertex cell
 * each, their "Normals" and "Colors" kept (.pcd through PCL, not inside ParaView). Frames
 * from a folder or pattern are sorted by the numbers in their names (natural order).
 *
 * Output port 0 is the current frame as vtkPolyData. It is temporal: frame k has time
 * k / FrameRate, so a ParaView user opens a sequence and presses Play, and a script calls
 * UpdateTimeStep(t). Output port 1 is the whole sequence as a vtkMultiBlockDataSet with one
 * block per frame, for filters that need every frame; it is read only when requested.
 *
 * Each frame is converted to metres (LengthUnit) and to the Y-up convention (UpAxis), then
 * validated: a missing, empty, truncated or corrupt file, indices out of range, NaN/Inf
 * coordinates or a mesh without faces are errors naming the file; duplicated vertices are
 * merged and zero-area faces removed, with a warning. Field data of each frame: SourceFile,
 * FrameIndex (position in the sequence), FrameNumber (number in the file name), TimeValue.
 */
#ifndef ctMeshSequenceReader_h
#define ctMeshSequenceReader_h

#include "ctReadersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <memory>
#include <string>

class vtkMultiBlockDataSet;

class CTREADERS_EXPORT ctMeshSequenceReader : public vtkPolyDataAlgorithm
{
public:
  static ctMeshSequenceReader* New();
  vtkTypeMacro(ctMeshSequenceReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum LengthUnits
  {
    METRES = 0,
    CENTIMETRES = 1,
    MILLIMETRES = 2
  };
  enum UpAxes
  {
    X_UP = 0,
    Y_UP = 1,
    Z_UP = 2
  };

  /// Folder, glob pattern, list file or single mesh file.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /// Frames per second: frame k is at time k / FrameRate.
  vtkSetClampMacro(FrameRate, double, 1e-6, 1e6);
  vtkGetMacro(FrameRate, double);

  /// Unit of the coordinates in the files; output is always in metres.
  vtkSetClampMacro(LengthUnit, int, METRES, MILLIMETRES);
  vtkGetMacro(LengthUnit, int);
  void SetLengthUnitToMetres() { this->SetLengthUnit(METRES); }
  void SetLengthUnitToCentimetres() { this->SetLengthUnit(CENTIMETRES); }
  void SetLengthUnitToMillimetres() { this->SetLengthUnit(MILLIMETRES); }

  /// Axis pointing up in the files; output is always Y-up.
  vtkSetClampMacro(UpAxis, int, X_UP, Z_UP);
  vtkGetMacro(UpAxis, int);

  /// Number of frames found (valid after UpdateInformation()).
  int GetNumberOfFrames();
  /// Path of frame `index` (valid after UpdateInformation()); empty when out of range.
  std::string GetFrameFileName(int index);

  /// The whole sequence (output port 1).
  vtkMultiBlockDataSet* GetSequenceOutput();

  /// Reads and returns frame `index` directly (no pipeline); nullptr and an error when it
  /// cannot be read. The caller owns the returned reference.
  vtkPolyData* ReadFrame(int index);

  /// Can this reader open `name` (a mesh file, folder of meshes, pattern or list)? For
  /// ParaView's file dialog.
  int CanReadFile(const char* name);

protected:
  ctMeshSequenceReader();
  ~ctMeshSequenceReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                             vtkInformationVector* outputVector) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
                         vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  std::string FileName;
  double FrameRate = 25.0;
  int LengthUnit = METRES;
  int UpAxis = Y_UP;

private:
  ctMeshSequenceReader(const ctMeshSequenceReader&) = delete;
  void operator=(const ctMeshSequenceReader&) = delete;

  bool ReadFrameInto(int index, vtkPolyData* output);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

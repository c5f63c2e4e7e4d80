#ifndef ctGuardedPolyDataReader_h
#define ctGuardedPolyDataReader_h
// VTK's XML PolyData reader, less one way a small file exhausts memory: VTK sizes each cell
// array's connectivity by the last value of its offsets array before it reads a value of it, so
// a few corrupt bytes ask for gigabytes. This reader first reads that last offset, and the
// connectivity value it points past, through VTK's own decoding (inline or appended, ASCII,
// base64 or raw, compressed or not) and refuses the piece when the connectivity is shorter.
// Internal to the readers module (not wrapped).
#include <vtkXMLPolyDataReader.h>

class ctGuardedPolyDataReader : public vtkXMLPolyDataReader
{
public:
  static ctGuardedPolyDataReader* New();
  vtkTypeMacro(ctGuardedPolyDataReader, vtkXMLPolyDataReader);

protected:
  ctGuardedPolyDataReader() = default;
  ~ctGuardedPolyDataReader() override = default;

  int ReadPieceData() override;

private:
  /// False (with an error) when the offsets of `cells` ask for more connectivity values than
  /// its connectivity array holds. Other faults are left to the reader, which reports them.
  bool connectivityHoldsOffsets(vtkXMLDataElement* cells, vtkIdType count, const char* kind);

  ctGuardedPolyDataReader(const ctGuardedPolyDataReader&) = delete;
  void operator=(const ctGuardedPolyDataReader&) = delete;
};

#endif

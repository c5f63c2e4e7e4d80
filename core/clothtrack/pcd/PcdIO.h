#pragma once
// PCD, the Point Cloud Library's format, read and written through PCL's io library: ascii,
// binary and binary_compressed. PCL's io links Debian's VTK 9.1, so this stage is left out of
// the ParaView plugin, whose process carries ParaView's own VTK.
#include <clothtrack/mesh/PointCloud.h>

#include <string>

namespace clothtrack
{
enum class PcdEncoding
{
  Ascii,
  Binary,
  BinaryCompressed
};

/// The points of a PCD file (fields x y z, with normal_x normal_y normal_z and rgb or rgba when
/// present). Organised clouds keep their NaN pixels (see dropInvalidPoints). Throws Error naming
/// the file.
PointCloud readPCD(const std::string& path);
void writePCD(const std::string& path, const PointCloud& cloud,
              PcdEncoding encoding = PcdEncoding::BinaryCompressed);
} // namespace clothtrack

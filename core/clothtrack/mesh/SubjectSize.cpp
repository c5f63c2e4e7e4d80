#include "SubjectSize.h"

#include <algorithm>
#include <cstdio>

namespace clothtrack
{
namespace
{
Eigen::Vector3d extents(const TriangleMesh& mesh)
{
  if (mesh.numVertices() == 0) return Eigen::Vector3d::Zero();
  return (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).transpose();
}

constexpr double kScales[] = {1.0, 0.1, 0.01, 0.001};
} // namespace

int inferUpAxis(const TriangleMesh& mesh)
{
  const Eigen::Vector3d e = extents(mesh);
  int longest;
  e.maxCoeff(&longest);
  return e.y() >= 0.9 * e[longest] ? 1 : longest;
}

double inferUnitScale(const TriangleMesh& mesh, int upAxis)
{
  const double height = extents(mesh)[upAxis];
  for (double scale : kScales)
    if (height * scale >= kSmallestPerson && height * scale <= kTallestPerson) return scale;
  return 0.0;
}

const char* unitName(double unitScale)
{
  if (unitScale == 1.0) return "m";
  if (unitScale == 0.1) return "dm";
  if (unitScale == 0.01) return "cm";
  if (unitScale == 0.001) return "mm";
  return "?";
}

std::vector<std::string> subjectWarnings(const TriangleMesh& metresYUp)
{
  std::vector<std::string> out;
  const Eigen::Vector3d e = extents(metresYUp);
  const double across = std::max(e.x(), e.z());
  // Longer across than tall: lying down, or read with the wrong up axis; its height is then
  // more likely the longest side.
  const bool sideways = e.y() < 0.8 * across;
  const double height = sideways ? across : e.y();
  char text[512];
  if (height < kSmallestPerson || height > kTallestPerson)
  {
    std::string hint = "check the file, or give --scale (metres per file unit)";
    for (double factor : {0.1, 0.01, 0.001, 10.0, 100.0, 1000.0})
      if (height * factor >= kSmallestPerson && height * factor <= kTallestPerson)
      {
        std::snprintf(text, sizeof(text), "%s %.3g m in a unit %g times %s",
                      sideways ? "its longest side would be" : "it would be", height * factor,
                      factor < 1 ? 1 / factor : factor,
                      factor < 1 ? "smaller: try --unit auto" : "larger: give --scale");
        hint = text;
        break;
      }
    char warning[768];
    std::snprintf(warning, sizeof(warning),
                  "the subject is %.3g m tall along the up axis; a person is %.1f to %.1f m (%s)",
                  e.y(), kSmallestPerson, kTallestPerson, hint.c_str());
    out.push_back(warning);
  }
  if (sideways)
  {
    std::snprintf(text, sizeof(text),
                  "the subject is %.3g m across but %.3g m tall: lying down, or is another axis "
                  "up? (--up x, z or auto)",
                  across, e.y());
    out.push_back(text);
  }
  return out;
}
} // namespace clothtrack

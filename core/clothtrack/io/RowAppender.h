#pragma once
// Filling a mesh's arrays row by row as a reader meets vertices and faces.
#include <clothtrack/mesh/TriangleMesh.h>

#include <algorithm>
#include <vector>

namespace clothtrack
{
/// Rows appended to an Eigen matrix sized from a first count: the readers fill the mesh's own
/// arrays instead of flat vectors copied after.
template <class Matrix> class RowAppender
{
public:
  RowAppender(Matrix& matrix, Eigen::Index expected) : matrix_(matrix)
  {
    matrix_.resize(std::max<Eigen::Index>(expected, 0), 3);
  }
  template <class Scalar> void add(Scalar a, Scalar b, Scalar c)
  {
    if (used_ == matrix_.rows())
      matrix_.conservativeResize(std::max<Eigen::Index>(16, 2 * used_), 3);
    auto* row = matrix_.data() + 3 * used_++;
    row[0] = a;
    row[1] = b;
    row[2] = c;
  }
  Eigen::Index size() const { return used_; }
  /// Room for `rows` rows in all, kept and filled first.
  void reserve(Eigen::Index rows)
  {
    if (rows > matrix_.rows()) matrix_.conservativeResize(rows, 3);
  }
  /// Trims the rows not used.
  void finish()
  {
    if (used_ != matrix_.rows()) matrix_.conservativeResize(used_, 3);
  }

private:
  Matrix& matrix_;
  Eigen::Index used_ = 0;
};

/// A polygon's triangles as a fan from its first vertex.
inline void addFan(const std::vector<int>& polygon, RowAppender<Triangles>& triangles)
{
  for (size_t k = 1; k + 1 < polygon.size(); ++k)
    triangles.add(polygon[0], polygon[k], polygon[k + 1]);
}
} // namespace clothtrack

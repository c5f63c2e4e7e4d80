#pragma once
// The template fit's unknowns and one round's quadratic energy, shared by the fitting loop
// (TemplateFit.cpp) and the solvers (FitSolvers.h). Internal to the fit library.
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/MeshTopology.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace clothtrack
{
// Unknowns: X, 4N x 3, rows 4i..4i+3 hold the transposed affine map of vertex i, so that the
// deformed vertex is X_i^T [t_i; 1]. Its first three rows are the linear part, the fourth the
// translation; the identity map is [I3; 0].
using Unknowns = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using SparseMatrix = Eigen::SparseMatrix<double>;

inline Unknowns identityMaps(int n)
{
  Unknowns X = Unknowns::Zero(4 * static_cast<Eigen::Index>(n), 3);
  for (int i = 0; i < n; ++i) X.block<3, 3>(4 * i, 0).setIdentity();
  return X;
}

inline double dot(const Unknowns& a, const Unknowns& b)
{
  return (a.array() * b.array()).sum();
}

/// a . b, in parallel (the same sum for any thread count).
inline double parallelDot(const Unknowns& a, const Unknowns& b)
{
  return parallelDot(a.data(), b.data(), a.size());
}

/// One round's quadratic: E(X) = tr(X^T H X) - 2 tr(X^T R) + c. H is a 4x4 block per vertex on
/// the diagonal and -edgeWeight I4 per edge; products use that structure, and the sparse matrix
/// is made only when a factorisation needs it (TemplateFitter::Impl::normalMatrix).
struct Quadratic
{
  Unknowns R;
  double c = 0.0;
  std::vector<Eigen::Matrix4d> diagonal;
  double edgeWeight = 0.0;
  const Adjacency* neighbours = nullptr; // vertex adjacency of the template

  Unknowns times(const Unknowns& X) const
  {
    Unknowns out(X.rows(), 3);
    times(X, out);
    return out;
  }
  void times(const Unknowns& X, Unknowns& out) const { timesDot(X, out); }
  /// out = H X, and returns X . out (the conjugate gradients' curvature) from the same pass.
  double timesDot(const Unknowns& X, Unknowns& out) const
  {
    out.resize(X.rows(), 3);
    const int n = static_cast<int>(diagonal.size());
    return parallelSum(n,
                       [&](long from, long to)
                       {
                         double dot = 0;
                         for (long i = from; i < to; ++i)
                         {
                           Eigen::Matrix<double, 4, 3> sum = Eigen::Matrix<double, 4, 3>::Zero();
                           for (const int* j = neighbours->begin(static_cast<int>(i));
                                j != neighbours->end(static_cast<int>(i)); ++j)
                             sum += X.middleRows<4>(4 * static_cast<Eigen::Index>(*j));
                           const auto Xi = X.middleRows<4>(4 * i);
                           const Eigen::Matrix<double, 4, 3> product =
                               diagonal[i] * Xi - edgeWeight * sum;
                           out.middleRows<4>(4 * i) = product;
                           dot += (Xi.array() * product.array()).sum();
                         }
                         return dot;
                       });
  }
  double energy(const Unknowns& X) const { return dot(X, times(X)) - 2.0 * dot(X, R) + c; }
};
} // namespace clothtrack

#pragma once
// The seam between the template fit and its sparse factorisation: the fit's preconditioned
// conjugate gradients need a factor L L^T of the normal matrix (4x4 blocks, one block row per
// vertex), renewed now and then and applied to three right-hand sides at once. Two back ends:
// the block factor of this library (BlockCholesky, single precision, vectorised) and CHOLMOD's
// supernodal Cholesky (SuiteSparse, double precision), when the build found it.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace clothtrack
{
enum class FactorBackend : int
{
  Block = 0,  ///< BlockCholesky (the default; docs/template-fit.md compares the two)
  Cholmod = 1 ///< CHOLMOD supernodal LL^T
};

const char* factorBackendName(FactorBackend backend);
/// Whether this build can make the back end (CHOLMOD is optional).
bool factorBackendAvailable(FactorBackend backend);

class PreconditionerFactor
{
public:
  using Matrix = Eigen::SparseMatrix<double>;
  using RightHandSides = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

  virtual ~PreconditionerFactor() = default;
  /// Factorises `lower`, the lower triangle of the matrix, with the pattern the factor was made
  /// for (or part of it). Throws Error when it is not positive definite.
  virtual void factorise(const Matrix& lower) = 0;
  /// x with L L^T x = rhs, and rhs . x, summed in an order that depends on neither the thread
  /// count nor the run. Not reentrant.
  virtual double solveDot(const RightHandSides& rhs, RightHandSides& x) const = 0;
};

/// A factor for the pattern of `lower` (analysed once). Throws Error when the back end is not in
/// this build.
std::unique_ptr<PreconditionerFactor> makeFactor(FactorBackend backend,
                                                 const Eigen::SparseMatrix<double>& lower);
} // namespace clothtrack

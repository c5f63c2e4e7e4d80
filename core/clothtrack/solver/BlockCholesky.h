#pragma once
// Sparse Cholesky factor of a symmetric positive-definite matrix made of 4x4 blocks, one block
// row per vertex (the normal equations of per-vertex affine maps), kept in single precision as
// dense 4x4 blocks. It serves as a preconditioner: its solve runs three right-hand sides at once
// over small dense blocks, which vectorises and reads a sixteenth of the indices of a scalar
// factor. The fill-reducing ordering (approximate minimum degree) is computed on the vertex
// graph and keeps the four unknowns of a vertex together.
#include "PreconditionerFactor.h"

#include <memory>
#include <vector>

namespace clothtrack
{
class BlockCholesky final : public PreconditionerFactor
{
public:
  /// Analyses the pattern of `lower`, the lower triangle of a 4n x 4n matrix (any values).
  /// Throws Error when the size is not a multiple of 4.
  explicit BlockCholesky(const Matrix& lower);
  ~BlockCholesky() override;
  BlockCholesky(const BlockCholesky&) = delete;
  BlockCholesky& operator=(const BlockCholesky&) = delete;

  /// Factorises `lower` (the pattern given to the constructor, or part of it). Throws Error
  /// when the matrix is not positive definite.
  void factorise(const Matrix& lower) override;

  /// x with L L^T x = rhs, in single-precision arithmetic. Not reentrant: it uses scratch
  /// memory of the object.
  void solve(const RightHandSides& rhs, RightHandSides& x) const;
  /// solve(), returning rhs . x (preconditioned conjugate gradients need both) from the same
  /// pass; the sum's order depends on neither the thread count nor the run.
  double solveDot(const RightHandSides& rhs, RightHandSides& x) const override;

  /// Nonzero 4x4 blocks of the factor, diagonal ones included.
  Eigen::Index blockCount() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace clothtrack

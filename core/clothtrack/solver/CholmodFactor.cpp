#include "CholmodFactor.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>

#ifdef CLOTHTRACK_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace clothtrack
{
#ifdef CLOTHTRACK_HAVE_CHOLMOD
namespace
{
class CholmodFactor final : public PreconditionerFactor
{
public:
  explicit CholmodFactor(const Matrix& lower)
  {
    // The normal matrix is ordered by CHOLMOD itself (AMD or METIS, whichever it judges best).
    llt_.analyzePattern(lower);
    if (llt_.info() != Eigen::Success) throw Error("CHOLMOD: the analysis failed.");
  }

  void factorise(const Matrix& lower) override
  {
    llt_.factorize(lower);
    if (llt_.info() != Eigen::Success) throw Error("CHOLMOD: the matrix is not positive definite.");
  }

  double solveDot(const RightHandSides& rhs, RightHandSides& x) const override
  {
    columns_ = rhs;
    solution_ = llt_.solve(columns_);
    x = solution_;
    return parallelDot(rhs.data(), x.data(), rhs.size());
  }

private:
  // Eigen's CHOLMOD wrapper reads the lower triangle of a symmetric matrix.
  Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> llt_;
  mutable Eigen::MatrixXd columns_, solution_; // CHOLMOD wants column-major right-hand sides
};
} // namespace

std::unique_ptr<PreconditionerFactor> makeCholmodFactor(const Eigen::SparseMatrix<double>& lower)
{
  return std::make_unique<CholmodFactor>(lower);
}
#else
std::unique_ptr<PreconditionerFactor> makeCholmodFactor(const Eigen::SparseMatrix<double>&)
{
  throw Error("This build has no CHOLMOD (install libsuitesparse-dev and configure again).");
}
#endif
} // namespace clothtrack

#include "PreconditionerFactor.h"

#include "BlockCholesky.h"
#include "CholmodFactor.h"

#include <clothtrack/base/Error.h>

namespace clothtrack
{
const char* factorBackendName(FactorBackend backend)
{
  return backend == FactorBackend::Cholmod ? "cholmod" : "block";
}

bool factorBackendAvailable(FactorBackend backend)
{
#ifdef CLOTHTRACK_HAVE_CHOLMOD
  (void)backend;
  return true;
#else
  return backend == FactorBackend::Block;
#endif
}

std::unique_ptr<PreconditionerFactor> makeFactor(FactorBackend backend,
                                                 const Eigen::SparseMatrix<double>& lower)
{
  if (backend == FactorBackend::Cholmod) return makeCholmodFactor(lower);
  return std::make_unique<BlockCholesky>(lower);
}
} // namespace clothtrack

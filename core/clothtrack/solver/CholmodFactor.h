#pragma once
// CHOLMOD's supernodal Cholesky (SuiteSparse) behind the PreconditionerFactor seam, through
// Eigen's CholmodSupport, in double precision.
#include "PreconditionerFactor.h"

namespace clothtrack
{
/// Throws Error when this build has no CHOLMOD.
std::unique_ptr<PreconditionerFactor> makeCholmodFactor(const Eigen::SparseMatrix<double>& lower);
} // namespace clothtrack

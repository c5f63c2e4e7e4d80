#pragma once
// The minimisers of one round of the template fit (FitQuadratic.h): preconditioned conjugate
// gradients on the normal equations (the exact solver) and limited-memory BFGS (the paper's).
#include "FitQuadratic.h"

#include <clothtrack/solver/PreconditionerFactor.h>

namespace clothtrack
{
/// Conjugate gradients on H X = R from X, preconditioned by `factor`, until the residual norm is
/// at most `target` or after `maxSteps` steps; `work` holds four vectors of X's size (reused
/// between calls: each is a megabyte). Returns the steps, and the squared residual norm in `rr`.
int conjugateGradients(const Quadratic& q, const PreconditionerFactor& factor, double target,
                       int maxSteps, Unknowns& X, Unknowns* work[4], double& rr);

/// Limited-memory BFGS on a quadratic, with the exact line search a quadratic allows; returns
/// the iterations.
int minimiseLBFGS(const Quadratic& q, Unknowns& X, int iterations);
} // namespace clothtrack

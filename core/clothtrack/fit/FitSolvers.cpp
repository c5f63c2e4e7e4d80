#include "FitSolvers.h"

#include <clothtrack/base/Parallel.h>

#include <cmath>
#include <deque>
#include <vector>

namespace clothtrack
{
int conjugateGradients(const Quadratic& q, const PreconditionerFactor& factor, double target,
                       int maxSteps, Unknowns& X, Unknowns* work[4], double& rr)
{
  // Preconditioned conjugate gradients; the vectors are reused (each is a megabyte).
  Unknowns& r = *work[0];
  Unknowns& z = *work[1];
  Unknowns& p = *work[2];
  Unknowns& Hp = *work[3];
  q.times(X, Hp);
  r.noalias() = q.R - Hp;
  double rz = factor.solveDot(r, z);
  p = z;
  rr = parallelDot(r, r);
  const Eigen::Index size = X.size();
  using Span = Eigen::Map<Eigen::VectorXd>;
  int step = 0;
  // Passes over the vectors are fused where a step allows (memory, not arithmetic, is what
  // they cost): H p with p . H p, the updates of X and r with r . r, z with r . z.
  for (; step < maxSteps && std::sqrt(rr) > target; ++step)
  {
    const double alpha = rz / q.timesDot(p, Hp);
    rr = parallelSum(size,
                     [&](long from, long to)
                     {
                       Span rk(r.data() + from, to - from);
                       Span(X.data() + from, to - from) += alpha * Span(p.data() + from, to - from);
                       rk -= alpha * Span(Hp.data() + from, to - from);
                       return rk.squaredNorm();
                     });
    const double rzNext = factor.solveDot(r, z);
    const double beta = rzNext / rz;
    forSpans(size,
             [&](long from, long to, int)
             {
               Span pk(p.data() + from, to - from);
               pk = Span(z.data() + from, to - from) + beta * pk;
             });
    rz = rzNext;
  }
  return step;
}

/// Limited-memory BFGS on a quadratic, with the exact line search a quadratic allows.
int minimiseLBFGS(const Quadratic& q, Unknowns& X, int iterations)
{
  constexpr int kMemory = 10;
  std::deque<Unknowns> s, y;
  std::deque<double> rho;
  Unknowns g = 2.0 * (q.times(X) - q.R);
  const double g0 = g.norm();
  int done = 0;
  for (; done < iterations; ++done)
  {
    if (g.norm() <= 1e-12 * std::max(1.0, g0)) break;
    // Two-loop recursion: d = -H_k g.
    Unknowns d = -g;
    std::vector<double> alpha(s.size());
    for (int k = static_cast<int>(s.size()) - 1; k >= 0; --k)
    {
      alpha[k] = rho[k] * dot(s[k], d);
      d -= alpha[k] * y[k];
    }
    if (!s.empty()) d *= dot(s.back(), y.back()) / dot(y.back(), y.back());
    for (size_t k = 0; k < s.size(); ++k)
    {
      const double beta = rho[k] * dot(y[k], d);
      d += (alpha[k] - beta) * s[k];
    }
    const Unknowns Hd = q.times(d);
    const double curvature = 2.0 * dot(d, Hd);
    const double slope = dot(g, d);
    if (!(curvature > 0) || slope >= 0) break;
    const double step = -slope / curvature;
    const Unknowns sk = step * d;
    const Unknowns yk = 2.0 * step * Hd;
    X += sk;
    g += yk;
    const double sy = dot(sk, yk);
    if (sy <= 0) break;
    s.push_back(sk);
    y.push_back(yk);
    rho.push_back(1.0 / sy);
    if (static_cast<int>(s.size()) > kMemory) s.pop_front(), y.pop_front(), rho.pop_front();
  }
  return done;
}
} // namespace clothtrack

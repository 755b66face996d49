// The settled static state of the sticking tangents (doc/theory.md 6.2).
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/analysis/settled_friction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hati
{
namespace
{
/**
 * An eigenvalue of S below this fraction of the largest is a mechanism: the
 * slips along it cost no force. On the 3D crane (0.55 m plates) the
 * mechanisms' eigenvalues are round-off, below 4e-8 of the largest, and
 * the softest tangential connection's is 0.015 of it (doc/theory.md 6.2).
 */
constexpr double mechanism_tolerance = 1e-5;
} // namespace

void settle_sticking_tangents(const DirectSolver &solver,
                              const SparseMatrix<double> &A,
                              const unsigned int n,
                              const std::vector<unsigned int> &tangent_rows,
                              Vector<double> &x,
                              Vector<double> &b)
{
  const unsigned int nt = tangent_rows.size(), N = x.size();
  if (nt == 0)
    return;
  // the columns of A^-1 on the tangent rows, one refinement step each (all
  // at once: one pass through the factor for the block)
  std::vector<double> block(std::size_t(N) * nt, 0.), corrections(std::size_t(N) * nt);
  for (unsigned int j = 0; j < nt; ++j)
    block[std::size_t(j) * N + n + tangent_rows[j]] = 1.;
  solver.solve_many(block.data(), nt);
  std::vector<Vector<double>> columns(nt, Vector<double>(N));
  Vector<double> e(N), r(N);
  for (unsigned int j = 0; j < nt; ++j)
  {
    std::copy(block.begin() + std::size_t(j) * N,
              block.begin() + std::size_t(j + 1) * N,
              columns[j].begin());
    e = 0.;
    e[n + tangent_rows[j]] = 1.;
    A.residual(r, columns[j], e);
    std::copy(r.begin(), r.end(), corrections.begin() + std::size_t(j) * N);
  }
  solver.solve_many(corrections.data(), nt);
  for (unsigned int j = 0; j < nt; ++j)
    for (unsigned int i = 0; i < N; ++i)
      columns[j][i] += corrections[std::size_t(j) * N + i];
  LAPACKFullMatrix<double> S(nt, nt);
  double largest = 0.;
  for (unsigned int i = 0; i < nt; ++i)
    for (unsigned int j = 0; j < nt; ++j)
    {
      // symmetric up to round-off: its mean
      S(i, j) = 0.5 * (columns[j][n + tangent_rows[i]] + columns[i][n + tangent_rows[j]]);
      largest = std::max(largest, std::abs(S(i, j)));
    }
  if (largest == 0.)
    return;
  Vector<double> sigma;
  FullMatrix<double> v;
  S.compute_eigenvalues_symmetric(-std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::max(),
                                  0.,
                                  sigma,
                                  v);
  double sigma_max = 0.;
  for (unsigned int k = 0; k < sigma.size(); ++k)
    sigma_max = std::max(sigma_max, std::abs(sigma[k]));
  // the self-stress part of the tangents' multipliers (on the eigenvectors
  // that are not mechanisms) and the slips that relieve it
  std::vector<double> delta(nt, 0.);
  for (unsigned int k = 0; k < sigma.size(); ++k)
  {
    if (std::abs(sigma[k]) <= mechanism_tolerance * sigma_max)
      continue;
    double a = 0.;
    for (unsigned int i = 0; i < nt; ++i)
      a += v(i, k) * x[n + tangent_rows[i]];
    for (unsigned int i = 0; i < nt; ++i)
      delta[i] -= a / sigma[k] * v(i, k);
  }
  for (unsigned int j = 0; j < nt; ++j)
  {
    b[n + tangent_rows[j]] += delta[j];
    x.add(delta[j], columns[j]);
  }
}
} // namespace hati

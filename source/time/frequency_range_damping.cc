#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/householder.h>
#include <deal.II/lac/vector.h>

#include <hati/time/frequency_range_damping.h>

#include <cmath>
#include <complex>
#include <limits>

namespace hati
{
namespace
{
/** @p n log-spaced values from @p a to @p b (both included; n = 1: sqrt(a b)). */
std::vector<double> log_spaced(const double a, const double b, const unsigned int n)
{
  if (n == 1)
    return {std::sqrt(a * b)};
  std::vector<double> v(n);
  for (unsigned int i = 0; i < n; ++i)
    v[i] = a * std::pow(b / a, double(i) / double(n - 1));
  return v;
}

/**
 * Non-negative least squares min |A x - b|, x >= 0, for a few columns:
 * the optimum is the unconstrained least-squares solution on some set of
 * free columns (the others zero) that is itself >= 0, so the feasible
 * solution of smallest residual over all column sets is exact.
 */
dealii::Vector<double> nnls_by_enumeration(const dealii::FullMatrix<double> &A,
                                           const dealii::Vector<double> &b)
{
  const unsigned int m = A.m(), n = A.n();
  dealii::Vector<double> best(n);
  double best_residual = b.l2_norm(); // x = 0
  for (unsigned int set = 1; set < (1u << n); ++set)
  {
    std::vector<unsigned int> columns;
    for (unsigned int j = 0; j < n; ++j)
      if (set & (1u << j))
        columns.push_back(j);
    dealii::FullMatrix<double> As(m, columns.size());
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int k = 0; k < columns.size(); ++k)
        As(i, k) = A(i, columns[k]);
    dealii::Vector<double> xs(columns.size());
    const double residual = dealii::Householder<double>(As).least_squares(xs, b);
    bool feasible = std::isfinite(residual);
    for (const double x : xs)
      feasible = feasible && x >= 0.;
    if (feasible && residual < best_residual)
    {
      best_residual = residual;
      best = 0.;
      for (unsigned int k = 0; k < columns.size(); ++k)
        best[columns[k]] = xs[k];
    }
  }
  return best;
}
} // namespace

double MaxwellBranches::damping_ratio(const double f) const
{
  const double w = 2. * M_PI * f;
  std::complex<double> c(1., 0.);
  for (unsigned int l = 0; l < alpha.size(); ++l)
  {
    const std::complex<double> iwt(0., w * tau[l]);
    c += alpha[l] * iwt / (1. + iwt);
  }
  return c.imag() / (2. * c.real());
}

double MaxwellBranches::alpha_sum() const
{
  double sum = 0.;
  for (const double a : alpha)
    sum += a;
  return sum;
}

MaxwellFit fit_maxwell_branches(const double ratio,
                                const double lower_frequency,
                                const double upper_frequency,
                                const unsigned int n_branches)
{
  AssertThrow(lower_frequency > 0. && lower_frequency < upper_frequency &&
                  std::isfinite(upper_frequency) && n_branches >= 1 && n_branches <= 8,
              dealii::ExcMessage("fit_maxwell_branches: needs 0 < lower frequency < "
                                 "upper frequency and 1 to 8 branches"));
  MaxwellFit fit;
  MaxwellBranches &branches = fit.branches;
  for (const double f : log_spaced(lower_frequency, upper_frequency, n_branches))
    branches.tau.push_back(1. / (2. * M_PI * f));
  branches.alpha.assign(n_branches, 0.);

  const std::vector<double> f_fit = log_spaced(lower_frequency, upper_frequency, 60);
  dealii::FullMatrix<double> A(f_fit.size(), n_branches);
  for (unsigned int i = 0; i < f_fit.size(); ++i)
    for (unsigned int l = 0; l < n_branches; ++l)
    {
      const double wt = 2. * M_PI * f_fit[i] * branches.tau[l];
      A(i, l) = wt / (1. + wt * wt); // Im c per unit alpha_l
    }
  // first Re c = 1, then five updates with the exact loss factor
  for (unsigned int pass = 0; pass < 6; ++pass)
  {
    dealii::Vector<double> b(f_fit.size());
    for (unsigned int i = 0; i < f_fit.size(); ++i)
    {
      double re_c = 1.;
      for (unsigned int l = 0; l < n_branches; ++l)
      {
        const double wt = 2. * M_PI * f_fit[i] * branches.tau[l];
        re_c += branches.alpha[l] * wt * wt / (1. + wt * wt);
      }
      b[i] = 2. * ratio * re_c;
    }
    const dealii::Vector<double> alpha = nnls_by_enumeration(A, b);
    branches.alpha.assign(alpha.begin(), alpha.end());
  }

  for (const double f : log_spaced(lower_frequency, upper_frequency, 200))
    fit.error = std::max(fit.error, std::abs(branches.damping_ratio(f) / ratio - 1.));
  return fit;
}
} // namespace hati

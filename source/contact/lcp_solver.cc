#include <deal.II/base/exceptions.h>

#include <hati/contact/lcp_solver.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hati
{
namespace
{
/** Exact enumeration of the 2^n active sets (n <= 12). */
bool enumerate(const FullMatrix<double> &W,
               const Vector<double> &q,
               const std::vector<bool> &bilateral,
               Vector<double> &lambda)
{
  unsigned int bilateral_mask = 0;
  for (unsigned int i = 0; i < bilateral.size(); ++i)
    if (bilateral[i])
      bilateral_mask |= 1u << i;
  const unsigned int n = q.size();
  double scale = 0.;
  for (unsigned int i = 0; i < n; ++i)
    scale = std::max(scale, std::abs(q[i]));
  const double tol = 1e-12 * std::max(scale, 1e-300);

  // visit subsets by increasing size
  std::vector<unsigned int> masks(1u << n);
  for (unsigned int s = 0; s < masks.size(); ++s)
    masks[s] = s;
  std::stable_sort(masks.begin(),
                   masks.end(),
                   [](unsigned int a, unsigned int b)
                   { return __builtin_popcount(a) < __builtin_popcount(b); });

  for (const unsigned int mask : masks)
  {
    if ((mask & bilateral_mask) != bilateral_mask)
      continue; // bilateral rows are always in the active set
    std::vector<unsigned int> set;
    for (unsigned int i = 0; i < n; ++i)
      if (mask & (1u << i))
        set.push_back(i);
    lambda = 0.;
    if (!set.empty())
    {
      FullMatrix<double> Wss(set.size(), set.size());
      Vector<double> rhs(set.size());
      for (unsigned int a = 0; a < set.size(); ++a)
      {
        rhs[a] = -q[set[a]];
        for (unsigned int b = 0; b < set.size(); ++b)
          Wss(a, b) = W(set[a], set[b]);
      }
      // skip singular principal submatrices (redundant contacts)
      double wmax = 0.;
      for (unsigned int a = 0; a < set.size(); ++a)
        wmax = std::max(wmax, std::abs(Wss(a, a)));
      if (wmax == 0.)
        continue;
      const double det = Wss.determinant();
      if (set.size() <= 3 && std::abs(det) < 1e-14 * std::pow(wmax, set.size()))
        continue;
      FullMatrix<double> inv(set.size(), set.size());
      try
      {
        inv.invert(Wss);
      }
      catch (...)
      {
        continue;
      }
      Vector<double> ls(set.size());
      inv.vmult(ls, rhs);
      bool ok = true;
      for (unsigned int a = 0; a < set.size(); ++a)
      {
        const bool free_sign = (bilateral_mask >> set[a]) & 1u;
        if (!std::isfinite(ls[a]) || (!free_sign && ls[a] < -tol / wmax))
          ok = false;
        lambda[set[a]] = free_sign ? ls[a] : std::max(0., ls[a]);
      }
      if (!ok)
        continue;
    }
    // check w >= 0 on the complement
    bool ok = true;
    for (unsigned int i = 0; i < n && ok; ++i)
      if (!(mask & (1u << i)))
      {
        double w = q[i];
        for (unsigned int j = 0; j < n; ++j)
          w += W(i, j) * lambda[j];
        if (w < -tol)
          ok = false;
      }
    if (ok)
      return true;
  }
  return false;
}

/** Projected Gauss-Seidel for larger clusters. */
bool projected_gauss_seidel(const FullMatrix<double> &W,
                            const Vector<double> &q,
                            const std::vector<bool> &bilateral,
                            Vector<double> &lambda)
{
  const unsigned int n = q.size();
  lambda = 0.;
  const double qnorm = std::max(q.linfty_norm(), 1e-300);
  for (unsigned int it = 0; it < 100000; ++it)
  {
    double change = 0.;
    for (unsigned int i = 0; i < n; ++i)
    {
      double r = q[i];
      for (unsigned int j = 0; j < n; ++j)
        r += W(i, j) * lambda[j];
      const double li = (i < bilateral.size() && bilateral[i])
                            ? lambda[i] - r / W(i, i)
                            : std::max(0., lambda[i] - r / W(i, i));
      change = std::max(change, std::abs(li - lambda[i]) * W(i, i));
      lambda[i] = li;
    }
    if (change <= 1e-12 * qnorm)
      return true;
  }
  return false;
}
} // namespace

Vector<double> solve_lcp(const FullMatrix<double> &W,
                         const Vector<double> &q,
                         const std::vector<bool> &bilateral)
{
  const bool has_bilateral =
      std::find(bilateral.begin(), bilateral.end(), true) != bilateral.end();
  const unsigned int n = q.size();
  Vector<double> lambda(n);
  if (n == 0)
    return lambda;
  for (unsigned int i = 0; i < n; ++i)
    AssertThrow(W(i, i) > 0.,
                ExcMessage("contact LCP: a contact acts on degrees of freedom without "
                           "mass (fixed or massless); its Delassus entry is zero."));
  if (n == 1)
  {
    lambda[0] = has_bilateral ? -q[0] / W(0, 0) : std::max(0., -q[0] / W(0, 0));
    return lambda;
  }
  const bool ok = (n <= 12) ? enumerate(W, q, bilateral, lambda)
                            : projected_gauss_seidel(W, q, bilateral, lambda);
  if (!ok)
  {
    std::ostringstream s;
    s << "contact LCP: no solution found for a cluster of " << n
      << " coupled contacts (W not positive semi-definite, or PGS did not converge)";
    AssertThrow(false, ExcMessage(s.str()));
  }
  return lambda;
}
} // namespace hati

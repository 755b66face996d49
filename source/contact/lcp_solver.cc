#include <deal.II/base/exceptions.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/contact/lcp_solver.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace hati
{
namespace
{
/**
 * Whether the square matrix @p A (n <= 12) is regular: Gaussian elimination
 * with partial pivoting on a copy, every pivot above 1e-12 of the largest
 * diagonal entry @p wmax. FullMatrix::invert() checks nothing in Release
 * (a singular set of 4 to 12 contacts gave huge or non-finite values), so
 * the enumeration asks this first; the inverse itself is still invert()'s.
 */
bool regular(const FullMatrix<double> &A, const double wmax)
{
  const unsigned int n = A.m();
  std::array<double, 144> a;
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      a[i * n + j] = A(i, j);
  for (unsigned int k = 0; k < n; ++k)
  {
    unsigned int p = k;
    for (unsigned int i = k + 1; i < n; ++i)
      if (std::abs(a[i * n + k]) > std::abs(a[p * n + k]))
        p = i;
    if (!(std::abs(a[p * n + k]) > 1e-12 * wmax))
      return false;
    if (p != k)
      for (unsigned int j = 0; j < n; ++j)
        std::swap(a[k * n + j], a[p * n + j]);
    for (unsigned int i = k + 1; i < n; ++i)
    {
      const double f = a[i * n + k] / a[k * n + k];
      for (unsigned int j = k; j < n; ++j)
        a[i * n + j] -= f * a[k * n + j];
    }
  }
  return true;
}

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
  // the active sets by size (smallest first), and the work matrices of
  // each size: built once per thread, no allocation afterwards
  static thread_local std::array<std::vector<unsigned int>, 13> sorted_masks;
  static thread_local std::array<FullMatrix<double>, 13> Wss_of_size, inv_of_size;
  static thread_local std::array<Vector<double>, 13> rhs_of_size, ls_of_size;
  std::vector<unsigned int> &masks = sorted_masks[n];
  if (masks.empty())
  {
    masks.resize(1u << n);
    for (unsigned int s = 0; s < masks.size(); ++s)
      masks[s] = s;
    std::stable_sort(masks.begin(),
                     masks.end(),
                     [](unsigned int a, unsigned int b)
                     { return __builtin_popcount(a) < __builtin_popcount(b); });
  }

  std::array<unsigned int, 12> set_entries;
  for (const unsigned int mask : masks)
  {
    if ((mask & bilateral_mask) != bilateral_mask)
      continue; // bilateral rows are always in the active set
    unsigned int set_size = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (mask & (1u << i))
        set_entries[set_size++] = i;
    const auto set = [&](const unsigned int a) { return set_entries[a]; };
    lambda = 0.;
    if (set_size > 0)
    {
      FullMatrix<double> &Wss = Wss_of_size[set_size];
      Vector<double> &rhs = rhs_of_size[set_size];
      if (Wss.m() != set_size)
      {
        Wss.reinit(set_size, set_size);
        inv_of_size[set_size].reinit(set_size, set_size);
        rhs.reinit(set_size);
        ls_of_size[set_size].reinit(set_size);
      }
      for (unsigned int a = 0; a < set_size; ++a)
      {
        rhs[a] = -q[set(a)];
        for (unsigned int b = 0; b < set_size; ++b)
          Wss(a, b) = W(set(a), set(b));
      }
      // skip singular principal submatrices (redundant contacts)
      double wmax = 0.;
      for (unsigned int a = 0; a < set_size; ++a)
        wmax = std::max(wmax, std::abs(Wss(a, a)));
      if (wmax == 0.)
        continue;
      // (FullMatrix::determinant() is exact up to 3 x 3 only)
      if (set_size <= 3 && std::abs(Wss.determinant()) < 1e-14 * std::pow(wmax, set_size))
        continue;
      if (set_size > 3 && !regular(Wss, wmax))
        continue;
      FullMatrix<double> &inv = inv_of_size[set_size];
      try
      {
        inv.invert(Wss);
      }
      catch (...)
      {
        continue;
      }
      Vector<double> &ls = ls_of_size[set_size];
      inv.vmult(ls, rhs);
      bool ok = true;
      for (unsigned int a = 0; a < set_size; ++a)
      {
        const bool free_sign = (bilateral_mask >> set(a)) & 1u;
        if (!std::isfinite(ls[a]) || (!free_sign && ls[a] < -tol / wmax))
          ok = false;
        lambda[set(a)] = free_sign ? ls[a] : std::max(0., ls[a]);
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

[[noreturn]] void throw_no_solution(const unsigned int n)
{
  std::ostringstream s;
  s << "contact LCP: no solution found for a cluster of " << n
    << " coupled contacts (W not positive semi-definite, or PGS did not converge)";
  AssertThrow(false, ExcMessage(s.str()));
  std::abort();
}

/**
 * The elimination of a cluster's bilateral rows (BilateralElimination);
 * false where W_BB is singular to round-off (redundant equalities) or a
 * unilateral row moves only with the equalities (S(a, a) ~ 0): there the
 * plain solve.
 */
bool form_elimination(const FullMatrix<double> &W,
                      const std::vector<bool> &bilateral,
                      BilateralElimination &e)
{
  const unsigned int n = W.m();
  e.b.clear();
  e.u.clear();
  for (unsigned int i = 0; i < n; ++i)
    (i < bilateral.size() && bilateral[i] ? e.b : e.u).push_back(i);
  if (!eliminate_rows(W, e.b, e.u, e.schur))
    return false;
  const unsigned int nb = e.b.size(), nu = e.u.size();
  for (unsigned int a = 0; a < nu; ++a)
    if (!(e.schur.S(a, a) > 1e-10 * W(e.u[a], e.u[a])))
      return false;
  e.q_b.reinit(nb);
  e.y.reinit(nb);
  e.q_s.reinit(nu);
  e.lambda_u.reinit(nu);
  return true;
}
} // namespace

bool eliminate_rows(const FullMatrix<double> &W,
                    const std::vector<unsigned int> &b,
                    const std::vector<unsigned int> &c,
                    SchurElimination &e)
{
  const unsigned int nb = b.size(), nc = c.size();
  FullMatrix<double> Wbb(nb, nb);
  e.Wbc.reinit(nb, nc);
  for (unsigned int k = 0; k < nb; ++k)
  {
    for (unsigned int j = 0; j < nb; ++j)
      Wbb(k, j) = W(b[k], b[j]);
    for (unsigned int l = 0; l < nc; ++l)
      e.Wbc(k, l) = W(b[k], c[l]);
  }
  // W_BB = L_B M^-1 L_B^T: symmetric, positive definite unless the
  // equalities are dependent (Cholesky throws there, in every build)
  LAPACKFullMatrix<double> inverse(nb, nb);
  inverse = Wbb;
  inverse.set_property(LAPACKSupport::symmetric);
  try
  {
    inverse.invert();
  }
  catch (...)
  {
    return false;
  }
  e.Wbb_inverse.reinit(nb, nb);
  for (unsigned int k = 0; k < nb; ++k)
    for (unsigned int j = 0; j < nb; ++j)
      e.Wbb_inverse(k, j) = inverse(k, j);
  // W_BB^-1 W_BB = I to 1e-9, else the equalities are (nearly) dependent
  FullMatrix<double> identity(nb, nb);
  e.Wbb_inverse.mmult(identity, Wbb);
  for (unsigned int k = 0; k < nb; ++k)
    identity(k, k) -= 1.;
  if (!(identity.linfty_norm() <= 1e-9 * nb))
    return false;
  complete_elimination(W, c, e);
  return true;
}

void complete_elimination(const FullMatrix<double> &W,
                          const std::vector<unsigned int> &c,
                          SchurElimination &e)
{
  const unsigned int nb = e.Wbb_inverse.m(), nc = c.size();
  // X = W_BB^-1 W_BC, S = W_CC - W_BC^T X
  e.X.reinit(nb, nc);
  e.S.reinit(nc, nc);
  if (nc == 0)
    return;
  FullMatrix<double> Wcc(nc, nc);
  for (unsigned int a = 0; a < nc; ++a)
    for (unsigned int l = 0; l < nc; ++l)
      Wcc(a, l) = W(c[a], c[l]);
  e.Wbb_inverse.mmult(e.X, e.Wbc);
  e.Wbc.Tmmult(e.S, e.X);
  e.S *= -1.;
  e.S.add(1., Wcc);
}

Vector<double> solve_lcp(const FullMatrix<double> &W,
                         const Vector<double> &q,
                         const std::vector<bool> &bilateral)
{
  Vector<double> lambda(q.size());
  solve_lcp(W, q, bilateral, lambda);
  return lambda;
}

void solve_lcp(const FullMatrix<double> &W,
               const Vector<double> &q,
               const std::vector<bool> &bilateral,
               Vector<double> &lambda)
{
  const bool has_bilateral =
      std::find(bilateral.begin(), bilateral.end(), true) != bilateral.end();
  const unsigned int n = q.size();
  if (lambda.size() != n)
    lambda.reinit(n);
  if (n == 0)
    return;
  for (unsigned int i = 0; i < n; ++i)
    AssertThrow(W(i, i) > 0.,
                ExcMessage("contact LCP: a contact acts on degrees of freedom without "
                           "mass (fixed or massless); its Delassus entry is zero."));
  if (n == 1)
  {
    lambda[0] = has_bilateral ? -q[0] / W(0, 0) : std::max(0., -q[0] / W(0, 0));
    return;
  }
  const bool ok = (n <= 12) ? enumerate(W, q, bilateral, lambda)
                            : projected_gauss_seidel(W, q, bilateral, lambda);
  if (!ok)
    throw_no_solution(n);
}

void solve_lcp(const FullMatrix<double> &W,
               const Vector<double> &q,
               const std::vector<bool> &bilateral,
               Vector<double> &lambda,
               BilateralElimination &e)
{
  const unsigned int n = q.size();
  if (n <= 12 || std::find(bilateral.begin(), bilateral.end(), true) == bilateral.end())
  {
    solve_lcp(W, q, bilateral, lambda);
    return;
  }
  if (!e.formed)
  {
    e.invertible = form_elimination(W, bilateral, e);
    e.formed = true;
  }
  if (!e.invertible)
  {
    solve_lcp(W, q, bilateral, lambda);
    return;
  }
  if (lambda.size() != n)
    lambda.reinit(n);
  const unsigned int nb = e.b.size(), nu = e.u.size();
  // y = W_BB^-1 q_B, q_S = q_U - W_BU^T y
  for (unsigned int k = 0; k < nb; ++k)
    e.q_b[k] = q[e.b[k]];
  e.schur.Wbb_inverse.vmult(e.y, e.q_b);
  if (nu > 0)
    e.schur.Wbc.Tvmult(e.q_s, e.y);
  for (unsigned int a = 0; a < nu; ++a)
    e.q_s[a] = q[e.u[a]] - e.q_s[a];
  // the unilateral rows' LCP (their S(a, a) > 0: form_elimination())
  if (nu == 1)
    e.lambda_u[0] = std::max(0., -e.q_s[0] / e.schur.S(0, 0));
  else if (nu > 1)
  {
    static const std::vector<bool> none;
    const bool ok = (nu <= 12)
                        ? enumerate(e.schur.S, e.q_s, none, e.lambda_u)
                        : projected_gauss_seidel(e.schur.S, e.q_s, none, e.lambda_u);
    if (!ok)
      throw_no_solution(n);
  }
  for (unsigned int a = 0; a < nu; ++a)
    lambda[e.u[a]] = e.lambda_u[a];
  // lambda_B = -(y + X lambda_U)
  if (nu > 0)
    e.schur.X.vmult_add(e.y, e.lambda_u);
  for (unsigned int k = 0; k < nb; ++k)
    lambda[e.b[k]] = -e.y[k];
}

void minimum_norm_solution(const FullMatrix<double> &W,
                           const Vector<double> &q,
                           Vector<double> &lambda)
{
  // lambda = -W^+ q, W^+ the pseudo-inverse by deal.II's SVD, singular
  // values below 1e-12 of the largest taken as zero
  const unsigned int n = W.m();
  LAPACKFullMatrix<double> inverse(n, n);
  inverse = W;
  inverse.compute_inverse_svd(1e-12);
  lambda.reinit(n);
  inverse.vmult(lambda, q);
  lambda *= -1.;
}

void solve_equalities(const FullMatrix<double> &W,
                      FullMatrix<double> &W_inverse,
                      bool &inverted,
                      const Vector<double> &q,
                      Vector<double> &lambda)
{
  const unsigned int n = W.m();
  if (!inverted)
  {
    if (W_inverse.m() != n || W_inverse.n() != W.n())
      W_inverse.reinit(n, W.n());
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < W.n(); ++j)
        W_inverse(i, j) = W(i, j);
    W_inverse.gauss_jordan();
    inverted = true;
  }
  if (lambda.size() != q.size())
    lambda.reinit(q.size());
  W_inverse.vmult(lambda, q);
  lambda *= -1.;
  // W is singular where rows of the set are dependent (a flange's lateral
  // contact along a sticking wheel's tangent): Gauss-Jordan then gives no
  // finite solution; the minimum-norm one (q lies in the range of W = L M^-1
  // L^T, since q = L v) gives the same velocities
  bool finite = true;
  for (unsigned int i = 0; i < n; ++i)
    finite = finite && std::isfinite(lambda[i]);
  if (!finite)
    minimum_norm_solution(W, q, lambda);
}
} // namespace hati

#include <deal.II/base/exceptions.h>

#include <hati/contact/friction_solver.h>

#include <algorithm>
#include <cmath>

namespace hati
{
namespace
{
/** Solve the n x n system A x = b (n <= 3, row-major, partial pivoting); false if
 * singular. */
bool solve_small(const double *A, const double *b, const unsigned int n, double *x)
{
  double a[3][4];
  for (unsigned int i = 0; i < n; ++i)
  {
    for (unsigned int j = 0; j < n; ++j)
      a[i][j] = A[i * n + j];
    a[i][n] = b[i];
  }
  for (unsigned int c = 0; c < n; ++c)
  {
    unsigned int p = c;
    for (unsigned int i = c + 1; i < n; ++i)
      if (std::abs(a[i][c]) > std::abs(a[p][c]))
        p = i;
    if (a[p][c] == 0.)
      return false;
    for (unsigned int j = 0; j <= n; ++j)
      std::swap(a[c][j], a[p][j]);
    for (unsigned int i = c + 1; i < n; ++i)
    {
      const double f = a[i][c] / a[c][c];
      for (unsigned int j = c; j <= n; ++j)
        a[i][j] -= f * a[c][j];
    }
  }
  for (int i = n - 1; i >= 0; --i)
  {
    double s = a[i][n];
    for (unsigned int j = i + 1; j < n; ++j)
      s -= a[i][j] * x[j];
    x[i] = s / a[i][i];
  }
  return true;
}

/**
 * The sliding solution of a contact with two tangents for the direction
 * angle phi (A9): `r_n = sigma rho`, `r_t = -mu rho s`, `s = (cos phi, sin
 * phi)`, with rho from `u_n = 0`; g = s_perp . u_t (zero at a solution),
 * its derivative, rho and alpha = s . u_t (> 0 at a solution).
 */
struct SlidingAngle
{
  const double *W, *q;
  double mu, sigma;

  /** False if the normal equation has no positive rho at this angle. */
  bool
  operator()(const double phi, double &g, double &dg, double &rho, double &alpha) const
  {
    const double s[2] = {std::cos(phi), std::sin(phi)}, p[2] = {-s[1], s[0]};
    const double Wnn = W[0], Wnt[2] = {W[1], W[2]}, Wtn[2] = {W[3], W[6]};
    const double Wtt[2][2] = {{W[4], W[5]}, {W[7], W[8]}};
    const double D = sigma * Wnn - mu * (Wnt[0] * s[0] + Wnt[1] * s[1]);
    if (D == 0.)
      return false;
    rho = -q[0] / D;
    if (!(rho >= 0.))
      return false;
    const double dD = -mu * (Wnt[0] * p[0] + Wnt[1] * p[1]);
    const double drho = q[0] * dD / (D * D);
    double u[2], du[2];
    for (unsigned int i = 0; i < 2; ++i)
    {
      const double Ws = Wtt[i][0] * s[0] + Wtt[i][1] * s[1],
                   Wp = Wtt[i][0] * p[0] + Wtt[i][1] * p[1];
      u[i] = q[1 + i] + sigma * rho * Wtn[i] - mu * rho * Ws;
      du[i] = sigma * drho * Wtn[i] - mu * drho * Ws - mu * rho * Wp;
    }
    g = p[0] * u[0] + p[1] * u[1];
    alpha = s[0] * u[0] + s[1] * u[1];
    dg = -alpha + p[0] * du[0] + p[1] * du[1];
    return true;
  }
};

/** The sliding impulse for the angle @p phi; true if it is a solution. */
bool sliding_from_angle(const SlidingAngle &f, const double phi, double *r)
{
  double g, dg, rho, alpha;
  if (!f(phi, g, dg, rho, alpha) || !(alpha >= 0.))
    return false;
  r[0] = f.sigma * rho;
  r[1] = -f.mu * rho * std::cos(phi);
  r[2] = -f.mu * rho * std::sin(phi);
  return true;
}

/** Sliding with two tangents: Newton on the angle, then a scan with bisection. */
bool slide_two_tangents(
    const double *W, const double *q, const double mu, const double sigma, double *r)
{
  const SlidingAngle f{W, q, mu, sigma};
  // the fixed point s <- u_t(s) / |u_t(s)| from s = q_t / |q_t|: exact for
  // an isotropic block (W_nt = 0, W_tt = w I), a start for Newton otherwise
  double phi = std::atan2(q[2], q[1]);
  double g = 0., dg = 0., rho = 0., alpha = 0.;
  for (unsigned int it = 0; it < 3; ++it)
  {
    if (!f(phi, g, dg, rho, alpha))
      break;
    const double s[2] = {std::cos(phi), std::sin(phi)};
    const double u0 = alpha * s[0] - g * s[1], u1 = alpha * s[1] + g * s[0];
    if (g == 0.)
      break;
    phi = std::atan2(u1, u0);
  }
  const double scale = std::abs(q[0]) *
                           (std::abs(W[0]) + std::abs(W[4]) + std::abs(W[8])) /
                           std::max(std::abs(W[0]), 1e-300) +
                       std::abs(q[1]) + std::abs(q[2]);
  for (unsigned int it = 0; it < 50; ++it)
  {
    if (!f(phi, g, dg, rho, alpha))
      break;
    if (std::abs(g) <= 1e-15 * scale)
    {
      if (sliding_from_angle(f, phi, r))
        return true;
      break; // a root with the wrong direction (alpha < 0)
    }
    if (dg == 0.)
      break;
    phi -= g / dg;
  }
  // a scan of the angle for sign changes of g with alpha > 0, then bisection
  constexpr unsigned int n_scan = 720;
  const double pi = std::acos(-1.);
  double a = -pi, ga = 0.;
  bool valid_a = f(a, ga, dg, rho, alpha) && alpha > 0.;
  for (unsigned int i = 1; i <= n_scan; ++i)
  {
    const double b = -pi + 2. * pi * i / n_scan;
    double gb = 0.;
    const bool valid_b = f(b, gb, dg, rho, alpha) && alpha > 0.;
    if (valid_a && valid_b && (ga == 0. || (ga < 0.) != (gb < 0.)))
    {
      double lo = a, hi = b, glo = ga;
      for (unsigned int k = 0; k < 200 && hi - lo > 1e-16 * pi; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        double gm = 0.;
        if (!f(mid, gm, dg, rho, alpha))
          break;
        if ((gm < 0.) == (glo < 0.))
        {
          lo = mid;
          glo = gm;
        }
        else
          hi = mid;
      }
      if (sliding_from_angle(f, 0.5 * (lo + hi), r))
        return true;
    }
    a = b;
    ga = gb;
    valid_a = valid_b;
  }
  return false;
}

/** Sliding with one tangent: both directions in closed form. */
bool slide_one_tangent(
    const double *W, const double *q, const double mu, const double sigma, double *r)
{
  for (const double s : {1., -1.})
  {
    const double D = sigma * W[0] - mu * W[1] * s;
    if (D == 0.)
      continue;
    const double rho = -q[0] / D;
    if (!(rho >= 0.))
      continue;
    const double ut = q[1] + sigma * rho * W[2] - mu * rho * W[3] * s;
    if (ut * s >= 0.)
    {
      r[0] = sigma * rho;
      r[1] = -mu * rho * s;
      return true;
    }
  }
  return false;
}
} // namespace

FrictionState solve_local_coulomb(const double *W,
                                  const unsigned int size,
                                  const double *q,
                                  const double mu,
                                  const bool bilateral,
                                  double *r,
                                  bool &exact)
{
  Assert(size >= 1 && size <= 3, ExcIndexRange(size, 1, 4));
  exact = true;
  for (unsigned int i = 0; i < size; ++i)
    r[i] = 0.;
  // open: no impulse is needed to keep the gap from closing
  if (!bilateral && q[0] >= 0.)
    return FrictionState::open;
  if (size == 1)
  {
    r[0] = bilateral ? -q[0] / W[0] : std::max(0., -q[0] / W[0]);
    return r[0] != 0. ? FrictionState::slip : FrictionState::open;
  }
  // sticking: u = 0, inside the cone
  double stick[3] = {0., 0., 0.}, minus_q[3];
  for (unsigned int i = 0; i < size; ++i)
    minus_q[i] = -q[i];
  const bool solved = solve_small(W, minus_q, size, stick);
  const double tangential = std::sqrt(stick[1] * stick[1] + stick[2] * stick[2]);
  if (solved && (bilateral || stick[0] >= 0.) && tangential <= mu * std::abs(stick[0]))
  {
    std::copy(stick, stick + size, r);
    return FrictionState::stick;
  }
  // sliding: u_n = 0, r_t = -mu |r_n| u_t / |u_t|; r_n = sigma rho
  for (const double sigma : {1., -1.})
  {
    if (sigma < 0. && !bilateral)
      break;
    if (size == 2 ? slide_one_tangent(W, q, mu, sigma, r)
                  : slide_two_tangents(W, q, mu, sigma, r))
      return FrictionState::slip;
  }
  // no solution found: the sticking impulse projected on the cone
  exact = false;
  if (solved)
  {
    std::copy(stick, stick + size, r);
    if (!bilateral)
      r[0] = std::max(0., r[0]);
    const double bound = mu * std::abs(r[0]);
    if (tangential > bound)
      for (unsigned int i = 1; i < size; ++i)
        r[i] *= bound / tangential;
  }
  return FrictionState::slip;
}

FrictionSolverResult solve_frictional_cluster(const FullMatrix<double> &W,
                                              const Vector<double> &q,
                                              const std::vector<unsigned int> &first,
                                              const std::vector<double> &mu,
                                              const std::vector<bool> &bilateral,
                                              Vector<double> &r,
                                              std::vector<FrictionState> &state,
                                              const FrictionSolverControl &control)
{
  const unsigned int m = mu.size(), n = q.size();
  AssertDimension(first.size(), m + 1);
  AssertDimension(first[m], n);
  if (r.size() != n)
    r.reinit(n);
  else
    r = 0.;
  state.assign(m, FrictionState::open);
  FrictionSolverResult result;
  double Wk[9], qk[3], rk[3];
  for (unsigned int sweep = 1;; ++sweep)
  {
    double change = 0., norm = 0.;
    bool exact_sweep = true;
    for (unsigned int k = 0; k < m; ++k)
    {
      const unsigned int a = first[k], size = first[k + 1] - a;
      AssertThrow(size >= 1 && size <= 3,
                  ExcMessage("friction solver: a contact has 0 or more than 2 tangents"));
      // the local problem with the other contacts' impulses as they are
      for (unsigned int i = 0; i < size; ++i)
      {
        double s = q[a + i];
        for (unsigned int j = 0; j < n; ++j)
          if (j < a || j >= a + size)
            s += W(a + i, j) * r[j];
        qk[i] = s;
        for (unsigned int j = 0; j < size; ++j)
          Wk[i * size + j] = W(a + i, a + j);
      }
      bool exact = true;
      state[k] = solve_local_coulomb(Wk, size, qk, mu[k], bilateral[k], rk, exact);
      exact_sweep = exact_sweep && exact;
      double d = 0., l = 0.;
      for (unsigned int i = 0; i < size; ++i)
      {
        d += (rk[i] - r[a + i]) * (rk[i] - r[a + i]);
        l += rk[i] * rk[i];
        r[a + i] = rk[i];
      }
      change += std::sqrt(d);
      norm += std::sqrt(l);
    }
    result.sweeps = sweep;
    result.converged = exact_sweep;
    if (m == 1 || change <= control.tolerance * norm)
      return result;
    if (sweep >= control.max_sweeps)
    {
      result.converged = false;
      return result;
    }
  }
}
} // namespace hati

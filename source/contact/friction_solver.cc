#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/contact/friction_solver.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
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
  const double scale = std::abs(q[0]) *
                           (std::abs(W[0]) + std::abs(W[4]) + std::abs(W[8])) /
                           std::max(std::abs(W[0]), 1e-300) +
                       std::abs(q[1]) + std::abs(q[2]);
  double phi = std::atan2(q[2], q[1]);
  double g = 0., dg = 0., rho = 0., alpha = 0.;
  for (unsigned int it = 0; it < 3; ++it)
  {
    if (!f(phi, g, dg, rho, alpha))
      break;
    const double s[2] = {std::cos(phi), std::sin(phi)};
    const double u0 = alpha * s[0] - g * s[1], u1 = alpha * s[1] + g * s[0];
    // stop at a root: near sticking u_t is tiny and its angle mostly round-off
    if (std::abs(g) <= 1e-15 * scale)
      break;
    phi = std::atan2(u1, u0);
  }
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

LocalCoulombSolution solve_local_coulomb(const double *W,
                                         const unsigned int size,
                                         const double *q,
                                         const double mu,
                                         const bool bilateral,
                                         double *r)
{
  Assert(size >= 1 && size <= 3, ExcIndexRange(size, 1, 4));
  for (unsigned int i = 0; i < size; ++i)
    r[i] = 0.;
  // open: no impulse is needed to keep the gap from closing
  if (!bilateral && q[0] >= 0.)
    return {FrictionState::open, true};
  if (size == 1)
  {
    r[0] = bilateral ? -q[0] / W[0] : std::max(0., -q[0] / W[0]);
    return {r[0] != 0. ? FrictionState::slip : FrictionState::open, true};
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
    return {FrictionState::stick, true};
  }
  // sliding: u_n = 0, r_t = -mu |r_n| u_t / |u_t|; r_n = sigma rho
  for (const double sigma : {1., -1.})
  {
    if (sigma < 0. && !bilateral)
      break;
    if (size == 2 ? slide_one_tangent(W, q, mu, sigma, r)
                  : slide_two_tangents(W, q, mu, sigma, r))
      return {FrictionState::slip, true};
  }
  // no solution found: the sticking impulse projected on the cone
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
  return {FrictionState::slip, false};
}

namespace
{
/**
 * A frictional contact and its partners: the frictionless one-row contacts
 * of the cluster whose row is parallel to one of its tangent rows (a wheel's
 * flange against its lateral tangent). Gauss-Seidel cannot split the
 * tangential impulse between such rows efficiently (the sweeps contract by
 * about the ratio of the slip speed to the relative velocity), so the
 * block is solved exactly as one local problem (block_solve()).
 */
struct FrictionBlock
{
  unsigned int contact;
  /** At most two partners (one per tangent); fixed storage, no allocation. */
  boost::container::static_vector<unsigned int, 2> partners;
  /** Per partner the global row of the tangent it is parallel to. */
  boost::container::static_vector<unsigned int, 2> parallel_to;
};

/** Whether rows i and j of the Delassus matrix are parallel (Cauchy-Schwarz equality). */
bool parallel_rows(const FullMatrix<double> &W,
                   const unsigned int i,
                   const unsigned int j)
{
  const double wii = W(i, i), wjj = W(j, j), wij = W(i, j);
  return wii > 0. && wjj > 0. && wij * wij >= (1. - 1e-12) * wii * wjj;
}

/** The blocks of a cluster: every contact once, frictional contacts with their partners.
 */
void friction_blocks(const FullMatrix<double> &W,
                     const std::vector<unsigned int> &first,
                     const std::vector<double> &mu,
                     std::vector<FrictionBlock> &all)
{
  const unsigned int m = mu.size();
  // work space reused from call to call (the solver runs every step)
  thread_local std::vector<int> owner;
  thread_local std::vector<FrictionBlock> blocks;
  owner.assign(m, -1);
  blocks.clear();
  for (unsigned int k = 0; k < m; ++k)
    if (mu[k] > 0. && first[k + 1] - first[k] > 1)
    {
      FrictionBlock b{k, {}, {}};
      for (unsigned int f = 0; f < m && b.partners.size() < 2; ++f)
        if (f != k && owner[f] < 0 && first[f + 1] - first[f] == 1)
          for (unsigned int t = first[k] + 1; t < first[k + 1]; ++t)
            if (parallel_rows(W, first[f], t))
            {
              b.partners.push_back(f);
              b.parallel_to.push_back(t);
              owner[f] = k;
              break;
            }
      owner[k] = k;
      blocks.push_back(b);
    }
  all.clear();
  for (unsigned int k = 0; k < m; ++k)
    if (owner[k] == static_cast<int>(k))
      all.push_back(*std::find_if(blocks.begin(),
                                  blocks.end(),
                                  [k](const FrictionBlock &b)
                                  { return b.contact == k; }));
    else if (owner[k] < 0)
      all.push_back(FrictionBlock{k, {}, {}});
}

/**
 * The exact solution of a block with partners: for each set S of closed
 * partners (bilateral partners always closed) the tangents parallel to a
 * closed partner are held by it (no slip along them, their friction impulse
 * zero: the partner carries that direction), the partners' rows are
 * eliminated (u_f = 0, Schur complement) and the contact's reduced local
 * problem is solved exactly (solve_local_coulomb()); the first S whose
 * partner impulses are >= 0 and whose open partners do not close is taken.
 * @p Wb, @p qb the block's rows (the contact's, then one per partner),
 * @p held the contact's local tangent row each partner is parallel to.
 * False if no set gave a consistent solution.
 */
bool block_solve(const FullMatrix<double> &Wb,
                 const std::vector<double> &qb,
                 const unsigned int size,
                 const std::vector<unsigned int> &held,
                 const double mu,
                 const bool bilateral,
                 const std::vector<bool> &partner_bilateral,
                 std::vector<double> &rb,
                 FrictionState &state)
{
  const unsigned int p = held.size(), nb = size + p;
  // the inverse of W_SS per size of S (0, 1 or 2), reused
  thread_local std::array<FullMatrix<double>, 3> inverses;
  for (unsigned int mask = 0; mask < (1u << p); ++mask)
  {
    bool valid = true;
    boost::container::static_vector<unsigned int, 2> S;
    boost::container::static_vector<unsigned int, 3> F{0};
    for (unsigned int i = 0; i < p; ++i)
      if (mask & (1u << i))
        S.push_back(size + i);
      else if (partner_bilateral[i])
        valid = false;
    if (!valid)
      continue;
    for (unsigned int t = 1; t < size; ++t)
    {
      bool is_held = false;
      for (unsigned int i = 0; i < p; ++i)
        is_held = is_held || ((mask & (1u << i)) && held[i] == t);
      if (!is_held)
        F.push_back(t);
    }
    const unsigned int s = S.size(), f = F.size();
    FullMatrix<double> &WSS_inv = inverses[s];
    WSS_inv.reinit(s, s);
    for (unsigned int i = 0; i < s; ++i)
      for (unsigned int j = 0; j < s; ++j)
        WSS_inv(i, j) = Wb(S[i], S[j]);
    if (s > 0)
    {
      if (s == 2 && std::abs(WSS_inv.determinant()) <=
                        1e-12 * std::abs(WSS_inv(0, 0) * WSS_inv(1, 1)))
        continue; // two partners along the same direction cannot both hold
      WSS_inv.gauss_jordan();
    }
    // W' = W_FF - W_FS W_SS^-1 W_SF, q' = q_F - W_FS W_SS^-1 q_S
    double Wr[9], qr[3], rr[3];
    for (unsigned int a = 0; a < f; ++a)
    {
      qr[a] = qb[F[a]];
      for (unsigned int i = 0; i < s; ++i)
        for (unsigned int j = 0; j < s; ++j)
          qr[a] -= Wb(F[a], S[i]) * WSS_inv(i, j) * qb[S[j]];
      for (unsigned int c = 0; c < f; ++c)
      {
        double w = Wb(F[a], F[c]);
        for (unsigned int i = 0; i < s; ++i)
          for (unsigned int j = 0; j < s; ++j)
            w -= Wb(F[a], S[i]) * WSS_inv(i, j) * Wb(S[j], F[c]);
        Wr[a * f + c] = w;
      }
    }
    const LocalCoulombSolution local = solve_local_coulomb(Wr, f, qr, mu, bilateral, rr);
    if (!local.exact)
      continue;
    std::fill(rb.begin(), rb.end(), 0.);
    for (unsigned int a = 0; a < f; ++a)
      rb[F[a]] = rr[a];
    // r_S = -W_SS^-1 (q_S + W_SF r_F)
    for (unsigned int i = 0; i < s; ++i)
    {
      double v = 0.;
      for (unsigned int j = 0; j < s; ++j)
      {
        double u = qb[S[j]];
        for (unsigned int a = 0; a < f; ++a)
          u += Wb(S[j], F[a]) * rr[a];
        v -= WSS_inv(i, j) * u;
      }
      rb[S[i]] = v;
      if (!partner_bilateral[S[i] - size] && v < 0.)
        valid = false;
    }
    // the open partners must not close
    for (unsigned int i = 0; i < p && valid; ++i)
      if (!(mask & (1u << i)))
      {
        double u = qb[size + i], scale = std::abs(qb[size + i]);
        for (unsigned int j = 0; j < nb; ++j)
        {
          u += Wb(size + i, j) * rb[j];
          scale += std::abs(Wb(size + i, j) * rb[j]);
        }
        valid = u >= -1e-12 * scale;
      }
    if (valid)
    {
      state = local.state;
      return true;
    }
  }
  return false;
}
} // namespace

namespace
{
/**
 * The all-sticking solution of a cluster of several blocks (A9): every
 * block's contact closed and sticking, `W_SS r_S = -q_S` on its rows S (its
 * partners open, r = 0), by Cholesky. Exact when every normal impulse of S
 * pushes (or its row is bilateral), every tangential one is within its cone
 * and every partner separates, `u = W r + q >= 0` on its row: then `u = 0`
 * on S and the complementarity and Coulomb's law hold everywhere. Returns
 * false (r undefined) otherwise, or if W_SS is not positive definite.
 */
bool solve_all_sticking(const FrictionalCluster &cluster,
                        const std::vector<FrictionBlock> &blocks,
                        Vector<double> &r,
                        std::vector<FrictionState> &state)
{
  const FullMatrix<double> &W = cluster.W;
  const std::vector<unsigned int> &first = cluster.first;
  thread_local std::vector<unsigned int> rows;
  rows.clear();
  for (const FrictionBlock &block : blocks)
    for (unsigned int i = first[block.contact]; i < first[block.contact + 1]; ++i)
      rows.push_back(i);
  const unsigned int ns = rows.size();
  // per size (the clusters alternate between sizes; reinit() allocates)
  thread_local std::vector<LAPACKFullMatrix<double>> Ws_by_size;
  thread_local std::vector<Vector<double>> rs_by_size;
  if (Ws_by_size.size() <= ns)
  {
    Ws_by_size.resize(ns + 1);
    rs_by_size.resize(ns + 1);
  }
  LAPACKFullMatrix<double> &Ws = Ws_by_size[ns];
  Vector<double> &rs = rs_by_size[ns];
  if (Ws.m() != ns)
    Ws.reinit(ns, ns);
  // back to the state of a matrix (its last use left the Cholesky factor;
  // deal.II's Debug library asserts the state)
  Ws = 0.;
  if (rs.size() != ns)
    rs.reinit(ns);
  for (unsigned int i = 0; i < ns; ++i)
  {
    rs[i] = -cluster.q[rows[i]];
    for (unsigned int j = 0; j < ns; ++j)
      Ws(i, j) = W(rows[i], rows[j]);
  }
  Ws.set_property(LAPACKSupport::symmetric);
  try
  {
    Ws.compute_cholesky_factorization();
  }
  catch (const ExceptionBase &)
  {
    return false; // W_SS singular (dependent rows)
  }
  Ws.solve(rs);
  r = 0.;
  for (unsigned int i = 0; i < ns; ++i)
    r[rows[i]] = rs[i];
  for (const FrictionBlock &block : blocks)
  {
    const unsigned int k = block.contact, a = first[k];
    const double rn = r[a];
    if (!cluster.bilateral[k] && !(rn >= 0.))
      return false;
    double t2 = 0.;
    for (unsigned int i = a + 1; i < first[k + 1]; ++i)
      t2 += r[i] * r[i];
    if (std::sqrt(t2) > cluster.mu[k] * std::abs(rn))
      return false;
    state[k] = rn != 0. ? FrictionState::stick : FrictionState::open;
    for (const unsigned int f : block.partners)
    {
      if (cluster.bilateral[f])
        return false;
      double u = cluster.q[first[f]];
      for (unsigned int j = 0; j < ns; ++j)
        u += W(first[f], rows[j]) * rs[j];
      if (!(u >= 0.))
        return false;
      state[f] = FrictionState::open;
    }
  }
  return true;
}
} // namespace

FrictionSolverResult solve_frictional_cluster(const FrictionalCluster &cluster,
                                              Vector<double> &r,
                                              std::vector<FrictionState> &state,
                                              const FrictionSolverControl &control)
{
  const FullMatrix<double> &W = cluster.W;
  const Vector<double> &q = cluster.q;
  const std::vector<unsigned int> &first = cluster.first;
  const std::vector<double> &mu = cluster.mu;
  const std::vector<bool> &bilateral = cluster.bilateral;
  const unsigned int m = mu.size(), n = q.size();
  AssertDimension(first.size(), m + 1);
  AssertDimension(first[m], n);
  if (r.size() != n)
    r.reinit(n);
  else
    r = 0.;
  state.assign(m, FrictionState::open);
  FrictionSolverResult result;
  // work space reused from call to call (the solver runs every step)
  thread_local std::vector<FrictionBlock> blocks;
  friction_blocks(W, first, mu, blocks);
  // several blocks coupled through W (the wheels of one rigid body with
  // true heights): the sweeps converge slowly, so first the all-sticking
  // solution, exact when it is admissible (a braked crane's usual step)
  if (blocks.size() > 1)
  {
    if (solve_all_sticking(cluster, blocks, r, state))
    {
      result.sweeps = 1;
      return result;
    }
    r = 0.;
    state.assign(m, FrictionState::open);
  }
  double Wk[9], qk[3], rk[3];
  thread_local FullMatrix<double> Wb;
  thread_local std::vector<double> qb, rb;
  thread_local std::vector<unsigned int> rows_b, held;
  thread_local std::vector<bool> partner_bilateral;
  for (unsigned int sweep = 1;; ++sweep)
  {
    double change = 0., norm = 0.;
    bool exact_sweep = true;
    for (const FrictionBlock &block : blocks)
    {
      const unsigned int k = block.contact;
      const unsigned int a = first[k], size = first[k + 1] - a;
      AssertThrow(size >= 1 && size <= 3,
                  ExcMessage("friction solver: a contact has 0 or more than 2 tangents"));
      if (!block.partners.empty())
      {
        // the contact and its partners as one local problem (block_solve())
        rows_b.clear();
        held.clear();
        partner_bilateral.clear();
        for (unsigned int i = 0; i < size; ++i)
          rows_b.push_back(a + i);
        for (unsigned int i = 0; i < block.partners.size(); ++i)
        {
          rows_b.push_back(first[block.partners[i]]);
          held.push_back(block.parallel_to[i] - a);
          partner_bilateral.push_back(bilateral[block.partners[i]]);
        }
        const unsigned int nb = rows_b.size();
        Wb.reinit(nb, nb);
        qb.assign(nb, 0.);
        rb.assign(nb, 0.);
        for (unsigned int i = 0; i < nb; ++i)
        {
          double v = q[rows_b[i]];
          for (unsigned int j = 0; j < n; ++j)
            if (std::find(rows_b.begin(), rows_b.end(), j) == rows_b.end())
              v += W(rows_b[i], j) * r[j];
          qb[i] = v;
          for (unsigned int j = 0; j < nb; ++j)
            Wb(i, j) = W(rows_b[i], rows_b[j]);
        }
        FrictionState block_state = FrictionState::open;
        if (block_solve(Wb,
                        qb,
                        size,
                        held,
                        mu[k],
                        bilateral[k],
                        partner_bilateral,
                        rb,
                        block_state))
        {
          state[k] = block_state;
          for (unsigned int i = 0; i < block.partners.size(); ++i)
            state[block.partners[i]] =
                rb[size + i] != 0. ? FrictionState::slip : FrictionState::open;
          double d = 0., l = 0.;
          for (unsigned int i = 0; i < nb; ++i)
          {
            d += (rb[i] - r[rows_b[i]]) * (rb[i] - r[rows_b[i]]);
            l += rb[i] * rb[i];
            r[rows_b[i]] = rb[i];
          }
          change += std::sqrt(d);
          norm += std::sqrt(l);
          continue;
        }
        exact_sweep = false;
      }
      // each contact of the block on its own with the others' impulses as they are
      boost::container::static_vector<unsigned int, 3> members{k};
      members.insert(members.end(), block.partners.begin(), block.partners.end());
      for (const unsigned int c : members)
      {
        const unsigned int a = first[c], size = first[c + 1] - a;
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
        const LocalCoulombSolution local =
            solve_local_coulomb(Wk, size, qk, mu[c], bilateral[c], rk);
        state[c] = local.state;
        exact_sweep = exact_sweep && local.exact;
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
    }
    result.sweeps = sweep;
    result.converged = exact_sweep;
    if ((blocks.size() == 1 && (blocks[0].partners.empty() || exact_sweep)) ||
        change <= control.tolerance * norm)
      return result;
    if (sweep >= control.max_sweeps)
    {
      result.converged = false;
      return result;
    }
  }
}
} // namespace hati

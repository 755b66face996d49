// Unit test of the Coulomb friction solver (algorithms.md A9, doc/theory.md
// A9). References: the numpy prototype proto/cdl_friction.py of the spec
// (a point mass, W = I/m, each local problem exact in closed form):
//  (a) a mass on a slope stepped with CD-Lagrange: at rest to round-off at
//      10 deg with mu = 0.3; at 20 and 30 deg the speed after 1 s is
//      g (sin - mu cos) t exactly (the prototype prints it to six digits,
//      checked here to 1e-9 relative; the distance is the discrete sum
//      -a dt^2 N (N - 1) / 2);
//  (c) a wheel node with a frictional vertical contact (mu = 0.15) and a
//      frictionless lateral flange contact in one cluster: nonsmooth
//      Gauss-Seidel converges (the prototype: 13 sweeps at 1e-12), post
//      velocity (-0.27, 0, 0), saturated cone |lambda_t| = mu lambda_n,
//      flange impulse 500 N s.
// Then the law itself as an independent criterion on random anisotropic
// 3x3 and 2x2 blocks (Newton on the sliding angle), unilateral and
// bilateral: complementarity, cone, sticking u_t = 0 or sliding r_t
// opposite to u_t on the cone's boundary; and on random clusters of three
// coupled contacts (the all-sticking solution where admissible, the sweeps
// otherwise), the law at every contact with the others' impulses.
// Then a wheel joined to its axle by rigid links (true heights): the
// frictionless bilateral link rows condensed out (condensed_cluster.h)
// give the velocities of the plain sweeps over the whole cluster, the
// links' relative velocities zero to round-off and the wheel's law on its
// condensed problem, in one sweep; with a dependent link row (W_BB
// singular) too.
#include "test_tools.h"

#include <hati/contact/condensed_cluster.h>
#include <hati/contact/friction_solver.h>

#include <cmath>
#include <random>
#include <utility>

namespace hati_unit_friction_solver
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{
/** A vector of three components. */
struct V3
{
  V3(const double a = 0., const double b = 0., const double d = 0.) : c{a, b, d} {}
  double c[3];
  double &operator[](const int i) { return c[i]; }
  double operator[](const int i) const { return c[i]; }
};
double dot(const V3 &a, const V3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/** The prototype's slope(): returns {distance along t1, speed along t1}. */
std::pair<double, double> slope(const double theta, const double mu)
{
  const double dt = 1e-4, g = 9.81, m = 2.;
  const V3 n{-std::sin(theta), 0., std::cos(theta)},
      t1{std::cos(theta), 0., std::sin(theta)}, t2{0., 1., 0.};
  V3 x{0., 0., 0.}, v{0., 0., 0.};
  const double W[9] = {1. / m, 0., 0., 0., 1. / m, 0., 0., 0., 1. / m};
  for (int step = 0; step < 10000; ++step)
  {
    for (int i = 0; i < 3; ++i)
      x[i] += dt * v[i];
    V3 vfree = v;
    vfree[2] -= dt * g;
    const double q[3] = {dot(n, vfree), dot(t1, vfree), dot(t2, vfree)};
    double r[3];
    solve_local_coulomb(W, 3, q, mu, false, r);
    for (int i = 0; i < 3; ++i)
      v[i] = vfree[i] + (r[0] * n[i] + r[1] * t1[i] + r[2] * t2[i]) / m;
  }
  return {dot(x, t1), dot(v, t1)};
}

/** Check the law on one local problem; returns the largest violation (relative). */
double law_violation(const std::vector<double> &W,
                     const unsigned int size,
                     const double *q,
                     const double mu,
                     const bool bilateral,
                     const double *r,
                     const FrictionState state)
{
  double u[3] = {0., 0., 0.}, scale = 0.;
  for (unsigned int i = 0; i < size; ++i)
  {
    u[i] = q[i];
    for (unsigned int j = 0; j < size; ++j)
      u[i] += W[i * size + j] * r[j];
    scale = std::max(scale, std::abs(q[i]));
  }
  const double rt = std::hypot(r[1], size > 2 ? r[2] : 0.),
               ut = std::hypot(u[1], size > 2 ? u[2] : 0.);
  double v = 0.;
  if (!bilateral)
    v = std::max(
        {v, -r[0] / scale, -u[0] / scale, std::abs(r[0] * u[0]) / (scale * scale)});
  else
    v = std::max(v, std::abs(u[0]) / scale);
  v = std::max(v, (rt - mu * std::abs(r[0])) / std::max(scale, std::abs(r[0])));
  if (state == FrictionState::stick)
    v = std::max(v, ut / scale);
  if (state == FrictionState::slip)
  {
    // on the boundary of the cone, opposite to the sliding velocity
    v = std::max(v,
                 std::abs(rt - mu * std::abs(r[0])) / std::max(1e-300, std::abs(r[0])));
    for (unsigned int i = 1; i < size; ++i)
      v = std::max(v, std::abs(r[i] / std::max(1e-300, rt) + u[i] / ut));
  }
  return v;
}

/**
 * Clusters of three frictional contacts coupled through a random SPD
 * Delassus matrix (the wheels of one rigid body): the solver's result
 * must satisfy the law at every contact with the others' impulses (u = W r
 * + q over the whole cluster), whether it took the all-sticking solution
 * (one sweep, every contact sticking: u = 0 to round-off) or the sweeps.
 */
void coupled_clusters(std::mt19937 &gen)
{
  std::uniform_real_distribution<double> u(-1., 1.);
  const unsigned int m = 3, n = 3 * m;
  double worst = 0., worst_swept = 0., worst_stick = 0.;
  unsigned int all_sticking = 0, swept = 0;
  for (unsigned int trial = 0; trial < 400; ++trial)
  {
    FullMatrix<double> B(n, n), W(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        B(i, j) = u(gen);
    B.mTmult(W, B);
    // coupled, but less than each contact's own block (rigid bodies)
    W *= 0.3 / n;
    for (unsigned int i = 0; i < n; ++i)
      W(i, i) += 1.;
    Vector<double> q(n), r;
    for (unsigned int i = 0; i < n; ++i)
      // mostly pushing (q_n < 0) with small tangential velocities: many
      // clusters stick, the others slide or open
      q[i] = i % 3 == 0 ? -1. + 0.8 * u(gen) : 0.6 * u(gen);
    const std::vector<double> mu(m, 0.5);
    std::vector<FrictionState> state;
    const FrictionSolverResult result = solve_frictional_cluster(
        {W, q, {0, 3, 6, 9}, mu, {false, false, false}}, r, state);
    expect(result.converged, "coupled cluster: converged");
    Vector<double> v(n);
    W.vmult(v, r);
    v += q;
    bool sticking = true;
    for (unsigned int k = 0; k < m; ++k)
    {
      std::vector<double> Wk(9);
      double qk[3], rk[3];
      for (unsigned int i = 0; i < 3; ++i)
      {
        rk[i] = r[3 * k + i];
        for (unsigned int j = 0; j < 3; ++j)
          Wk[3 * i + j] = W(3 * k + i, 3 * k + j);
      }
      // the contact's local problem with the others' impulses as they are
      for (unsigned int i = 0; i < 3; ++i)
      {
        qk[i] = v[3 * k + i];
        for (unsigned int j = 0; j < 3; ++j)
          qk[i] -= Wk[3 * i + j] * rk[j];
      }
      worst = std::max(worst, law_violation(Wk, 3, qk, mu[k], false, rk, state[k]));
      sticking = sticking && state[k] == FrictionState::stick;
    }
    if (result.sweeps == 1 && sticking)
    {
      ++all_sticking;
      worst_stick = std::max(worst_stick, v.linfty_norm());
    }
    else
    {
      ++swept;
      worst_swept = std::max(worst_swept, worst);
    }
    worst = 0.;
  }
  std::cout << "     coupled clusters: " << all_sticking << " all sticking (one solve), "
            << swept << " by the sweeps" << std::endl;
  // the sweeps stop on the change of r (1e-10): their residual is larger
  // (measured 3.7e-10)
  check("coupled clusters, by the sweeps: largest violation of the law",
        worst_swept,
        0.,
        1e-8);
  check("coupled clusters, all sticking: largest |u| (m/s)", worst_stick, 0., 1e-12);
  expect(all_sticking > 50 && swept > 50, "coupled clusters: both paths taken");
}

/**
 * A wheel contact point (DoFs 6-8) joined by rigid links to an axle node
 * (translations 0-2, rotations 3-5) at the arm @p arm: three link rows
 * `u_p - u_a - theta x arm = 0` (frictionless, bilateral; a fourth,
 * dependent one if @p dependent), then the wheel's normal (z) and tangents
 * (x, y) on the contact point, random lumped masses and velocities:
 * W = L M^-1 L^T, q = L v. Condensed against the plain sweeps.
 */
void wheel_on_links(std::mt19937 &gen,
                    const bool dependent,
                    double &worst_velocity,
                    double &worst_link,
                    double &worst_law,
                    unsigned int &max_sweeps,
                    unsigned int &plain_sweeps_max)
{
  std::uniform_real_distribution<double> u(-1., 1.), pos(0.5, 2.);
  const unsigned int n_dofs = 9, n_links = dependent ? 4 : 3, n = n_links + 3;
  const double arm[3] = {0.3 * u(gen), 0.2 * u(gen), -0.5};
  FullMatrix<double> L(n, n_dofs);
  for (unsigned int d = 0; d < 3; ++d)
  {
    // u_p,d - u_a,d - (theta x arm)_d, (theta x arm) = (t1 a2 - t2 a1, ...)
    L(d, 6 + d) = 1.;
    L(d, d) = -1.;
    const unsigned int e = (d + 1) % 3, f = (d + 2) % 3;
    L(d, 3 + e) = -arm[f];
    L(d, 3 + f) = arm[e];
  }
  if (dependent)
    for (unsigned int j = 0; j < n_dofs; ++j)
      L(3, j) = L(0, j) + 0.5 * L(1, j);
  L(n_links, 8) = 1.;     // normal z
  L(n_links + 1, 6) = 1.; // tangent x
  L(n_links + 2, 7) = 1.; // tangent y
  Vector<double> minv(n_dofs), v(n_dofs);
  for (unsigned int j = 0; j < n_dofs; ++j)
  {
    minv[j] = 1. / pos(gen);
    v[j] = u(gen);
  }
  v[8] -= 1.5; // the wheel mostly pushes into its rail
  FullMatrix<double> W(n, n);
  Vector<double> q(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < n_dofs; ++k)
        W(i, j) += L(i, k) * minv[k] * L(j, k);
    for (unsigned int k = 0; k < n_dofs; ++k)
      q[i] += L(i, k) * v[k];
  }
  std::vector<unsigned int> first;
  for (unsigned int k = 0; k <= n_links; ++k)
    first.push_back(k);
  first.push_back(n);
  std::vector<double> mu(n_links, 0.);
  mu.push_back(0.3);
  std::vector<bool> bilateral(n_links, true);
  bilateral.push_back(false);
  Vector<double> r_c, r_p, u_c(n), u_p(n);
  std::vector<FrictionState> s_c, s_p;
  const FrictionSolverResult condensed =
      solve_condensed_frictional_cluster({W, q, first, mu, bilateral}, r_c, s_c);
  FrictionSolverControl tight;
  tight.tolerance = 1e-14;
  tight.max_sweeps = 100000;
  const FrictionSolverResult plain =
      solve_frictional_cluster({W, q, first, mu, bilateral}, r_p, s_p, tight);
  W.vmult(u_c, r_c);
  u_c += q;
  W.vmult(u_p, r_p);
  u_p += q;
  const double scale = q.linfty_norm();
  for (unsigned int i = 0; i < n; ++i)
    worst_velocity = std::max(worst_velocity, std::abs(u_c[i] - u_p[i]) / scale);
  for (unsigned int i = 0; i < n_links; ++i)
    worst_link = std::max(worst_link, std::abs(u_c[i]) / scale);
  // the wheel's law with the links' impulses as they are
  std::vector<double> Wk(9);
  double qk[3], rk[3];
  for (unsigned int i = 0; i < 3; ++i)
  {
    rk[i] = r_c[n_links + i];
    qk[i] = u_c[n_links + i];
    for (unsigned int j = 0; j < 3; ++j)
    {
      Wk[3 * i + j] = W(n_links + i, n_links + j);
      qk[i] -= Wk[3 * i + j] * r_c[n_links + j];
    }
  }
  // (in the whole cluster's terms the wheel's local problem is coupled to
  // the links: the law is checked on its velocities u = W r + q)
  const double ut = std::hypot(u_c[n_links + 1], u_c[n_links + 2]),
               rt = std::hypot(rk[1], rk[2]);
  double law = std::max({-rk[0] / scale,
                         -u_c[n_links] / scale,
                         std::abs(rk[0] * u_c[n_links]) / (scale * scale),
                         (rt - 0.3 * rk[0]) / std::max(scale, rk[0])});
  if (s_c[n_links] == FrictionState::stick)
    law = std::max(law, ut / scale);
  if (s_c[n_links] == FrictionState::slip && ut > 0.)
    for (unsigned int t = 1; t <= 2; ++t)
      law = std::max(law, std::abs(rk[t] / std::max(1e-300, rt) + u_c[n_links + t] / ut));
  worst_law = std::max(worst_law, law);
  expect(condensed.converged && plain.converged, "wheel on links: both converged");
  max_sweeps = std::max(max_sweeps, condensed.sweeps);
  plain_sweeps_max = std::max(plain_sweeps_max, plain.sweeps);
}

void condensed_links(std::mt19937 &gen)
{
  for (const bool dependent : {false, true})
  {
    double worst_velocity = 0., worst_link = 0., worst_law = 0.;
    unsigned int sweeps = 0, plain_sweeps = 0;
    for (unsigned int trial = 0; trial < 200; ++trial)
      wheel_on_links(
          gen, dependent, worst_velocity, worst_link, worst_law, sweeps, plain_sweeps);
    const std::string what =
        dependent ? "wheel on links, a dependent link: " : "wheel on links: ";
    std::cout << "     " << what << "condensed " << sweeps
              << " sweep(s), the plain sweeps up to " << plain_sweeps << std::endl;
    // the plain sweeps stop at 1e-14 of the change of r: the velocities
    // agree to that order
    check(what + "velocities, condensed vs the plain sweeps (of |q|)",
          worst_velocity,
          0.,
          1e-9);
    check(what + "links' relative velocities (of |q|)", worst_link, 0., 1e-12);
    check(what + "the wheel's law (complementarity, cone, slip opposite)",
          worst_law,
          0.,
          1e-10);
    expect(sweeps == 1, what + "one sweep condensed");
  }
}
} // namespace

HATI_UNIT_TEST(friction_solver)
{
  // (a) the slope
  const double g = 9.81;
  for (const double deg : {10., 20., 30.})
  {
    const double theta = deg * std::acos(-1.) / 180., mu = 0.3;
    const auto [s, v] = slope(theta, mu);
    const double a = std::max(0., g * (std::sin(theta) - mu * std::cos(theta)));
    const std::string where = "slope " + std::to_string(int(deg)) + " deg, mu 0.3: ";
    if (a == 0.)
    {
      check(where + "distance after 1 s (at rest to round-off)", s, 0., 1e-14);
      check(where + "speed after 1 s", v, 0., 1e-14);
    }
    else
    {
      check(where + "speed after 1 s vs -g (sin - mu cos) t", v, -a, 1e-9 * a);
      check(where + "distance vs the discrete -a dt^2 N (N-1)/2",
            s,
            -a * 1e-8 * 10000. * 9999. / 2.,
            1e-9 * a);
    }
  }

  // (c) the wheel cluster: rows n0 = ez, t01 = ex, t02 = ey | n1 = ey
  {
    const double m = 1000., mu = 0.15;
    const V3 vfree{-0.3, -0.5, -0.2};
    FullMatrix<double> W(4, 4);
    const V3 rows[4] = {{0., 0., 1.}, {1., 0., 0.}, {0., 1., 0.}, {0., 1., 0.}};
    Vector<double> q(4);
    for (unsigned int a = 0; a < 4; ++a)
    {
      q[a] = dot(rows[a], vfree);
      for (unsigned int b = 0; b < 4; ++b)
        W(a, b) = dot(rows[a], rows[b]) / m;
    }
    Vector<double> r;
    std::vector<FrictionState> state;
    const FrictionSolverResult result =
        solve_frictional_cluster({W, q, {0, 3, 4}, {mu, 0.}, {false, false}}, r, state);
    V3 v = vfree;
    for (unsigned int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i)
        v[i] += rows[a][i] * r[a] / m;
    std::cout << "     wheel cluster: " << result.sweeps
              << " Gauss-Seidel sweeps at the relative tolerance 1e-10" << std::endl;
    expect(result.converged && result.sweeps <= 13,
           "wheel cluster converged within the prototype's 13 sweeps");
    check("wheel cluster: post velocity x", v[0], -0.27, 1e-12);
    check("wheel cluster: post velocity y", v[1], 0., 1e-12);
    check("wheel cluster: post velocity z", v[2], 0., 1e-12);
    check("wheel cluster: |lambda_t| / (mu lambda_n) (saturated cone)",
          std::hypot(r[1], r[2]) / (mu * r[0]),
          1.,
          1e-10);
    check("wheel cluster: flange impulse (N s)", r[3], 500., 1e-7);
    expect(state[0] == FrictionState::slip, "wheel cluster: the wheel contact slides");
  }

  // (d) a cluster captured from the default crane (Travel = braked, Hoist =
  // rope) under HATI, which Gauss-Seidel did not converge in 1000 sweeps:
  // a braked wheel (normal z, tangents x, y, mu = 0.15) and its lateral
  // flange contact, whose row equals the wheel's y tangent (W singular).
  // Independent solution (closed form, W = w I on the wheel node): the
  // flange holds y (u_y = 0, flange impulse -q_y / w), the wheel's normal
  // impulse is -q_n / w and its sticking x impulse -q_x / w lies just
  // outside the cone, so the wheel slides along x with r_x = mu r_n and
  // u_x = q_x + w mu r_n (the post velocities are unique although the split
  // of the y impulse between the two rows would not be when sticking).
  {
    const double w = 0.034392153086351761, mu = 0.15;
    const double qv[4] = {-0.13590225207076351,
                          -0.020389218466158335,
                          -0.014489508722631252,
                          -0.014489508722631252};
    FullMatrix<double> W(4, 4);
    Vector<double> q(4);
    for (unsigned int a = 0; a < 4; ++a)
    {
      q[a] = qv[a];
      W(a, a) = w;
    }
    W(2, 3) = W(3, 2) = w;
    Vector<double> r;
    std::vector<FrictionState> state;
    const FrictionSolverResult result =
        solve_frictional_cluster({W, q, {0, 3, 4}, {mu, 0.}, {false, false}}, r, state);
    std::cout << "     crane wheel cluster: " << result.sweeps << " sweeps" << std::endl;
    expect(result.converged && result.sweeps <= 2,
           "crane wheel cluster converged (wheel and flange solved as one block)");
    Vector<double> u(q);
    W.vmult_add(u, r);
    const double rn = -qv[0] / w, scale = std::abs(qv[0]);
    check("crane wheel cluster: u_n", u[0], 0., 1e-10 * scale);
    check("crane wheel cluster: u_y (flange closed)", u[3], 0., 1e-10 * scale);
    check("crane wheel cluster: u_x (slides) vs q_x + w mu r_n",
          u[1],
          qv[1] + w * mu * rn,
          1e-10 * scale);
    check("crane wheel cluster: wheel normal impulse", r[0], rn, 1e-10 * rn);
    check("crane wheel cluster: friction impulse x = mu r_n (cone saturated)",
          r[1],
          mu * rn,
          1e-10 * rn);
    check("crane wheel cluster: cone |r_t| <= mu r_n",
          std::max(0., std::hypot(r[1], r[2]) - mu * r[0]),
          0.,
          1e-10 * rn);
    check("crane wheel cluster: y impulse (wheel + flange) vs -q_y / w",
          r[2] + r[3],
          -qv[2] / w,
          1e-10 * rn);
    expect(r[3] >= 0. && state[0] == FrictionState::slip,
           "crane wheel cluster: flange impulse >= 0, the wheel slides");
  }

  // (e) a single wheel captured from the explicit crane run: the sticking
  // impulse lies outside the cone by 1.7e-6 relative (isotropic block, the
  // sliding solution r_t = -mu r_n q_t / |q_t| in closed form)
  {
    const double w = 0.010318212498128854, mu = 0.15;
    const double q[3] = {
        -0.01188005420057503, 0.0012661056043010554, -0.0012540095949597056};
    const double W[9] = {w, 0., 0., 0., w, 0., 0., 0., w};
    double r[3];
    const LocalCoulombSolution local = solve_local_coulomb(W, 3, q, mu, false, r);
    const bool exact = local.exact;
    const FrictionState s = local.state;
    const double rn = -q[0] / w, qt = std::hypot(q[1], q[2]);
    expect(exact && s == FrictionState::slip, "near-cone wheel: solved exactly, slides");
    check("near-cone wheel: r_n", r[0], rn, 1e-12 * rn);
    check("near-cone wheel: r_t1", r[1], -mu * rn * q[1] / qt, 1e-12 * rn);
    check("near-cone wheel: r_t2", r[2], -mu * rn * q[2] / qt, 1e-12 * rn);
  }

  // the law on random anisotropic blocks (Newton on the sliding angle)
  std::mt19937 gen(17);
  std::uniform_real_distribution<double> u(-1., 1.);
  double worst = 0.;
  unsigned int n_states[3] = {0, 0, 0}, n_inexact = 0;
  for (unsigned int trial = 0; trial < 4000; ++trial)
  {
    const unsigned int size = 2 + trial % 2;
    const bool bilateral = trial % 5 == 0;
    std::vector<double> B(size * size), W(size * size, 0.);
    for (auto &b : B)
      b = u(gen);
    for (unsigned int i = 0; i < size; ++i)
      for (unsigned int j = 0; j < size; ++j)
      {
        for (unsigned int k = 0; k < size; ++k)
          W[i * size + j] += B[i * size + k] * B[j * size + k];
        W[i * size + j] += (i == j ? 0.5 : 0.);
      }
    double q[3] = {u(gen), u(gen), u(gen)}, r[3];
    const double mu = 0.05 + 0.6 * (u(gen) + 1.) / 2.;
    const LocalCoulombSolution local =
        solve_local_coulomb(W.data(), size, q, mu, bilateral, r);
    const bool exact = local.exact;
    const FrictionState s = local.state;
    n_inexact += exact ? 0 : 1;
    ++n_states[static_cast<int>(s)];
    if (exact)
      worst = std::max(worst, law_violation(W, size, q, mu, bilateral, r, s));
  }
  std::cout << "     random blocks: " << n_states[0] << " open, " << n_states[1]
            << " stick, " << n_states[2] << " slip, " << n_inexact
            << " without an exact solution" << std::endl;
  check("random anisotropic blocks: largest violation of the law", worst, 0., 1e-10);
  expect(n_inexact == 0, "random anisotropic blocks: every local problem solved exactly");
  expect(n_states[1] > 100 && n_states[2] > 100,
         "random blocks: both stick and slip seen");
  coupled_clusters(gen);
  condensed_links(gen);
  return finish();
}
} // namespace hati_unit_friction_solver

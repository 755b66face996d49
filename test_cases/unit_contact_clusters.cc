// Unit test of the contact clusters of CD-Lagrange (algorithms.md A4-A6,
// doc/theory.md 1.2): active contacts that share a free DoF are solved as one
// LCP with the Delassus matrix L M^-1 L^T. DiscreteSystem objects built by
// hand:
//  (A) a point mass (3 DoFs) thrown into a V-shaped groove of two planes
//      with non-orthogonal normals n1, n2 (n1 . n2 = cos 2 alpha = 1/2), the
//      groove turned in space so that both rows act on the 3 DoFs, the second
//      row scaled by 2.5 (a gap need not be normalised): with e = 0 both
//      contacts push and the velocity after the impact is the projection of
//      v0 on the edge t = n1 x n2 / |n1 x n2|, (v0 . t) t; with e = 0.5 it is
//      (v0 . t) t - e (v0 - (v0 . t) t);
//  (B) the same groove with a velocity that leaves plane 2 once plane 1 has
//      pushed: the exact answer is the projection on plane 1,
//      v0 - (1 + e) (n1 . v0) n1, with no impulse on plane 2 although its gap
//      is negative; e = 0 and e = 0.5;
//  (E) the impacts of (A) and (B) under gravity with e = 0.5: the velocity
//      after the impact is P(V_free + e V_{n+1/2}) - e V_{n+1/2}, with P the
//      projection on the cone {n1 . x >= 0, n2 . x >= 0} computed by geometry;
//  (C) the mass resting in the groove under gravity with a component along
//      the edge: each step both contacts carry the impulse
//      m g_n dt / (2 cos alpha) (statics of a wedge) and the mass slides along
//      the edge with the acceleration g . t;
//  (D) three masses on a line pushed against a wall (contacts wall-A, A-B,
//      B-C: the first and the last share no DoF, they are in one cluster
//      through A-B): with e = 0 all stop, impulses (mA + mB + mC) v,
//      (mB + mC) v, mC v (momentum balance of each sub-chain).
//  (F) the Delassus matrix of rows of random lengths (1 to 300 entries, some
//      DoFs repeated within a row, long rows that share DoFs like the rows of
//      a tie) equals bitwise the double loop over the entries of each pair
//      of rows (terms added by position in row a, then in row b).
// In (A)-(E) the answer of per-contact closed forms lambda_k = max(0,
// -q_k / W_kk) (contacts treated independently) is computed and shown to
// differ from the exact one, so that the test checks the coupling. Every
// check prints value, reference and tolerance; returns non-zero on failure.
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include "test_tools.h"

#include <hati/base/mpi_environment.h>
#include <hati/model/discrete_system.h>
#include <hati/time/cd_lagrange.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace hati_unit_contact_clusters
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{

using Vec = Tensor<1, 3>;

/** The rotation R = Rz(35 deg) Rx(20 deg) that turns the groove in space. */
Vec rotate(const Vec &x)
{
  const double a = 20. * M_PI / 180., b = 35. * M_PI / 180.;
  const Vec y({x[0],
               std::cos(a) * x[1] - std::sin(a) * x[2],
               std::sin(a) * x[1] + std::cos(a) * x[2]});
  return Vec({std::cos(b) * y[0] - std::sin(b) * y[1],
              std::sin(b) * y[0] + std::cos(b) * y[1],
              y[2]});
}

/**
 * The groove: planes through the origin with inward normals n1, n2 at
 * +-alpha from the local z axis, turned by rotate(); the local y axis is the
 * edge. Row k of the contact operator is scale_k n_k on DoFs 0, 1, 2.
 */
struct Groove
{
  static constexpr double alpha = M_PI / 6.; // n1 . n2 = cos 2 alpha = 1/2
  static constexpr double m = 2.;            // kg
  const double scale[2] = {1., 2.5};
  Vec n[2], edge, up;

  Groove()
  {
    n[0] = rotate(Vec({std::sin(alpha), 0., std::cos(alpha)}));
    n[1] = rotate(Vec({-std::sin(alpha), 0., std::cos(alpha)}));
    edge = rotate(Vec({0., 1., 0.}));
    up = rotate(Vec({0., 0., 1.}));
  }

  /** A point mass at the bottom of the groove (gaps 0), velocity v0. */
  void build(DiscreteSystem &s, const Vec &v0, const double e) const
  {
    s.reinit(3);
    for (unsigned int d = 0; d < 3; ++d)
    {
      s.lumped_mass[d] = m;
      s.initial_velocity[d] = v0[d];
    }
    for (unsigned int k = 0; k < 2; ++k)
    {
      ContactRow c;
      c.name = k == 0 ? "plane1" : "plane2";
      c.dofs = {0, 1, 2};
      c.coefficients = {scale[k] * n[k][0], scale[k] * n[k][1], scale[k] * n[k][2]};
      c.restitution = e;
      s.contacts.push_back(c);
    }
  }
};

Vec velocity_of(const CDLagrange &cd)
{
  return Vec({cd.velocity()[0], cd.velocity()[1], cd.velocity()[2]});
}

/**
 * The velocity after one impact if each contact took its own closed form
 * lambda_k = max(0, -q_k / W_kk), q_k = L_k (v_free + e v_half), applied
 * together (no coupling); rows n_k of unit length, equal masses m.
 */
Vec independent_answer(const Groove &g,
                       const Vec &v_half,
                       const Vec &v_free,
                       const double e)
{
  Vec v = v_free;
  for (unsigned int k = 0; k < 2; ++k)
    v += std::max(0., -(g.n[k] * (v_free + e * v_half))) * g.n[k];
  return v;
}

/**
 * The Euclidean projection of @p y on the cone {n1 . x >= 0, n2 . x >= 0}
 * of the groove, by geometry: y itself if inside, else the projection on a
 * face if it lies on the other face's side (its multiplier -n_k . y is then
 * positive), else the projection on the edge (the unique point satisfying
 * the optimality conditions when no other candidate does).
 */
Vec project_on_groove(const Groove &g, const Vec &y)
{
  if (g.n[0] * y >= 0. && g.n[1] * y >= 0.)
    return y;
  for (unsigned int k = 0; k < 2; ++k)
  {
    const Vec p = y - (g.n[k] * y) * g.n[k];
    if (g.n[k] * y < 0. && g.n[1 - k] * p >= 0.)
      return p;
  }
  const Vec t =
      cross_product_3d(g.n[0], g.n[1]) / cross_product_3d(g.n[0], g.n[1]).norm();
  return (y * t) * t;
}

/** N1, N2 with m dv = N1 n1 + N2 n2 (c = n1 . n2, Gram matrix inverted by hand). */
void normal_impulses(const Groove &g, const Vec &dv, double N[2])
{
  const Vec d = g.m * dv;
  const double c = g.n[0] * g.n[1];
  N[0] = (d * g.n[0] - c * (d * g.n[1])) / (1. - c * c);
  N[1] = (d * g.n[1] - c * (d * g.n[0])) / (1. - c * c);
}

/**
 * Checks after the impact step of a groove case: velocity and impulses
 * against the analytical ones, w_k = L_k (V + e V_{n+1/2}) >= 0 (Newton's
 * law, A5), complementarity, and that the independent answer differs.
 * @p v_half is V_{n+1/2} before the impact, @p v_free the free velocity.
 */
void check_groove_impact(const std::string &label,
                         const Groove &g,
                         const CDLagrange &cd,
                         const Vec &v_half,
                         const Vec &v_free,
                         const double e,
                         const Vec &v_exact,
                         const double N_exact[2])
{
  const Vec v = velocity_of(cd);
  const double v_scale = v_half.norm();
  expect(cd.active()[0] && cd.active()[1], label + ": both contacts active (gaps < 0)");
  // round-off: 1e-12 of |V_{n+1/2}|
  check(label + ": |V - V_exact| (m/s)", (v - v_exact).norm(), 0., 1e-12 * v_scale);
  for (unsigned int k = 0; k < 2; ++k)
  {
    const std::string ck = label + ": contact " + std::to_string(k + 1);
    // the impulse of row k = scale_k n_k is the physical normal impulse N_k
    // divided by scale_k; 1e-12 relative to m |V_{n+1/2}|
    check(ck + " impulse * row scale (N s)",
          cd.impulses()[k] * g.scale[k],
          N_exact[k],
          1e-12 * g.m * v_scale);
    // Newton's law at the velocity level: w_k = L_k V + e L_k V_{n+1/2} >= 0
    const double w = cd.normal_velocities()[k] + e * g.scale[k] * (g.n[k] * v_half);
    std::ostringstream what;
    what << ck << ": w = L V + e L V_{n+1/2} = " << w << " m/s >= -1e-12 |V_{n+1/2}|";
    expect(w >= -1e-12 * v_scale, what.str());
    if (cd.impulses()[k] > 0.)
      check(ck + ": lambda > 0, complementary w (m/s)", w, 0., 1e-12 * v_scale);
  }
  const Vec v_independent = independent_answer(g, v_half, v_free, e);
  std::cout << "     independent closed forms would give |V_indep - V_exact| = "
            << (v_independent - v_exact).norm() << " m/s" << std::endl;
  expect((v_independent - v_exact).norm() > 0.1 * v_scale,
         label + ": contacts treated independently give another answer (> 0.1 |v0|)");
}

// (A) both contacts push: projection on the edge
void test_edge()
{
  std::cout << "--- (A) point mass into a groove, both contacts push" << std::endl;
  const Groove g;
  // local (0.3, 0.7, -2): n1 . v0 = -1.58, n2 . v0 = -1.88 m/s
  const Vec v0 = rotate(Vec({0.3, 0.7, -2.}));
  for (const double e : {0., 0.5})
  {
    DiscreteSystem s;
    g.build(s, v0, e);
    CDLagrange cd(s, 1e-3, 1.);
    cd.step();
    // analytical: the normal part of v0 (in span(n1, n2)) is reversed times e
    const Vec t =
        cross_product_3d(g.n[0], g.n[1]) / cross_product_3d(g.n[0], g.n[1]).norm();
    const Vec tangential = (v0 * t) * t;
    const Vec v_exact = tangential - e * (v0 - tangential);
    // impulses: m (v_exact - v0) = N1 n1 + N2 n2, with c = n1 . n2:
    // N1 = (d.n1 - c d.n2) / (1 - c^2), N2 = (d.n2 - c d.n1) / (1 - c^2)
    check("(A) n1 . n2", g.n[0] * g.n[1], 0.5, 1e-15);
    double N[2];
    normal_impulses(g, v_exact - v0, N);
    expect(N[0] > 0. && N[1] > 0., "(A) the analytical impulses are both positive");
    check_groove_impact(
        "(A) e = " + std::to_string(e).substr(0, 3), g, cd, v0, v0, e, v_exact, N);
    // e = 0: the mass then slides along the edge, gaps constant, no impulse
    if (e == 0.)
    {
      for (unsigned int i = 0; i < 10; ++i)
        cd.step();
      check("(A) e = 0: |V - (v0 . t) t| after 10 more steps (m/s)",
            (velocity_of(cd) - tangential).norm(),
            0.,
            1e-12 * v0.norm());
    }
  }
}

// (B) plane 1 pushes, the velocity leaves plane 2: lambda_2 = 0
void test_face()
{
  std::cout << "--- (B) point mass into a groove, only plane 1 pushes" << std::endl;
  const Groove g;
  // local (-1.5, 0.4, -1.25 / cos alpha): n1 . v0 = -2, n2 . v0 = -0.5 m/s,
  // both gaps become negative; after plane 1 pushes, n2 . v = -0.5 + (1 + e)
  // 2 (n1 . n2) = 0.5 (e = 0) or 1 (e = 0.5) > 0
  const Vec v0 = rotate(Vec({-1.5, 0.4, -1.25 / std::cos(Groove::alpha)}));
  check("(B) n1 . v0 (m/s)", g.n[0] * v0, -2., 1e-14);
  check("(B) n2 . v0 (m/s)", g.n[1] * v0, -0.5, 1e-14);
  for (const double e : {0., 0.5})
  {
    DiscreteSystem s;
    g.build(s, v0, e);
    CDLagrange cd(s, 1e-3, 1.);
    cd.step();
    const Vec v_exact = v0 - (1. + e) * (g.n[0] * v0) * g.n[0];
    const double N[2] = {-(1. + e) * g.m * (g.n[0] * v0), 0.};
    const std::string label = "(B) e = " + std::to_string(e).substr(0, 3);
    expect(g.n[1] * v_exact > 0., label + ": the exact velocity leaves plane 2");
    check_groove_impact(label, g, cd, v0, v0, e, v_exact, N);
    // exactly zero impulse on plane 2 (an active contact that does not push)
    check(label + ": impulse of plane 2 (N s)", cd.impulses()[1], 0., 0.);
  }
}

// (E) the impacts of (A) and (B) under gravity, e = 0.5: V_free differs from
// V_{n+1/2}
void test_gravity_impact()
{
  std::cout << "--- (E) point mass into the groove under gravity, e = 0.5" << std::endl;
  const Groove g;
  const double e = 0.5, dt = 1e-2;
  const Vec gravity = rotate(Vec({1., -2., -9.81}));
  for (const Vec &v0 : {rotate(Vec({0.3, 0.7, -2.})),
                        rotate(Vec({-1.5, 0.4, -1.25 / std::cos(Groove::alpha)}))})
  {
    DiscreteSystem s;
    g.build(s, v0, e);
    for (unsigned int d = 0; d < 3; ++d)
      s.constant_force[d] = g.m * gravity[d];
    CDLagrange cd(s, dt, 1.);
    cd.step();
    // V_{1/2} = v0 + dt/2 g, V_free = V_{1/2} + dt g; with
    // X = V + e V_{1/2}, Newton's law is 0 <= L X _|_ lambda >= 0 and
    // X = V_free + e V_{1/2} + L^T lambda / m: X is the projection of
    // V_free + e V_{1/2} on the cone (equal masses)
    const Vec v_half = v0 + 0.5 * dt * gravity, v_free = v_half + dt * gravity;
    const Vec v_exact = project_on_groove(g, v_free + e * v_half) - e * v_half;
    double N[2];
    normal_impulses(g, v_exact - v_free, N);
    std::ostringstream label;
    label << "(E) n . v0 = " << g.n[0] * v0 << ", " << g.n[1] * v0;
    check_groove_impact(label.str(), g, cd, v_half, v_free, e, v_exact, N);
  }
}

// (C) resting in the groove under gravity, sliding along the edge
void test_rest()
{
  std::cout << "--- (C) point mass resting in the groove under gravity" << std::endl;
  const Groove g;
  const double gn = 9.81, gt = 1.2, dt = 1e-3, s0 = 0.3;
  const Vec gravity = -gn * g.up + gt * g.edge;
  DiscreteSystem s;
  g.build(s, s0 * g.edge, 0.);
  for (unsigned int d = 0; d < 3; ++d)
    s.constant_force[d] = g.m * gravity[d];
  CDLagrange cd(s, dt, 1.);
  cd.step(); // the first step also removes the half step of V_{1/2}
  double error_lambda = 0., error_v = 0., max_rate = 0.;
  // N n1 + N n2 = m gn dt up, n_k . up = cos alpha: N = m gn dt / (2 cos alpha)
  const double N = g.m * gn * dt / (2. * std::cos(Groove::alpha));
  for (unsigned int i = 0; i < 200; ++i)
  {
    cd.step();
    for (unsigned int k = 0; k < 2; ++k)
    {
      error_lambda = std::max(error_lambda, std::abs(cd.impulses()[k] * g.scale[k] - N));
      max_rate = std::max(max_rate, std::abs(cd.normal_velocities()[k]));
    }
    // V_{n+1/2} = (s0 + gt t_{n+1/2}) edge: sliding without friction
    const Vec v_exact = (s0 + gt * (cd.time() + 0.5 * dt)) * g.edge;
    error_v = std::max(error_v, (velocity_of(cd) - v_exact).norm());
  }
  // round-off: 1e-12 relative
  check("(C) max |lambda_k scale_k - m gn dt / (2 cos alpha)| (N s)",
        error_lambda,
        0.,
        1e-12 * N);
  check("(C) max |L_k V| at rest in the groove (m/s)", max_rate, 0., 1e-12);
  check("(C) max |V - (s0 + gt t) edge| (m/s)", error_v, 0., 1e-12);
  // independent closed forms: lambda_k = m gn dt (n_k . up) each, which
  // leaves a normal velocity gn dt cos(2 alpha) = 4.9e-3 m/s
  Vec v_free = -gn * dt * g.up; // the normal part of V_free
  const Vec v_independent = v_free + gn * dt * (g.n[0] * g.up) * (g.n[0] + g.n[1]);
  std::cout << "     independent closed forms would leave |V_n| = "
            << v_independent.norm() << " m/s" << std::endl;
  expect(v_independent.norm() > 0.1 * gn * dt,
         "(C) contacts treated independently give another answer (> 0.1 gn dt)");
}

// (D) three masses against a wall: a cluster through a common neighbour
void test_line()
{
  std::cout << "--- (D) three masses against a wall: transitive cluster" << std::endl;
  const double mA = 1., mB = 2., mC = 3., v = 1.5;
  DiscreteSystem s;
  s.reinit(3);
  s.lumped_mass[0] = mA;
  s.lumped_mass[1] = mB;
  s.lumped_mass[2] = mC;
  for (unsigned int d = 0; d < 3; ++d)
    s.initial_velocity[d] = -v;
  // gaps: wall-A u0, A-B u1 - u0, B-C u2 - u1, all touching at t = 0
  const std::vector<std::vector<types::global_dof_index>> dofs{{0}, {0, 1}, {1, 2}};
  const std::vector<std::vector<double>> coefficients{{1.}, {-1., 1.}, {-1., 1.}};
  for (unsigned int k = 0; k < 3; ++k)
  {
    ContactRow c;
    c.name = "c" + std::to_string(k);
    c.dofs = dofs[k];
    c.coefficients = coefficients[k];
    s.contacts.push_back(c);
  }
  CDLagrange cd(s, 1e-3, 1.);
  cd.step();
  for (unsigned int d = 0; d < 3; ++d)
    check("(D) velocity of mass " + std::to_string(d) + " after the impact (m/s)",
          cd.velocity()[d],
          0.,
          1e-12 * v);
  // momentum balance of the sub-chains {A, B, C}, {B, C}, {C}: 1e-12 relative
  const double lambda[3] = {(mA + mB + mC) * v, (mB + mC) * v, mC * v};
  for (unsigned int k = 0; k < 3; ++k)
    check("(D) impulse of contact " + std::to_string(k) + " (N s)",
          cd.impulses()[k],
          lambda[k],
          1e-12 * lambda[k]);
  // independent closed forms: only the wall pushes (q = 0 on the others), A
  // stops, B and C go on at -v into A
  const double vB_independent = -v;
  std::cout << "     independent closed forms would leave mass B at " << vB_independent
            << " m/s" << std::endl;
  expect(std::abs(vB_independent - cd.velocity()[1]) > 0.1 * v,
         "(D) contacts treated independently give another answer");
}

/** W_ab as the double loop over the entries of rows a and b (the reference). */
double delassus_entry(const SparseRow &a, const SparseRow &b, const Vector<double> &minv)
{
  double w = 0.;
  for (unsigned int i = 0; i < a.dofs.size(); ++i)
    for (unsigned int j = 0; j < b.dofs.size(); ++j)
      if (a.dofs[i] == b.dofs[j])
        w += a.coefficients[i] * b.coefficients[j] * minv[a.dofs[i]];
  return w;
}

void test_delassus_order()
{
  const unsigned int n_dofs = 400;
  Vector<double> minv(n_dofs);
  unsigned int seed = 12345;
  auto next = [&]() { return seed = 1103515245u * seed + 12345u; };
  auto uniform = [&]() { return double(next() % 1000001) / 1000000. - 0.5; };
  for (unsigned int d = 0; d < n_dofs; ++d)
    minv[d] = (d % 17 == 0) ? 0. : 1. + uniform();
  const std::vector<unsigned int> lengths = {1, 3, 8, 9, 40, 150, 300, 300, 2, 120, 77};
  std::vector<SparseRow> rows(lengths.size());
  for (unsigned int r = 0; r < rows.size(); ++r)
    for (unsigned int i = 0; i < lengths[r]; ++i)
    {
      // a narrow DoF range for some rows: many shared and repeated DoFs
      const unsigned int range = (r % 3 == 0) ? 50 : n_dofs;
      rows[r].dofs.push_back(next() % range);
      rows[r].coefficients.push_back(uniform() * std::pow(10., int(next() % 7) - 3));
    }
  std::vector<const SparseRow *> pointers;
  for (const auto &r : rows)
    pointers.push_back(&r);
  const FullMatrix<double> W = delassus(pointers, minv);
  unsigned int n_differ = 0;
  for (unsigned int a = 0; a < rows.size(); ++a)
    for (unsigned int b = 0; b < rows.size(); ++b)
    {
      const double w = delassus_entry(rows[a], rows[b], minv);
      n_differ += (std::memcmp(&w, &W(a, b), sizeof(double)) != 0) ? 1 : 0;
    }
  check("(F) Delassus entries not bitwise the double loop's", n_differ, 0., 0.);
}
} // namespace

HATI_UNIT_TEST(contact_clusters)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
  {
    test_edge();
    test_face();
    test_gravity_impact();
    test_rest();
    test_line();
    test_delassus_order();
  }
  catch (const std::exception &e)
  {
    std::cout << "FAIL exception: " << e.what() << std::endl;
    return 1;
  }
  return finish();
}
} // namespace hati_unit_contact_clusters

// Unit test of the contact LCP solver (algorithms.md A5): closed form for one
// contact, exact enumeration for coupled clusters, projected Gauss-Seidel for
// large ones. Every solution is checked against the complementarity
// conditions themselves (lambda >= 0, w = W lambda + q >= 0, lambda.w = 0),
// an independent criterion, and the enumeration against PGS on the same
// problems; the prescribed active set's equalities with dependent rows; a
// cluster's equalities eliminated against PGS.
// Returns non-zero on failure.
#include <deal.II/base/exceptions.h>

#include "test_tools.h"

#include <hati/contact/lcp_solver.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

namespace hati_unit_lcp_solver
{

using namespace dealii;
using namespace hati_test;

namespace
{

/** Largest violation of the complementarity conditions, relative to |q|. */
double
violation(const FullMatrix<double> &W, const Vector<double> &q, const Vector<double> &l)
{
  Vector<double> w(q);
  W.vmult_add(w, l);
  double v = 0.;
  for (unsigned int i = 0; i < q.size(); ++i)
    v = std::max({v, -l[i], -w[i], std::abs(l[i] * w[i])});
  return v / std::max(1e-300, q.linfty_norm());
}

std::string sci(const double x)
{
  std::ostringstream s;
  s << std::scientific << std::setprecision(2) << x;
  return s.str();
}

FullMatrix<double> random_spd(const unsigned int n, std::mt19937 &gen)
{
  std::uniform_real_distribution<double> u(-1., 1.);
  FullMatrix<double> B(n, n), W(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      B(i, j) = u(gen);
  B.Tmmult(W, B);
  for (unsigned int i = 0; i < n; ++i)
    W(i, i) += 0.1 * n;
  return W;
}
} // namespace

HATI_UNIT_TEST(lcp_solver)
{
  // one contact: lambda = max(0, -q/W)
  {
    FullMatrix<double> W(1, 1);
    W(0, 0) = 0.5;
    Vector<double> q(1);
    q[0] = -2.;
    expect(std::abs(hati::solve_lcp(W, q)[0] - 4.) < 1e-15, "single contact, closing");
    q[0] = 3.;
    expect(hati::solve_lcp(W, q)[0] == 0., "single contact, separating");
  }
  // a rigid bar on two supports (coupled contacts): W = [[2,1],[1,2]],
  // q = [-1, 1]: only the first one pushes, lambda = (0.5, 0)
  {
    FullMatrix<double> W(2, 2);
    W(0, 0) = W(1, 1) = 2.;
    W(0, 1) = W(1, 0) = 1.;
    Vector<double> q(2);
    q[0] = -1.;
    q[1] = 1.;
    const auto l = hati::solve_lcp(W, q);
    expect(std::abs(l[0] - 0.5) < 1e-15 && l[1] == 0.,
           "two coupled contacts, one active");
    q[1] = -1.; // both push: lambda = W^-1 (1, 1) = (1/3, 1/3)
    const auto l2 = hati::solve_lcp(W, q);
    expect(std::abs(l2[0] - 1. / 3.) < 1e-15 && std::abs(l2[1] - 1. / 3.) < 1e-15,
           "two coupled contacts, both active");
  }
  // random coupled clusters: enumeration (n <= 12) and PGS (n > 12)
  std::mt19937 gen(42);
  std::uniform_real_distribution<double> u(-1., 1.);
  for (const unsigned int n : {3u, 6u, 10u, 20u, 40u})
    for (unsigned int trial = 0; trial < 5; ++trial)
    {
      const FullMatrix<double> W = random_spd(n, gen);
      Vector<double> q(n);
      for (unsigned int i = 0; i < n; ++i)
        q[i] = u(gen);
      const auto l = hati::solve_lcp(W, q);
      const double v = violation(W, q, l);
      expect(v < 1e-9,
             "random SPD cluster n = " + std::to_string(n) + ", complementarity " +
                 std::to_string(v));
    }
  // a contact on a massless DoF is an error, not a NaN
  {
    FullMatrix<double> W(1, 1);
    Vector<double> q(1);
    q[0] = -1.;
    bool thrown = false;
    try
    {
      hati::solve_lcp(W, q);
    }
    catch (const std::exception &)
    {
      thrown = true;
    }
    expect(thrown, "zero Delassus entry refused");
  }
  // a prescribed active set with dependent rows (solve_equalities): a wheel
  // sticking on its rail, rows normal (z) and tangents (x, y) of one node of
  // inverse mass 1/m, and the flange's lateral contact along y on the same
  // node. W = L M^-1 L^T is singular (rows 2 and 3 equal); q = L v with v
  // the node's free velocity. Independent reference: the velocity after the
  // impulses, v + M^-1 L^T lambda, must be zero along x, y, z (every row an
  // equality), and the minimum-norm solution shares the y impulse equally.
  {
    const double minv = 1. / 250.;
    FullMatrix<double> L(4, 3);
    L(0, 2) = 1.; // normal
    L(1, 0) = 1.; // tangent x
    L(2, 1) = 1.; // tangent y
    L(3, 1) = 1.; // flange, y
    FullMatrix<double> W(4, 4);
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        for (unsigned int d = 0; d < 3; ++d)
          W(i, j) += L(i, d) * minv * L(j, d);
    Vector<double> v(3), q(4), lambda;
    v[0] = 0.3;
    v[1] = -0.2;
    v[2] = -1.1;
    L.vmult(q, v);
    FullMatrix<double> W_inverse;
    bool inverted = false;
    hati::solve_equalities(W, W_inverse, inverted, q, lambda);
    Vector<double> after(v), impulse(3);
    L.Tvmult(impulse, lambda);
    for (unsigned int d = 0; d < 3; ++d)
      after[d] += minv * impulse[d];
    expect(after.linfty_norm() < 1e-14,
           "dependent prescribed rows: velocity after the impulses " +
               std::to_string(after.linfty_norm()));
    expect(std::abs(lambda[2] - lambda[3]) < 1e-12 * std::abs(lambda[2]) &&
               std::abs(lambda[2] + lambda[3] - 0.2 * 250.) < 1e-10,
           "dependent prescribed rows: the minimum-norm split of the y impulse");
  }
  // a cluster of equalities with contacts on them (ties of a rail to a
  // flange, a wheel on the rail): the equalities eliminated
  // (BilateralElimination) against the conditions themselves (bilateral
  // rows: w = 0, either sign; unilateral: complementarity) and against
  // projected Gauss-Seidel on the whole cluster (tolerance 1e-12); twice
  // with the same W (the elimination kept) and a new q
  for (const unsigned int n_unilateral : {0u, 1u, 3u, 14u})
  {
    const unsigned int n = 20 + n_unilateral;
    const FullMatrix<double> W = random_spd(n, gen);
    // the contacts' rows spread among the equalities
    std::vector<bool> bilateral(n, true);
    for (unsigned int k = 0; k < n_unilateral; ++k)
      bilateral[k * n / n_unilateral] = false;
    hati::BilateralElimination elimination;
    for (unsigned int trial = 0; trial < 2; ++trial)
    {
      Vector<double> q(n), l, l_pgs;
      for (unsigned int i = 0; i < n; ++i)
        q[i] = u(gen);
      hati::solve_lcp(W, q, bilateral, l, elimination);
      hati::solve_lcp(W, q, bilateral, l_pgs);
      Vector<double> w(q);
      W.vmult_add(w, l);
      double v = 0.;
      for (unsigned int i = 0; i < n; ++i)
        v = bilateral[i] ? std::max(v, std::abs(w[i]))
                         : std::max({v, -l[i], -w[i], std::abs(l[i] * w[i])});
      v /= q.linfty_norm();
      Vector<double> d(l);
      d -= l_pgs;
      const std::string name = "equalities eliminated, " + std::to_string(n_unilateral) +
                               " contacts, trial " + std::to_string(trial) + ": ";
      expect(elimination.formed && elimination.invertible, name + "elimination formed");
      expect(v < 1e-12, name + "conditions " + sci(v));
      expect(d.linfty_norm() < 1e-8 * l_pgs.linfty_norm(),
             name + "against PGS " + sci(d.linfty_norm() / l_pgs.linfty_norm()));
    }
  }
  // dependent equalities (the same tie row twice): not eliminated, the plain
  // solve (PGS) gives a solution
  {
    const unsigned int n = 16;
    FullMatrix<double> W = random_spd(n, gen);
    for (unsigned int j = 0; j < n; ++j)
      W(1, j) = W(0, j);
    for (unsigned int i = 0; i < n; ++i)
      W(i, 1) = W(i, 0);
    std::vector<bool> bilateral(n, true);
    bilateral[n - 1] = false;
    Vector<double> q(n), l;
    for (unsigned int i = 0; i < n; ++i)
      q[i] = u(gen);
    q[1] = q[0];
    hati::BilateralElimination elimination;
    hati::solve_lcp(W, q, bilateral, l, elimination);
    Vector<double> w(q);
    W.vmult_add(w, l);
    double v = std::max({-l[n - 1], -w[n - 1], std::abs(l[n - 1] * w[n - 1])});
    for (unsigned int i = 0; i + 1 < n; ++i)
      v = std::max(v, std::abs(w[i]));
    expect(elimination.formed && !elimination.invertible,
           "dependent equalities: not eliminated");
    expect(v < 1e-9 * q.linfty_norm(),
           "dependent equalities: conditions " + sci(v / q.linfty_norm()));
  }
  // issue #59: redundant contacts in a cluster of 4 to 12 (the enumeration
  // tests each set's regularity itself; FullMatrix::invert() does not in
  // Release): two wheels' rows on one node of inverse mass 1, the second a
  // copy of the first perturbed at round-off, plus four single rows; every
  // row closing at -1 m/s. Reference: the conditions themselves and the
  // total impulse on the doubled node, 1 (its velocity stopped)
  for (const double perturbation : {0., 1e-15, 1e-13})
  {
    FullMatrix<double> L(6, 5);
    L(0, 0) = 1.;
    L(1, 0) = 1. + perturbation;
    for (unsigned int i = 2; i < 6; ++i)
      L(i, i - 1) = 1.;
    FullMatrix<double> W(6, 6);
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int d = 0; d < 5; ++d)
          W(i, j) += L(i, d) * L(j, d);
    Vector<double> q(6);
    for (unsigned int i = 0; i < 6; ++i)
      q[i] = -1.;
    const Vector<double> l = hati::solve_lcp(W, q);
    bool finite = true;
    for (const double x : l)
      finite = finite && std::isfinite(x) && std::abs(x) < 10.;
    const double stopped = l[0] + (1. + perturbation) * l[1];
    expect(finite && violation(W, q, l) < 1e-9 && std::abs(stopped - 1.) < 1e-9,
           "redundant rows in a cluster of 6, perturbation " + sci(perturbation) +
               ": complementary, bounded, the doubled node stopped (" +
               sci(std::abs(stopped - 1.)) + ")");
  }
  std::cout << (failures ? "FAILED" : "all checks passed") << std::endl;
  return failures ? 1 : 0;
}
} // namespace hati_unit_lcp_solver

// Unit test of Rayleigh damping in the explicit CD-Lagrange integrator
// (algorithms.md A7, doc/theory.md 1.6), on DiscreteSystem objects built by
// hand and checked against independent results:
//  (a) one damped step against the formula of A7 evaluated with deal.II's
//      matrix-vector products (compiled row widths and the generic one);
//  (b) damped SDOF: the exact stability limit of the scheme, found by
//      bisection on the spectral radius of the amplification matrix of the
//      code, against dt_crit = (2/omega)(sqrt(1 + xi^2) - xi); runs at
//      0.99 and 1.05 times the limit stay bounded and blow up;
//  (c) damped SDOF, 1000 steps per period: decay rate against the exact
//      exp(-zeta omega t) and the whole history against the exact solution;
//  (d) energy balance with a0, a1 > 0 (spring chain with a constant and a
//      time-dependent load and an initial velocity, the chain against a
//      contact, and a dense system using the generic kernel);
//  (e) linear state, snapshots, the undamped state and the refusal message.
// Every check prints value, reference and tolerance; returns non-zero on
// failure.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "test_tools.h"

#include <hati/base/mpi_environment.h>
#include <hati/model/discrete_system.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/rayleigh_damping.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace hati_unit_cd_lagrange
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{

RayleighDamping rayleigh(const double a0, const double a1)
{
  RayleighDamping d;
  d.a0 = a0;
  d.a1 = a1;
  return d;
}

/** One mass m (kg) on a spring k (N/m). */
void make_sdof(DiscreteSystem &s, const double k, const double m)
{
  s.reinit(1);
  s.lumped_mass[0] = m;
  DynamicSparsityPattern dsp(1, 1);
  dsp.add(0, 0);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  s.stiffness.set(0, 0, k);
}

/**
 * A chain of N springs k_e (N/m) between N + 1 nodes of masses m_i (kg)
 * along x; node 0 is fixed (condensed: only its diagonal). Stiffnesses and
 * masses vary along the chain so that no symmetry hides an error.
 */
void make_chain(DiscreteSystem &s, const unsigned int N)
{
  const unsigned int n = N + 1;
  s.reinit(n);
  DynamicSparsityPattern dsp(n, n);
  for (unsigned int e = 0; e < N; ++e)
    for (unsigned int a = e; a <= e + 1; ++a)
      for (unsigned int b = e; b <= e + 1; ++b)
        dsp.add(a, b);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  for (unsigned int e = 0; e < N; ++e)
  {
    const double k = 1000. * (1. + 0.3 * e);
    s.stiffness.add(e, e, k);
    s.stiffness.add(e + 1, e + 1, k);
    s.stiffness.add(e, e + 1, -k);
    s.stiffness.add(e + 1, e, -k);
  }
  for (unsigned int i = 0; i < n; ++i)
    s.lumped_mass[i] = 1. + 0.25 * i;
  s.fixed[0] = true;
  s.stiffness.set(0, 1, 0.);
  s.stiffness.set(1, 0, 0.);
}

/**
 * A dense system of n DoFs, `K = k (I + 1 1^T / n)` (symmetric positive
 * definite), every row n wide: with n > 96 it takes the generic kernel.
 */
void make_dense(DiscreteSystem &s, const unsigned int n, const double k)
{
  s.reinit(n);
  DynamicSparsityPattern dsp(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      dsp.add(i, j);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      s.stiffness.set(i, j, k * ((i == j ? 1. : 0.) + (1. + 0.1 * ((i + j) % 3)) / n));
  for (unsigned int i = 0; i < n; ++i)
    s.lumped_mass[i] = 1. + 0.01 * i;
}

/** Largest modulus of the eigenvalues of a real 2x2 matrix. */
double spectral_radius(const double a, const double b, const double c, const double d)
{
  const double tr = a + d, det = a * d - b * c;
  const std::complex<double> root = std::sqrt(std::complex<double>(tr * tr - 4. * det));
  return std::max(std::abs(0.5 * (tr + root)), std::abs(0.5 * (tr - root)));
}

/**
 * Spectral radius of the amplification matrix of one step of the code on
 * the state (U_n, V_{n+1/2}) of a SDOF, from its response to the two unit
 * states.
 */
double code_spectral_radius(const DiscreteSystem &s,
                            const double dt,
                            const RayleighDamping &damping)
{
  double A[2][2];
  for (unsigned int j = 0; j < 2; ++j)
  {
    CDLagrange integrator(s, dt, 1e3, damping);
    auto state = integrator.linear_state();
    (*state[0])[0] = (j == 0 ? 1. : 0.);
    (*state[1])[0] = (j == 1 ? 1. : 0.);
    integrator.step();
    A[0][j] = integrator.displacement()[0];
    A[1][j] = integrator.velocity()[0];
  }
  return spectral_radius(A[0][0], A[0][1], A[1][0], A[1][1]);
}

/** max |U| over @p n steps of a SDOF from U_0 = 1 (non-finite: +inf). */
std::vector<double> sdof_history(const DiscreteSystem &s,
                                 const double dt,
                                 const RayleighDamping &damping,
                                 const unsigned int n)
{
  CDLagrange integrator(s, dt, 1e3, damping);
  std::vector<double> u{integrator.displacement()[0]};
  for (unsigned int i = 0; i < n; ++i)
  {
    integrator.step();
    u.push_back(integrator.displacement()[0]);
  }
  return u;
}

double
max_abs(const std::vector<double> &u, const unsigned int begin, const unsigned int end)
{
  double m = 0.;
  for (unsigned int i = begin; i < end; ++i)
    m = std::isfinite(u[i]) ? std::max(m, std::abs(u[i]))
                            : std::numeric_limits<double>::infinity();
  return m;
}

// (a) one damped step against the formula of A7
void test_one_step()
{
  std::cout << "--- (a) one damped step against (1 + a0 dt/2) V_free = (1 - a0 dt/2) V "
               "+ dt M^-1 (F - K U - a1 K V)"
            << std::endl;
  for (const unsigned int n : {5u, 120u})
  {
    DiscreteSystem s;
    if (n == 5)
      make_chain(s, n - 1);
    else
      make_dense(s, n, 100.);
    for (unsigned int i = 0; i < n; ++i)
      if (!s.fixed[i])
      {
        s.initial_displacement[i] = 0.01 * std::sin(1. + i);
        s.initial_velocity[i] = 0.3 * std::cos(2. + i);
        s.constant_force[i] = 5. * std::sin(3. + i);
      }
    const double a0 = 3., a1 = 2e-3;
    const double dt = 0.5 * CDLagrange(s, 1., 1e9, rayleigh(a0, a1)).critical_time_step();
    CDLagrange integrator(s, dt, 1., rayleigh(a0, a1));
    for (unsigned int i = 0; i < 3; ++i)
      integrator.step();
    Vector<double> U(integrator.displacement()), V(integrator.velocity());
    integrator.step();
    // reference: U_{n+1} = U_n + dt V, then the A7 update with deal.II
    U.add(dt, V);
    Vector<double> ku(n), kv(n), ref(n);
    s.stiffness.vmult(ku, U);
    s.stiffness.vmult(kv, V);
    double error = 0., scale = 0.;
    for (unsigned int i = 0; i < n; ++i)
    {
      if (!s.fixed[i])
        ref[i] = ((1. - 0.5 * a0 * dt) * V[i] +
                  dt / s.lumped_mass[i] * (s.constant_force[i] - ku[i] - a1 * kv[i])) /
                 (1. + 0.5 * a0 * dt);
      error = std::max(error, std::abs(integrator.velocity()[i] - ref[i]));
      scale = std::max(scale, std::abs(ref[i]));
    }
    check("n = " + std::to_string(n) + " DoFs (row width " +
              (n == 5 ? std::string("3") : std::string("120, generic")) +
              "): max |V_{n+3/2} - reference| / max |reference|",
          error / scale,
          0.,
          1e-13);
  }
}

// (b) exact stability limit of the scheme on a SDOF
void test_stability_limit()
{
  std::cout << "--- (b) damped SDOF: exact stability limit against "
               "dt_crit = (2/omega)(sqrt(1 + xi^2) - xi), xi = a1 omega / 2"
            << std::endl;
  const double k = 4. * M_PI * M_PI, m = 1.; // omega = 2 pi rad/s
  const double omega = std::sqrt(k / m);
  DiscreteSystem s;
  make_sdof(s, k, m);
  s.initial_displacement[0] = 1.;
  struct Case
  {
    double zeta_mass, xi;
  };
  // zeta_mass = a0 / (2 omega), xi = a1 omega / 2 (the two parts of zeta)
  for (const Case c : {Case{0., 0.},
                       Case{0.05, 0.},
                       Case{0., 0.02},
                       Case{0.05, 0.05},
                       Case{0., 0.3},
                       Case{0.2, 1.},
                       Case{0., 3.}})
  {
    const RayleighDamping damping = rayleigh(2. * c.zeta_mass * omega, 2. * c.xi / omega);
    std::ostringstream name;
    name << "a0/(2 omega) = " << c.zeta_mass << ", xi = " << c.xi;
    // the largest dt with spectral radius <= 1: bisection on the code's
    // amplification matrix (stable at 0, unstable at 4 / omega)
    double lo = 0., hi = 4. / omega;
    for (unsigned int it = 0; it < 60; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (code_spectral_radius(s, mid, damping) <= 1. + 1e-12 ? lo : hi) = mid;
    }
    const double exact = lo;
    const double dt_crit = CDLagrange(s, 1e-6, 1., damping).critical_time_step();
    const double formula =
        2. / omega * (std::sqrt(1. + c.xi * c.xi) - c.xi); // Belytschko et al.
    check(name.str() + ": dt_crit of the code (s) against the formula",
          dt_crit,
          formula,
          1e-12 * formula);
    check(name.str() + ": exact limit of the scheme (s, bisection) against dt_crit",
          exact,
          dt_crit,
          1e-9 * dt_crit);
    expect(dt_crit <= exact * (1. + 1e-9),
           name.str() + ": dt_crit <= exact limit (a safe bound)");
    // runs just below and above the limit, 4000 steps from U_0 = 1
    const auto below = sdof_history(s, 0.99 * exact, damping, 4000);
    const auto above = sdof_history(s, 1.05 * exact, damping, 4000);
    const double first = max_abs(below, 0, 1000), last = max_abs(below, 3000, 4001);
    std::cout << "     0.99 x limit: max |U| steps 0-1000 " << first << ", 3000-4000 "
              << last << "; 1.05 x limit: max |U| steps 3000-4000 "
              << max_abs(above, 3000, 4001) << std::endl;
    expect(first < 100. && last <= 1.01 * first,
           name.str() + ": bounded at 0.99 x limit (max |U| of the last 1000 steps <= "
                        "1.01 x that of the first 1000, < 100)");
    expect(max_abs(above, 3000, 4001) > 1e6,
           name.str() + ": blows up at 1.05 x limit (max |U| of the last 1000 steps > "
                        "1e6)");
  }
}

// (c) decay rate of the damped SDOF against the exact solution
void test_decay()
{
  std::cout << "--- (c) damped SDOF, zeta = 0.02, 1000 steps per period: decay "
               "against exp(-zeta omega t)"
            << std::endl;
  const double k = 4. * M_PI * M_PI, m = 1.;
  const double omega = std::sqrt(k / m), T = 2. * M_PI / omega, zeta = 0.02;
  const double dt = T / 1000.;
  const double omega_d = omega * std::sqrt(1. - zeta * zeta);
  DiscreteSystem s;
  make_sdof(s, k, m);
  s.initial_displacement[0] = 1.;
  struct Case
  {
    std::string name;
    double mass_share; // share of zeta from a0
  };
  for (const Case &c :
       {Case{"mass only", 1.}, Case{"stiffness only", 0.}, Case{"mixed", 0.5}})
  {
    const RayleighDamping damping = rayleigh(2. * c.mass_share * zeta * omega,
                                             2. * (1. - c.mass_share) * zeta / omega);
    const unsigned int n = 10000; // 10 periods
    const auto u = sdof_history(s, dt, damping, n);
    // peaks: local maxima of U_n, refined by a parabola through three steps
    std::vector<double> t_peak, u_peak;
    for (unsigned int i = 1; i < n; ++i)
      if (u[i] > u[i - 1] && u[i] >= u[i + 1])
      {
        const double den = u[i - 1] - 2. * u[i] + u[i + 1];
        const double x = 0.5 * (u[i - 1] - u[i + 1]) / den;
        t_peak.push_back((i + x) * dt);
        u_peak.push_back(u[i] - 0.25 * (u[i - 1] - u[i + 1]) * x);
      }
    const unsigned int np = t_peak.size();
    const double rate =
        std::log(u_peak[0] / u_peak[np - 1]) / (t_peak[np - 1] - t_peak[0]);
    check(c.name + ": decay rate from the " + std::to_string(np) +
              " peaks (1/s) against zeta omega",
          rate,
          zeta * omega,
          5e-3 * zeta * omega);
    check(c.name +
              ": ratio of successive peaks against exp(-2 pi zeta / sqrt(1 - zeta^2))",
          u_peak[np - 1] / u_peak[np - 2],
          std::exp(-2. * M_PI * zeta / std::sqrt(1. - zeta * zeta)),
          5e-3 * (1. - std::exp(-2. * M_PI * zeta)));
    // the period: the lagged stiffness part raises the discrete frequency by
    // xi omega dt / 2 (first order, doc/theory.md 1.6), CD itself by
    // (omega dt)^2 / 24
    const double xi = (1. - c.mass_share) * zeta, s_dt = omega * dt;
    const double period = (t_peak[np - 1] - t_peak[0]) / (np - 1);
    std::cout << "     measured period / (2 pi / omega_d) - 1 = "
              << period * omega_d / (2. * M_PI) - 1. << ", predicted "
              << -(0.5 * xi * s_dt + s_dt * s_dt / 24.) << std::endl;
    check(c.name + ": damped period (s) against 2 pi / omega_d",
          period,
          2. * M_PI / omega_d,
          1e-4 * 2. * M_PI / omega_d);
    // the whole history against u(t) = e^{-zeta w t}(cos w_d t + zeta w / w_d sin w_d t):
    // a phase error of (xi omega dt / 2) omega t, 1.1e-3 m after 10 periods with
    // stiffness damping only
    double error = 0.;
    for (unsigned int i = 0; i <= n; ++i)
    {
      const double t = i * dt;
      const double exact =
          std::exp(-zeta * omega * t) *
          (std::cos(omega_d * t) + zeta * omega / omega_d * std::sin(omega_d * t));
      error = std::max(error, std::abs(u[i] - exact));
    }
    check(
        c.name + ": max |U_n - u(t_n)| over 10 periods (m, U_0 = 1 m)", error, 0., 2e-3);
  }
}

/**
 * Largest |total(t) - total(0)| over @p n steps divided by the largest
 * energy term seen; also returns that term and the dissipated energy.
 */
double energy_drift(CDLagrange &integrator,
                    const unsigned int n,
                    double &scale,
                    double &dissipated)
{
  const Energies e0 = integrator.energies();
  double drift = 0.;
  scale = 0.;
  for (unsigned int i = 0; i < n; ++i)
  {
    integrator.step();
    const Energies e = integrator.energies();
    drift = std::max(drift, std::abs(e.total() - e0.total()));
    for (const double x :
         {e.kinetic, e.internal, e.dissipated, e.external_work, e.contact_work})
      scale = std::max(scale, std::abs(x));
    dissipated = e.dissipated;
    if (e.dissipated != integrator.dissipated_energy())
      drift = std::numeric_limits<double>::infinity();
  }
  return drift / scale;
}

// (d) energy balance with damping
void test_energy_balance()
{
  std::cout << "--- (d) energy balance T + W + D - X - C constant with a0, a1 > 0"
            << std::endl;
  for (const std::string variant :
       {"chain", "chain with contact", "dense (generic kernel)"})
  {
    DiscreteSystem s;
    unsigned int n;
    if (variant == "dense (generic kernel)")
    {
      n = 100;
      make_dense(s, n, 500.);
    }
    else
    {
      n = 6;
      make_chain(s, n - 1);
    }
    Vector<double> shape(n);
    for (unsigned int i = 1; i < n; ++i)
    {
      s.initial_displacement[i] = 1e-3 * std::sin(0.7 * i);
      s.initial_velocity[i] = 0.05 * std::cos(1.3 * i);
      s.constant_force[i] = (i == n - 1 ? 2. : 0.);
      shape[i] = (i % 2 == 0 ? 1. : -0.5);
    }
    TimeDependentLoad load;
    load.shape = shape;
    load.amplitude = [](const double t) { return 3. * std::sin(7. * t) + t; };
    s.time_dependent_loads.push_back(load);
    if (variant == "chain with contact")
    {
      ContactRow c;
      c.name = "tip";
      c.dofs = {n - 1};
      c.coefficients = {-1.}; // wall at x = 2 mm ahead of the tip
      c.initial_gap = 2e-3;
      c.restitution = 0.5;
      s.contacts.push_back(c);
    }
    const double a0 = 0.8, a1 = 4e-3;
    const double dt = 0.9 * CDLagrange(s, 1., 1e9, rayleigh(a0, a1)).critical_time_step();
    CDLagrange integrator(s, dt, 1., rayleigh(a0, a1));
    double scale = 0., dissipated = 0.;
    const double drift = energy_drift(integrator, 3000, scale, dissipated);
    std::cout << "     " << variant << ": dt = " << dt << " s, largest energy term "
              << scale << " J, dissipated " << dissipated << " J" << std::endl;
    check(
        variant + ": max |total(t) - total(0)| / largest energy term", drift, 0., 1e-12);
    expect(dissipated > 0.01 * scale,
           variant + ": the damping matters (dissipated > 0.01 x largest energy term)");
    if (variant == "chain with contact")
    {
      bool impact = false;
      CDLagrange again(s, dt, 1., rayleigh(a0, a1));
      for (unsigned int i = 0; i < 3000 && !impact; ++i)
      {
        again.step();
        impact = again.impulses()[0] > 0.;
      }
      expect(impact, variant + ": the contact was active");
    }
  }
}

// (e) linear state, snapshots, undamped state, refusal message
void test_state()
{
  std::cout << "--- (e) linear state, snapshots, undamped state, refusal" << std::endl;
  DiscreteSystem s;
  make_chain(s, 4);
  for (unsigned int i = 1; i < 5; ++i)
    s.initial_velocity[i] = 0.1 * i;
  const double dt = 1e-3;
  {
    CDLagrange undamped(s, dt, 1.);
    for (unsigned int i = 0; i < 50; ++i)
      undamped.step();
    const auto state = undamped.linear_state();
    check("undamped: |d_prev| (linear_state()[3])", state[3]->l2_norm(), 0., 0.);
    check("undamped: dissipated energy (J)", undamped.energies().dissipated, 0., 0.);
  }
  CDLagrange integrator(s, dt, 1., rayleigh(1., 1e-3));
  // d_0 = dt M^-1 C V_0 with C V_0 = a0 M V_0 + a1 K V_0
  {
    Vector<double> kv(5);
    s.stiffness.vmult(kv, s.initial_velocity);
    double error = 0.;
    for (unsigned int i = 1; i < 5; ++i)
      error = std::max(
          error,
          std::abs((*integrator.linear_state()[3])[i] -
                   dt * (1. * s.initial_velocity[i] + 1e-3 * kv[i] / s.lumped_mass[i])));
    check("d_0 = dt M^-1 C V_0 (m/s)", error, 0., 1e-15);
  }
  for (unsigned int i = 0; i < 100; ++i)
    integrator.step();
  CDLagrange::Snapshot snapshot;
  integrator.save(snapshot);
  for (unsigned int i = 0; i < 50; ++i)
    integrator.step();
  const Vector<double> U(integrator.displacement()), V(integrator.velocity());
  const double dissipated = integrator.dissipated_energy();
  integrator.restore(snapshot);
  for (unsigned int i = 0; i < 50; ++i)
    integrator.step();
  Vector<double> dU(U), dV(V);
  dU -= integrator.displacement();
  dV -= integrator.velocity();
  check("restore and redo 50 steps: |dU| + |dV|", dU.l2_norm() + dV.l2_norm(), 0., 0.);
  check("restore and redo 50 steps: dissipated energy (J)",
        integrator.dissipated_energy(),
        dissipated,
        0.);
  integrator.add_dissipated(1.5);
  check(
      "add_dissipated(1.5 J)", integrator.energies().dissipated, dissipated + 1.5, 1e-15);

  // refusal above the damped dt_crit: the message names the damping
  const RayleighDamping damping = rayleigh(0., 0.01);
  const double dt_crit = CDLagrange(s, 1e-6, 1., damping).critical_time_step();
  try
  {
    CDLagrange refused(s, 1.01 * dt_crit, 1., damping);
    expect(false, "dt = 1.01 dt_crit with a1 > 0 refused");
  }
  catch (const std::exception &e)
  {
    const std::string what = message_of(e);
    std::ostringstream crit;
    crit.precision(6);
    crit << dt_crit;
    expect(what.find("damping") != std::string::npos &&
               what.find("sqrt(1 + xi^2) - xi") != std::string::npos &&
               what.find(crit.str()) != std::string::npos,
           "dt = 1.01 dt_crit with a1 > 0 refused, the message names the damping and "
           "dt_crit = " +
               crit.str() + " s");
  }
}
} // namespace

HATI_UNIT_TEST(cd_lagrange)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
  {
    test_one_step();
    test_stability_limit();
    test_decay();
    test_energy_balance();
    test_state();
  }
  catch (const std::exception &e)
  {
    std::cout << "FAIL exception: " << e.what() << std::endl;
    return 1;
  }
  return finish();
}
} // namespace hati_unit_cd_lagrange

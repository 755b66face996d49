// Unit test of frequency-range damping in the integrators (doc/theory.md
// A8 for CD-Lagrange, N4 for Newmark; the branches from
// fit_maxwell_branches(), 2 % over 1-30 Hz), on DiscreteSystem objects
// built by hand:
//  (a) free decay of a single DoF at five frequencies across the band,
//      CD-Lagrange at dt = 0.2 (2/omega) and Newmark at DT = T/50: the
//      logarithmic decrement gives a ratio within 5 % of the fitted exact
//      ratio MaxwellBranches::damping_ratio(f);
//  (b) the stable step of CD-Lagrange: dt just above
//      (2/omega_max)/sqrt(1 + sum alpha) is refused with the critical step
//      in the message, dt just below runs bounded (a SDOF far above the
//      band, where the branches act as springs), and 2 % above it grows;
//  (c) Newmark: the class's steps against the N4 formula of the
//      specification's prototype, and the spectral radius of that
//      amplification matrix <= 1 for omega DT from 1e-3 to 1e4;
//  (d) energy balance at round-off in both integrators on a spring chain
//      (stored + dissipated of the branches booked), the stored energy
//      against 1/2 sum alpha_l q_l.K q_l and the dissipated energy against
//      the continuous rate sum_l (alpha_l/tau_l) q_l.K q_l integrated.
// Every check prints value, reference and tolerance; returns non-zero on
// failure.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include "test_tools.h"

#include <hati/base/mpi_environment.h>
#include <hati/model/discrete_system.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/frequency_range_damping.h>
#include <hati/time/newmark.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace hati_unit_maxwell_damping
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{
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

/** A chain of N springs (varying k) between N + 1 masses, node 0 fixed. */
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
    const double k = 4000. * (1. + 0.3 * e);
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
 * Damping ratio from the logarithmic decrement of the positive peaks of
 * @p u, skipping the first two and the last one (as the prototype does).
 */
double decay_ratio(const std::vector<double> &u)
{
  std::vector<unsigned int> peaks;
  for (unsigned int j = 1; j + 1 < u.size(); ++j)
    if (u[j] > u[j - 1] && u[j] >= u[j + 1] && u[j] > 0.)
      peaks.push_back(j);
  if (peaks.size() < 6)
    return std::nan("");
  const double n_periods = peaks.size() - 3;
  const double delta = std::log(u[peaks[2]] / u[peaks[peaks.size() - 2]]) / n_periods;
  return delta / std::sqrt(4. * M_PI * M_PI + delta * delta);
}

MaxwellBranches band_fit() { return fit_maxwell_branches(0.02, 1., 30., 3).branches; }

// (a) free decay of a single DoF
void test_free_decay(const MaxwellBranches &b)
{
  std::cout << "--- (a) free decay: ratio of CD-Lagrange (dt = 0.2 (2/omega)) and "
               "Newmark (DT = T/50) within 5 % of the fitted exact ratio"
            << std::endl;
  std::cout << "    f (Hz)   fitted xi   CD xi      Newmark xi" << std::endl;
  for (const double f : {1., 3.6, 6.2, 10., 30.})
  {
    const double omega = 2. * M_PI * f, m = 2., k = m * omega * omega;
    DiscreteSystem s;
    make_sdof(s, k, m);
    s.initial_displacement[0] = 1e-3;
    const unsigned int periods = 40;
    double xi[2];
    for (unsigned int method = 0; method < 2; ++method)
    {
      std::vector<double> u{s.initial_displacement[0]};
      if (method == 0)
      {
        const double dt = 0.2 * 2. / omega;
        CDLagrange cd(s, dt, 1., RayleighDamping(), b);
        for (unsigned int i = 0; i < std::lround(periods / f / dt); ++i)
        {
          cd.step();
          u.push_back(cd.displacement()[0]);
        }
      }
      else
      {
        const double dt = 0.02 / f;
        Newmark nm(s, dt, NewmarkParameters(), RayleighDamping(), b);
        for (unsigned int i = 0; i < std::lround(periods / f / dt); ++i)
        {
          nm.step();
          u.push_back(nm.displacement()[0]);
        }
      }
      xi[method] = decay_ratio(u);
    }
    const double ref = b.damping_ratio(f);
    std::cout << "    " << std::setw(6) << f << "   " << std::setprecision(5) << ref
              << "    " << xi[0] << "    " << xi[1] << std::endl;
    check("f = " + std::to_string(f) + " Hz: CD-Lagrange ratio / fitted ratio",
          xi[0] / ref,
          1.,
          0.05);
    check("f = " + std::to_string(f) + " Hz: Newmark ratio / fitted ratio",
          xi[1] / ref,
          1.,
          0.05);
  }
}

/** Largest |u| of CD-Lagrange at dt = factor dt_crit after n steps (safety 2). */
double cd_amplitude(const DiscreteSystem &s,
                    const MaxwellBranches &b,
                    const double factor,
                    const unsigned int n)
{
  const double dt_crit =
      CDLagrange(s, 1e-12, 1., RayleighDamping(), b).critical_time_step();
  CDLagrange cd(s, factor * dt_crit, 2., RayleighDamping(), b);
  double peak = 0.;
  for (unsigned int i = 0; i < n; ++i)
  {
    cd.step();
    peak = std::max(peak, std::abs(cd.displacement()[0]));
    if (!std::isfinite(peak))
      return peak;
  }
  return peak;
}

// (b) the stable step of CD-Lagrange
void test_stable_step(const MaxwellBranches &b)
{
  std::cout << "--- (b) stable step (2/omega_max)/sqrt(1 + sum alpha)" << std::endl;
  const double omega = 2. * M_PI * 1e5, m = 1., k = m * omega * omega;
  DiscreteSystem s;
  make_sdof(s, k, m);
  s.initial_displacement[0] = 1.;
  const double expected = 2. / omega / std::sqrt(1. + b.alpha_sum());
  const double dt_crit =
      CDLagrange(s, 1e-12, 1., RayleighDamping(), b).critical_time_step();
  check("dt_crit / ((2/omega)/sqrt(1 + sum alpha))", dt_crit / expected, 1., 1e-12);
  check("dt_crit / (2/omega) (0.924 for 2 % over 1-30 Hz)",
        dt_crit / (2. / omega),
        0.92392,
        1e-4);
  std::string message;
  try
  {
    CDLagrange cd(s, 1.001 * expected, 1., RayleighDamping(), b);
  }
  catch (const std::exception &e)
  {
    message = message_of(e);
  }
  std::cout << "    message: " << message << std::endl;
  std::ostringstream crit;
  crit.precision(6);
  crit << "dt_crit = (2/omega_max)/sqrt(1 + sum alpha) = " << expected << " s";
  expect(message.find(crit.str()) != std::string::npos,
         "dt = 1.001 dt_crit refused, the message gives '" + crit.str() + "'");
  bool runs = true;
  try
  {
    CDLagrange cd(s, 0.999 * expected, 1., RayleighDamping(), b);
    for (unsigned int i = 0; i < 100; ++i)
      cd.step();
  }
  catch (const std::exception &)
  {
    runs = false;
  }
  expect(runs, "dt = 0.999 dt_crit accepted with safety factor 1");
  const double below = cd_amplitude(s, b, 0.999, 200000);
  expect(below <= 1.5,
         "dt = 0.999 dt_crit: |u| <= 1.5 over 200000 steps (" + std::to_string(below) +
             ")");
  const double above = cd_amplitude(s, b, 1.02, 20000);
  expect(!(above < 1e3),
         "dt = 1.02 dt_crit: |u| grows above 1e3 within 20000 steps (" +
             std::to_string(above) + ")");
}

/** One N4 step of the prototype (m = 1, k = w^2) on the state (u, v, a, q_l). */
std::vector<double> n4_step(const MaxwellBranches &b,
                            const double w,
                            const double DT,
                            const std::vector<double> &x)
{
  const double k = w * w, beta = 0.25, gamma = 0.5;
  const unsigned int L = b.alpha.size();
  double bs = 0., hist = 0.;
  std::vector<double> e(L);
  for (unsigned int l = 0; l < L; ++l)
  {
    e[l] = std::exp(-DT / b.tau[l]);
    bs += b.alpha[l] * b.tau[l] * (1. - e[l]) / DT;
    hist += b.alpha[l] * e[l] * x[3 + l];
  }
  const double u = x[0], v = x[1], a = x[2];
  const double us = u + DT * v + DT * DT * (0.5 - beta) * a,
               vs = v + DT * (1. - gamma) * a;
  const double a1 =
      -k * (us + hist + bs * (us - u)) / (1. + beta * DT * DT * k * (1. + bs));
  std::vector<double> y(3 + L);
  y[0] = us + beta * DT * DT * a1;
  y[1] = vs + gamma * DT * a1;
  y[2] = a1;
  for (unsigned int l = 0; l < L; ++l)
    y[3 + l] = e[l] * x[3 + l] + b.tau[l] * (1. - e[l]) * (y[0] - u) / DT;
  return y;
}

// (c) Newmark: the class against N4, and the spectral radius
void test_newmark_radius(const MaxwellBranches &b)
{
  std::cout << "--- (c) Newmark (N4): the class against the formula, spectral radius"
            << std::endl;
  {
    const double w = 2. * M_PI * 5., DT = 0.01;
    DiscreteSystem s;
    make_sdof(s, w * w, 1.);
    s.initial_displacement[0] = 1.;
    Newmark nm(s, DT, NewmarkParameters(), RayleighDamping(), b);
    std::vector<double> x(3 + b.alpha.size(), 0.);
    x[0] = 1.;
    x[2] = -w * w;
    double error = 0.;
    for (unsigned int i = 0; i < 200; ++i)
    {
      nm.step();
      x = n4_step(b, w, DT, x);
      error = std::max({error,
                        std::abs(nm.displacement()[0] - x[0]),
                        std::abs(nm.velocity()[0] - x[1]) / w,
                        std::abs(nm.acceleration()[0] - x[2]) / (w * w)});
      for (unsigned int l = 0; l < b.alpha.size(); ++l)
        error = std::max(error, std::abs(nm.memory().memory()[l][0] - x[3 + l]));
    }
    check("200 steps, 5 Hz, DT = 0.01 s: max |class - N4 formula| (scaled)",
          error,
          0.,
          1e-12);
  }
  const unsigned int N = 3 + b.alpha.size();
  double worst = 0.;
  for (unsigned int j = 0; j < 57; ++j)
  {
    const double wdt = 1e-3 * std::pow(1e7, j / 56.);
    for (const double DT : {1e-4, 1e-3, 1e-2})
    {
      LAPACKFullMatrix<double> A(N, N);
      for (unsigned int c = 0; c < N; ++c)
      {
        std::vector<double> x(N, 0.);
        x[c] = 1.;
        const std::vector<double> y = n4_step(b, wdt / DT, DT, x);
        for (unsigned int r = 0; r < N; ++r)
          A(r, c) = y[r];
      }
      A.compute_eigenvalues();
      for (unsigned int i = 0; i < N; ++i)
        worst = std::max(worst, std::abs(A.eigenvalue(i)));
    }
  }
  std::ostringstream what;
  what.precision(15);
  what << "max spectral radius for omega DT in [1e-3, 1e4], DT in {1e-4, 1e-3, 1e-2}: "
       << worst << " <= 1 + 1e-12 (the prototype: 0.999999999978362)";
  expect(worst <= 1. + 1e-12, what.str());
}

/** Energy balance of one integrator on the chain; prints and checks it. */
template <class Integrator>
void check_balance(Integrator &integrator,
                   const DiscreteSystem &s,
                   const MaxwellBranches &b,
                   const std::string &name,
                   const unsigned int n_steps)
{
  const double dt = integrator.time_step();
  const Energies e0 = integrator.energies();
  double drift = 0., scale = 0., rate_integral = 0., previous_rate = 0.;
  Vector<double> kq(s.n_dofs());
  double stored_error = 0.;
  for (unsigned int i = 0; i < n_steps; ++i)
  {
    integrator.step();
    const Energies e = integrator.energies();
    scale = std::max({scale, std::abs(e.kinetic), std::abs(e.internal)});
    drift = std::max(drift, std::abs(e.total() - e0.total()));
    // the continuous dissipation rate sum_l alpha_l / tau_l q_l.K q_l and
    // the stored energy, from the memory variables
    double rate = 0., stored = 0.;
    for (unsigned int l = 0; l < b.alpha.size(); ++l)
    {
      const Vector<double> &q = integrator.memory().memory()[l];
      s.stiffness.vmult(kq, q);
      rate += b.alpha[l] / b.tau[l] * (q * kq);
      stored += 0.5 * b.alpha[l] * (q * kq);
    }
    rate_integral += 0.5 * dt * (previous_rate + rate);
    previous_rate = rate;
    stored_error = std::max(stored_error, std::abs(e.damping_stored - stored));
  }
  const Energies e = integrator.energies();
  std::cout << "    " << name << ": largest energy term " << scale << " J, dissipated "
            << e.dissipated << " J, stored " << e.damping_stored << " J, drift " << drift
            << " J" << std::endl;
  check(name + ": max |total - total_0| / largest energy term", drift / scale, 0., 1e-12);
  check(name + ": max |damping_stored - 1/2 sum alpha q.K q| / largest energy term",
        stored_error / scale,
        0.,
        1e-14);
  check(name + ": dissipated / integral of sum (alpha/tau) q.K q dt",
        e.dissipated / rate_integral,
        1.,
        0.02);
  expect(e.dissipated > 0.2 * scale,
         name + ": the damping matters (dissipated > 0.2 x largest energy term)");
}

// (d) energy balance
void test_energy_balance(const MaxwellBranches &b)
{
  std::cout << "--- (d) energy balance with frequency-range damping" << std::endl;
  DiscreteSystem s;
  make_chain(s, 6);
  for (unsigned int i = 1; i < s.n_dofs(); ++i)
  {
    s.initial_displacement[i] = 0.01 * std::sin(1. + i);
    s.initial_velocity[i] = 0.3 * std::cos(2. + i);
    s.constant_force[i] = 20. * std::sin(3. + i);
  }
  const double dt_crit =
      CDLagrange(s, 1e-12, 1., RayleighDamping(), b).critical_time_step();
  CDLagrange cd(s, 0.1 * dt_crit, 1., RayleighDamping(), b);
  check_balance(cd, s, b, "CD-Lagrange", 8000);
  Newmark nm(s, 2e-3, NewmarkParameters(), RayleighDamping(), b);
  check_balance(nm, s, b, "Newmark", 2000);
}
} // namespace

HATI_UNIT_TEST(maxwell_damping)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MaxwellBranches b = band_fit();
  std::cout << "branches: alpha";
  for (const double a : b.alpha)
    std::cout << ' ' << a;
  std::cout << ", tau";
  for (const double t : b.tau)
    std::cout << ' ' << t;
  std::cout << ", sum alpha " << b.alpha_sum() << std::endl;
  test_free_decay(b);
  test_stable_step(b);
  test_newmark_radius(b);
  test_energy_balance(b);
  return finish();
}
} // namespace hati_unit_maxwell_damping

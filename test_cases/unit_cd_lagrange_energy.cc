// Unit test of CD-Lagrange (algorithms.md A1-A6) under time-dependent loads
// (DiscreteSystem::time_dependent_loads), on DiscreteSystem objects built by
// hand:
//  (a) one mass on a spring to a fixed base under a base acceleration step
//      a0 from t = 0 and (b) a sine base acceleration A sin(w t): the relative
//      displacement is compared with the exact solution of the central
//      difference recurrence u_{n+1} - 2 u_n + u_{n-1} = dt^2 (-a(t_n) -
//      omega^2 u_n) (closed forms below), which checks that the load acts with
//      the lumped mass (-M_lumped r a, not the shape given by the model) and
//      with the amplitude of t_{n+1};
//  (c) a fixed-free chain of springs and masses under a sine and a step base
//      acceleration (the step starting at a time step, and between two), a
//      time-dependent tip force and gravity: the discrete energy balance
//      (doc/theory.md E1) Energies::total() stays constant to round-off, and
//      the external work equals the trapezoidal sum of F(t) . dU recomputed
//      here from the loads; the balance with a rectangle rule instead is
//      shown to miss by far more than the tolerance (the check discriminates).
//      The step on a time step t_j = j dt is chosen where (j + 1) dt - dt < j
//      dt in floating point: booking the work with the amplitude at
//      t_{n+1} - dt instead of t_n lost half a step of work there (3e-3 of
//      the energy), fixed in CDLagrange::free_velocity();
//  (d) the same chain hitting a stop (restitution 0.5) under a sine base
//      acceleration: E1 with contact work.
// Every check prints value, reference and tolerance; returns non-zero on
// failure.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "test_tools.h"

#include <hati/base/mpi_environment.h>
#include <hati/loading/base_excitation.h>
#include <hati/model/discrete_system.h>
#include <hati/time/cd_lagrange.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace hati_unit_cd_lagrange_energy
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{

/**
 * A fixed-free chain along x: node 0 is fixed (condensed), nodes 1..N have
 * the lumped masses @p masses[i-1] (kg) and are joined by springs k (N/m).
 * The influence vector along x is 1 on the free nodes. mass_influence[0] is
 * the lumped mass plus @p support_inertia (kg) on node 1, as a model with a
 * consistent mass coupled to the support would give it: CD-Lagrange must
 * not use it (it uses -M_lumped r for base accelerations).
 */
void make_chain(DiscreteSystem &s,
                const std::vector<double> &masses,
                const double k,
                const double support_inertia)
{
  const unsigned int N = masses.size(), n = N + 1;
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
    s.stiffness.add(e, e, k);
    s.stiffness.add(e + 1, e + 1, k);
    s.stiffness.add(e, e + 1, -k);
    s.stiffness.add(e + 1, e, -k);
  }
  // condensed support: only the diagonal of node 0
  s.fixed[0] = true;
  s.stiffness.set(0, 1, 0.);
  s.stiffness.set(1, 0, 0.);
  s.lumped_mass[0] = 1.;
  for (unsigned int i = 1; i <= N; ++i)
    s.lumped_mass[i] = masses[i - 1];
  s.influence[0].reinit(n);
  s.mass_influence[0].reinit(n);
  for (unsigned int i = 1; i <= N; ++i)
  {
    s.influence[0][i] = 1.;
    s.mass_influence[0][i] = masses[i - 1];
  }
  s.mass_influence[0][1] += support_inertia;
}

/** A base acceleration a(t) along x with the model's shape -mass_influence. */
void add_base_acceleration(DiscreteSystem &s, const std::function<double(double)> &a)
{
  std::array<std::function<double(double)>, 3> acceleration;
  acceleration[0] = a;
  add_base_excitation(s, acceleration);
}

/** The largest of |kinetic|, |internal|, |external work|, |contact work|. */
double energy_scale(const Energies &e)
{
  return std::max({std::abs(e.kinetic),
                   std::abs(e.internal),
                   std::abs(e.external_work),
                   std::abs(e.contact_work)});
}

// (a), (b) one mass on a spring under a base acceleration: exact discrete
// solutions
void test_sdof()
{
  std::cout << "--- (a), (b) SDOF under a base acceleration: exact discrete solution"
            << std::endl;
  const double m = 2., k = 800., omega = std::sqrt(k / m); // 20 rad/s
  const double dt = 0.05 / omega;
  // discrete circular frequency of central differences: cos(Omega dt) = 1 -
  // (omega dt)^2 / 2
  const double Omega = std::acos(1. - 0.5 * omega * omega * dt * dt) / dt;
  const unsigned int n_steps = 2000; // about 16 periods
  {
    // (a) step a0 from t = 0: u_n = -a0 / omega^2 (1 - cos(Omega t_n)) solves
    // the recurrence with u_0 = 0 and u_1 = -a0 dt^2 / 2 (V_{1/2} = dt/2 F(0)/m)
    const double a0 = 3.;
    DiscreteSystem s;
    make_chain(s, {m}, k, 0.7 * m);
    add_base_acceleration(s, base_acceleration_step(Tensor<1, 3>({a0, 0., 0.}), 0.)[0]);
    CDLagrange cd(s, dt, 1.);
    const double amplitude = a0 / (omega * omega);
    double error = 0.;
    for (unsigned int i = 0; i < n_steps; ++i)
    {
      cd.step();
      const double u = -amplitude * (1. - std::cos(Omega * cd.time()));
      error = std::max(error, std::abs(cd.displacement()[1] - u));
    }
    // round-off of 2000 steps: 1e-11 of the static displacement a0 / omega^2
    // (with the model's shape, 1.7 m instead of m, the error would be 0.7
    // a0 / omega^2)
    check("(a) step: max |u_n + a0/omega^2 (1 - cos Omega t_n)| (m)",
          error,
          0.,
          1e-11 * amplitude);
  }
  {
    // (b) sine A sin(w t): u_n = B sin(w t_n) + C sin(Omega t_n), with
    // B = -A / (omega^2 - 4 sin^2(w dt / 2) / dt^2) (particular solution of
    // the recurrence) and C = -B sin(w dt) / sin(Omega dt) (u_0 = u_1 = 0,
    // since a(0) = 0)
    const double A = 1.5, w = 0.6 * omega;
    DiscreteSystem s;
    make_chain(s, {m}, k, 0.7 * m);
    add_base_acceleration(s, [A, w](const double t) { return A * std::sin(w * t); });
    CDLagrange cd(s, dt, 1.);
    const double B =
        -A / (omega * omega - 4. * std::pow(std::sin(0.5 * w * dt), 2) / (dt * dt));
    const double C = -B * std::sin(w * dt) / std::sin(Omega * dt);
    double error = 0., peak = 0., drift = 0., scale = 0.;
    const double e0 = cd.energies().total();
    for (unsigned int i = 0; i < n_steps; ++i)
    {
      cd.step();
      const double t = cd.time();
      const double u = B * std::sin(w * t) + C * std::sin(Omega * t);
      error = std::max(error, std::abs(cd.displacement()[1] - u));
      peak = std::max(peak, std::abs(u));
      const Energies e = cd.energies();
      drift = std::max(drift, std::abs(e.total() - e0));
      scale = std::max(scale, energy_scale(e));
    }
    // round-off: 1e-11 of the peak displacement (an amplitude taken at t_n
    // instead of t_{n+1} shifts the phase by dt: an error of w dt ~ 3e-2)
    check("(b) sine: max |u_n - B sin(w t_n) - C sin(Omega t_n)| (m)",
          error,
          0.,
          1e-11 * peak);
    // E1: round-off, 1e-12 of the largest energy of the run
    check("(b) sine: max |total(t) - total(0)| (J)", drift, 0., 1e-12 * scale);
  }
}

/** The loads of case (c): each returns the force F(t) the integrator applies. */
struct ChainLoads
{
  Vector<double> gravity_force; // constant: g M_lumped r
  Vector<double> base_shape;    // -M_lumped r
  Vector<double> tip_shape;     // unit force on the tip
  std::function<double(double)> sine, step, tip;

  void force(const double t, Vector<double> &f) const
  {
    f = gravity_force;
    f.add(sine(t) + step(t), base_shape);
    f.add(tip(t), tip_shape);
  }
};

/**
 * Run the chain of case (c) for @p n_steps steps; checks E1 and the external
 * work against the trapezoidal sum recomputed from @p loads.
 */
void run_chain_balance(DiscreteSystem &s,
                       const ChainLoads &loads,
                       const double dt,
                       const unsigned int n_steps,
                       const std::string &label)
{
  CDLagrange cd(s, dt, 0.9);
  const unsigned int n = s.n_dofs();
  const double e0 = cd.energies().total();
  Vector<double> u_old(cd.displacement()), du(n), f_old(n), f_new(n);
  loads.force(0., f_old);
  // x_trapezoid: sum 1/2 (F(t_j) + F(t_{j+1})) . (U_{j+1} - U_j) (E1);
  // x_rectangle: sum F(t_j) . (U_{j+1} - U_j), a wrong quadrature
  double x_trapezoid = 0., x_rectangle = 0.;
  double drift = 0., work_error = 0., rectangle_drift = 0., scale = 0.;
  for (unsigned int i = 0; i < n_steps; ++i)
  {
    cd.step();
    du = cd.displacement();
    du -= u_old;
    u_old = cd.displacement();
    loads.force(cd.time(), f_new);
    x_trapezoid += 0.5 * (f_old * du + f_new * du);
    x_rectangle += f_old * du;
    f_old = f_new;
    const Energies e = cd.energies();
    drift = std::max(drift, std::abs(e.total() - e0));
    work_error = std::max(work_error, std::abs(e.external_work - x_trapezoid));
    rectangle_drift = std::max(rectangle_drift,
                               std::abs(e.total() + e.external_work - x_rectangle - e0));
    scale = std::max(scale, energy_scale(e));
  }
  const Energies e = cd.energies();
  std::cout << "     " << label << ": largest energy " << scale << " J, external work "
            << e.external_work << " J, kinetic " << e.kinetic << " J, internal "
            << e.internal << " J" << std::endl;
  // the loads do work comparable to the largest energy (else the balance
  // below would hold trivially)
  expect(scale > 0. && std::abs(x_trapezoid) > 1e-3 * scale,
         label + ": the loads do work (|X| > 1e-3 of the largest energy)");
  // E1: round-off, 1e-12 of the largest energy of the run
  check(label + ": max |total(t) - total(0)| (J)", drift, 0., 1e-12 * scale);
  // external work = trapezoidal sum of the applied forces: 1e-12 of the scale
  check(label + ": max |external_work - sum 1/2 (F_j + F_j+1) . dU| (J)",
        work_error,
        0.,
        1e-12 * scale);
  // the same balance with the rectangle rule misses by O(dt) relative: far
  // more than the tolerance, so that the balance check discriminates
  expect(rectangle_drift > 1e3 * 1e-12 * scale,
         label + ": balance with a rectangle rule misses by " +
             std::to_string(rectangle_drift / scale) + " of the scale (> 1e-9)");
}

// (c) chain: energy balance under time-dependent loads
void test_chain_balance()
{
  std::cout << "--- (c) fixed-free chain: energy balance under time-dependent loads"
            << std::endl;
  const std::vector<double> masses{1., 1.3, 0.8, 1.1, 0.6};
  const double k = 1000.;
  // omega_max <= 2 sqrt(k / m_min) = 81.6 rad/s
  const double dt = 0.4 * 2. / (2. * std::sqrt(k / 0.6));
  const unsigned int n = masses.size() + 1;
  const double g = -9.81;
  // step starts: exactly on a time step j dt (as the integrator computes
  // t_j = j dt), with j such that (j + 1) dt - dt < j dt in floating point
  // (an amplitude at t_{n+1} - dt instead of t_n then misses the step), and
  // between two steps
  unsigned int j = 400;
  while ((j + 1) * dt - dt >= j * dt && j < 2500)
    ++j;
  std::cout << "     step on the time step j = " << j
            << ": (j + 1) dt - dt - j dt = " << (j + 1) * dt - dt - j * dt << " s"
            << std::endl;
  expect(j < 2500, "(c) a step time j dt with (j + 1) dt - dt < j dt exists (j < 2500)");
  for (const double step_start : {j * dt, 400.5 * dt})
  {
    DiscreteSystem s;
    make_chain(s, masses, k, 0.4);
    // gravity along x: the model's M r g, swapped by CD for M_lumped r g
    s.gravity[0] = g;
    s.constant_force.add(g, s.mass_influence[0]);
    ChainLoads loads;
    const double omega1 = 8.; // near the first mode of the chain
    loads.sine = [omega1](const double t) { return 2. * std::sin(omega1 * t); };
    loads.step = base_acceleration_step(Tensor<1, 3>({-4., 0., 0.}), step_start)[0];
    loads.tip = [](const double t) { return 5. * std::cos(13. * t) * std::exp(-t); };
    add_base_acceleration(s, loads.sine);
    add_base_acceleration(s, loads.step);
    loads.tip_shape.reinit(n);
    loads.tip_shape[n - 1] = 1.;
    s.time_dependent_loads.push_back({loads.tip_shape, loads.tip, -1});
    loads.gravity_force.reinit(n);
    loads.base_shape.reinit(n);
    for (unsigned int i = 1; i < n; ++i)
    {
      loads.gravity_force[i] = g * s.lumped_mass[i];
      loads.base_shape[i] = -s.lumped_mass[i];
    }
    std::ostringstream label;
    label << "(c) step at " << step_start / dt << " dt";
    run_chain_balance(s, loads, dt, 3000, label.str());
  }
}

// (d) chain hitting a stop under a base acceleration: E1 with contact work
void test_chain_contact()
{
  std::cout << "--- (d) chain against a stop, e = 0.5, under a sine base acceleration"
            << std::endl;
  const std::vector<double> masses{1., 1.3, 0.8, 1.1, 0.6};
  const double k = 1000., dt = 0.4 / std::sqrt(k / 0.6);
  const unsigned int n = masses.size() + 1;
  DiscreteSystem s;
  make_chain(s, masses, k, 0.4);
  add_base_acceleration(s, [](const double t) { return 20. * std::sin(8. * t); });
  // a stop 2 cm beyond the tip: g = 0.02 - u_tip >= 0
  ContactRow stop;
  stop.name = "stop";
  stop.dofs = {n - 1};
  stop.coefficients = {-1.};
  stop.initial_gap = 0.02;
  stop.restitution = 0.5;
  s.contacts.push_back(stop);
  CDLagrange cd(s, dt, 0.9);
  const double e0 = cd.energies().total();
  double drift = 0., scale = 0.;
  unsigned int impacts = 0;
  bool was_pushing = false;
  for (unsigned int i = 0; i < 5000; ++i)
  {
    cd.step();
    const Energies e = cd.energies();
    drift = std::max(drift, std::abs(e.total() - e0));
    scale = std::max(scale, energy_scale(e));
    const bool pushing = cd.impulses()[0] > 0.;
    impacts += (pushing && !was_pushing) ? 1 : 0;
    was_pushing = pushing;
  }
  const Energies e = cd.energies();
  std::cout << "     " << impacts << " impacts, contact work " << e.contact_work
            << " J, external work " << e.external_work << " J, largest energy " << scale
            << " J" << std::endl;
  // the scenario really has impacts that dissipate energy
  expect(impacts >= 3, "(d) at least 3 impacts on the stop");
  expect(e.contact_work < -1e-3 * scale,
         "(d) the impacts (e = 0.5) dissipate: contact work < -1e-3 of the scale");
  // E1: round-off, 1e-12 of the largest energy of the run
  check("(d) max |total(t) - total(0)| (J)", drift, 0., 1e-12 * scale);
}
} // namespace

HATI_UNIT_TEST(cd_lagrange_energy)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
  {
    test_sdof();
    test_chain_balance();
    test_chain_contact();
  }
  catch (const std::exception &e)
  {
    std::cout << "FAIL exception: " << e.what() << std::endl;
    return 1;
  }
  return finish();
}
} // namespace hati_unit_cd_lagrange_energy

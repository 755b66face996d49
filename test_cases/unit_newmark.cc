// Unit test of the implicit Newmark integrator (algorithms.md N1-N3), the
// static analysis and the modal analysis, on DiscreteSystem objects built by
// hand and checked against independent analytical results:
//  (a) undamped SDOF: discrete period of the average acceleration scheme,
//      tan(Omega DT/2) = omega DT/2, and energy conservation;
//  (b) damped SDOF (Rayleigh damping from a damping ratio): energy balance and
//      amplitude decay exp(-zeta omega t);
//  (c) fixed-free chain of springs and masses: static tip load, modes
//      (ARPACK and dense LAPACK paths), effective masses;
//  (d) free-free chain: the static analysis refuses it with a clear message;
//  (e) step force on the SDOF: mean F/k and peak 2F/k;
//  (f) the choice of the linear solver (auto: KLU below 20,000 DoFs).
// Every check prints value, reference and tolerance; returns non-zero on
// failure.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "test_tools.h"

#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/static_analysis.h>
#include <hati/base/mpi_environment.h>
#include <hati/linear_algebra/direct_solver.h>
#include <hati/model/discrete_system.h>
#include <hati/time/newmark.h>
#include <hati/time/rayleigh_damping.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace hati_unit_newmark
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{

/** One mass m (kg) on a spring k (N/m); influence along x. */
void make_sdof(DiscreteSystem &s, const double k, const double m)
{
  s.reinit(1);
  s.lumped_mass[0] = m;
  DynamicSparsityPattern dsp(1, 1);
  dsp.add(0, 0);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  s.stiffness.set(0, 0, k);
  s.influence[0].reinit(1);
  s.influence[0][0] = 1.;
}

/**
 * A chain of N equal springs k (N/m) between N + 1 nodes of mass m (kg),
 * along x. fixed_free: node 0 is fixed (condensed: only its diagonal), the
 * free nodes 1..N all carry m (the tip too). Otherwise all N + 1 nodes are
 * free (no supports). consistent: the mass is (also) given as a diagonal
 * matrix on the stiffness pattern, which the implicit code then uses.
 */
void make_chain(DiscreteSystem &s,
                const unsigned int N,
                const double k,
                const double m,
                const bool fixed_free,
                const bool consistent)
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
    s.stiffness.add(e, e, k);
    s.stiffness.add(e + 1, e + 1, k);
    s.stiffness.add(e, e + 1, -k);
    s.stiffness.add(e + 1, e, -k);
  }
  for (unsigned int i = 0; i < n; ++i)
    s.lumped_mass[i] = m;
  s.influence[0].reinit(n);
  for (unsigned int i = 0; i < n; ++i)
    s.influence[0][i] = 1.;
  if (fixed_free)
  {
    s.fixed[0] = true;
    s.influence[0][0] = 0.;
    s.stiffness.set(0, 1, 0.);
    s.stiffness.set(1, 0, 0.);
  }
  if (consistent)
  {
    s.consistent_mass.reinit(s.stiffness_pattern);
    for (unsigned int i = 0; i < n; ++i)
      s.consistent_mass.set(i, i, m);
  }
}

/** Relative drift max |total(t) - total(0)| / scale over @p n_steps steps. */
double energy_drift(Newmark &integrator, const unsigned int n_steps, const double scale)
{
  const double e0 = integrator.energies().total();
  double drift = 0.;
  for (unsigned int i = 0; i < n_steps; ++i)
  {
    integrator.step();
    drift = std::max(drift, std::abs(integrator.energies().total() - e0));
  }
  return drift / scale;
}

// (a) undamped SDOF: period and energy
void test_undamped_sdof()
{
  std::cout << "--- (a) undamped SDOF, average acceleration" << std::endl;
  const double k = 4. * M_PI * M_PI, m = 1.; // omega = 2 pi rad/s, T = 1 s
  const double omega = std::sqrt(k / m), T = 2. * M_PI / omega;
  for (const double omega_dt : {0.1, 0.3})
  {
    DiscreteSystem s;
    make_sdof(s, k, m);
    s.initial_displacement[0] = 1.;
    const double dt = omega_dt / omega;
    Newmark newmark(s, dt, NewmarkParameters(), RayleighDamping());
    // exact discrete frequency: tan(Omega DT / 2) = omega DT / 2, and the
    // discrete solution is exactly U_n = cos(Omega t_n)
    const double Omega = 2. / dt * std::atan(0.5 * omega_dt);
    const double T_discrete = 2. * M_PI / Omega;
    // about 300 periods; zero crossings interpolated linearly (error O(DT^3)
    // per crossing since cos'' = 0 at a crossing, divided by the number of
    // periods)
    const unsigned int n_steps = static_cast<unsigned int>(300. * T / dt);
    double first = -1., last = -1., previous = 1., max_error = 0.;
    unsigned int crossings = 0;
    for (unsigned int i = 0; i < n_steps; ++i)
    {
      newmark.step();
      const double u = newmark.displacement()[0];
      max_error = std::max(max_error, std::abs(u - std::cos(Omega * newmark.time())));
      if ((u > 0.) != (previous > 0.))
      {
        const double tc = newmark.time() - dt * u / (u - previous);
        if (first < 0.)
          first = tc;
        last = tc;
        ++crossings;
      }
      previous = u;
    }
    const double T_measured = 2. * (last - first) / (crossings - 1);
    std::ostringstream label;
    label << "omega DT = " << omega_dt;
    // round-off over ~19000 steps: 1e-9
    check(label.str() + ": max |U_n - cos(Omega t_n)|", max_error, 0., 1e-9);
    // relative 1e-6 on the measured period
    check(label.str() + ": measured period vs 2 pi / Omega (s)",
          T_measured,
          T_discrete,
          1e-6 * T_discrete);
    // period elongation (T_num - T)/T ~ (omega DT)^2 / 12: within 10 % of it
    const double elongation = (T_measured - T) / T;
    const double predicted = omega_dt * omega_dt / 12.;
    check(label.str() + ": period elongation (T_num - T)/T vs (omega DT)^2/12",
          elongation,
          predicted,
          0.1 * predicted);
  }
  {
    DiscreteSystem s;
    make_sdof(s, k, m);
    s.initial_displacement[0] = 1.;
    s.initial_velocity[0] = 0.7;
    Newmark newmark(s, 0.1 / omega, NewmarkParameters(), RayleighDamping());
    const double e0 = newmark.energies().total();
    check("energy 1/2 k U0^2 + 1/2 m V0^2 at t = 0 (J)",
          e0,
          0.5 * k + 0.5 * m * 0.49,
          1e-14 * e0);
    // total() constant to round-off: 1e-12 relative over 1000 steps
    check("undamped: relative drift of total energy over 1000 steps",
          energy_drift(newmark, 1000, e0),
          0.,
          1e-12);
    // M_eff = m + beta DT^2 k on the SDOF
    Vector<double> x(1), b(1);
    b[0] = 3.;
    newmark.solve_with_effective_matrix(x, b);
    const double dt = newmark.time_step();
    check("solve_with_effective_matrix: x = b / (m + DT^2 k / 4)",
          x[0],
          3. / (m + 0.25 * dt * dt * k),
          1e-14);
    expect(newmark.factorization_time() >= 0., "factorization_time() is available");
  }
}

// (b) damped SDOF
void test_damped_sdof()
{
  std::cout << "--- (b) damped SDOF, Rayleigh damping from a damping ratio" << std::endl;
  const double k = 4. * M_PI * M_PI, m = 1., omega = std::sqrt(k / m);
  const double zeta = 0.05;
  ParameterHandler prm;
  prm.enter_subsection("Damping");
  RayleighDamping::declare_parameters(prm);
  prm.leave_subsection();
  prm.parse_input_from_string("subsection Damping\n"
                              "  set Damping ratio = 0.05\n"
                              "  set First frequency = 1\n"
                              "  set Second frequency = 1\n"
                              "end\n");
  RayleighDamping damping;
  prm.enter_subsection("Damping");
  damping.parse_parameters(prm);
  prm.leave_subsection();
  // f1 = f2 = 1 Hz: a0 = zeta omega, a1 = zeta / omega
  check("a0 = zeta omega (1/s)", damping.a0, zeta * omega, 1e-14);
  check("a1 = zeta / omega (s)", damping.a1, zeta / omega, 1e-16);
  {
    bool thrown = false;
    ParameterHandler bad;
    RayleighDamping::declare_parameters(bad);
    bad.parse_input_from_string("set Damping ratio = 0.05\nset First frequency = 1\n"
                                "set Second frequency = 2\nset Mass coefficient = 1\n");
    RayleighDamping d;
    try
    {
      d.parse_parameters(bad);
    }
    catch (const std::exception &e)
    {
      thrown = message_of(e).find("not both") != std::string::npos;
    }
    expect(thrown, "damping ratio together with a coefficient is refused");
  }
  {
    bool thrown = false;
    ParameterHandler bad;
    NewmarkParameters::declare_parameters(bad);
    bad.parse_input_from_string("set Gamma = 0.4\n");
    NewmarkParameters p;
    try
    {
      p.parse_parameters(bad);
    }
    catch (const std::exception &e)
    {
      thrown = message_of(e).find("Gamma must be >= 0.5") != std::string::npos;
    }
    expect(thrown, "Gamma < 1/2 is refused");
  }

  DiscreteSystem s;
  make_sdof(s, k, m);
  s.initial_displacement[0] = 1.;
  const double dt = 0.01 / omega;
  Newmark newmark(s, dt, NewmarkParameters(), damping);
  const double e0 = newmark.energies().total();
  // peaks of U: successive maxima decay as exp(-zeta omega t) (the exact
  // response e^{-zeta omega t}(cos w_d t + zeta omega / w_d sin w_d t) has its
  // maxima on this envelope times the constant 1/sqrt(1 - zeta^2))
  const unsigned int n_steps = static_cast<unsigned int>(10. * 2. * M_PI / omega / dt);
  double u_prev2 = 1., u_prev = 1., drift = 0.;
  std::vector<std::pair<double, double>> peaks;
  for (unsigned int i = 0; i < n_steps; ++i)
  {
    newmark.step();
    const double u = newmark.displacement()[0];
    if (i >= 1 && u_prev > u_prev2 && u_prev >= u)
      peaks.emplace_back(newmark.time() - dt, u_prev);
    u_prev2 = u_prev;
    u_prev = u;
    drift = std::max(drift, std::abs(newmark.energies().total() - e0));
  }
  // energy balance to round-off (1e-12 relative to the initial energy)
  check("damped: relative drift of kinetic + internal + dissipated - external",
        drift / e0,
        0.,
        1e-12);
  const auto e = newmark.energies();
  expect(e.dissipated > 0.9 * e0, "damped: most of the energy is dissipated");
  expect(peaks.size() >= 8, "damped: at least 8 peaks");
  if (peaks.size() >= 8)
  {
    const double ratio = peaks[7].second / peaks[0].second;
    const double reference = std::exp(-zeta * omega * (peaks[7].first - peaks[0].first));
    // 2 % relative (DT = 0.01 / omega)
    check("damped: peak ratio U_max(8) / U_max(1) vs exp(-zeta omega dt)",
          ratio,
          reference,
          0.02 * reference);
  }
}

// (c) fixed-free chain: static and modal
void test_chain()
{
  std::cout << "--- (c) fixed-free chain of springs and masses" << std::endl;
  const unsigned int N = 10;
  const double k = 1000., m = 2., F = 10.;
  DiscreteSystem s;
  make_chain(s, N, k, m, true, false);
  s.constant_force[N] = F;
  Vector<double> u_direct, u_iterative;
  solve_static(s, 0., u_direct, "direct");
  solve_static(s, 0., u_iterative, "iterative");
  double error = 0., difference = 0.;
  for (unsigned int i = 0; i <= N; ++i)
  {
    error = std::max(error, std::abs(u_direct[i] - i * F / k));
    difference = std::max(difference, std::abs(u_direct[i] - u_iterative[i]));
  }
  // u_i = i F / k exactly: round-off, 1e-12 relative to the tip displacement
  check("static: max |u_i - i F/k| (m), direct", error, 0., 1e-12 * N * F / k);
  // direct vs iterative (CG tolerance 1e-12): 1e-8 relative
  check("static: max |u_direct - u_iterative| (m)", difference, 0., 1e-8 * N * F / k);

  // analytical frequencies of the fixed-free chain with N equal masses
  auto fixed_free_frequency = [&](const unsigned int j, const unsigned int n_masses)
  {
    return 2. * std::sqrt(k / m) *
           std::sin((2. * j - 1.) * M_PI / (2. * (2. * n_masses + 1.))) / (2. * M_PI);
  };
  for (const bool consistent : {false, true})
  {
    DiscreteSystem c;
    make_chain(c, N, k, m, true, consistent);
    // 4 modes of 10 free DoFs: ncv = 10, ARPACK path
    const ModalResult modes = compute_modes(c, 4);
    for (unsigned int j = 1; j <= 4; ++j)
    {
      std::ostringstream label;
      label << "ARPACK, " << (consistent ? "mass matrix" : "lumped mass") << ": f_" << j
            << " (Hz)";
      const double f = fixed_free_frequency(j, N);
      // 1e-8 relative
      check(label.str(), modes.frequencies[j - 1], f, 1e-8 * f);
    }
    double orthogonality = 0.;
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int b = 0; b < 4; ++b)
      {
        double mab = 0.;
        for (unsigned int i = 0; i <= N; ++i)
          mab += modes.modes[a][i] * m * modes.modes[b][i] * (i > 0 ? 1. : 0.);
        orthogonality = std::max(orthogonality, std::abs(mab - (a == b ? 1. : 0.)));
      }
    // mass-normalised and M-orthogonal to 1e-10
    check("ARPACK: max |phi_a.M phi_b - delta_ab|", orthogonality, 0., 1e-10);
  }
  {
    // a longer chain: 6 modes of 200 DoFs with ARPACK
    DiscreteSystem c;
    make_chain(c, 200, k, m, true, false);
    const ModalResult modes = compute_modes(c, 6);
    double worst = 0.;
    for (unsigned int j = 1; j <= 6; ++j)
      worst = std::max(
          worst, std::abs(modes.frequencies[j - 1] / fixed_free_frequency(j, 200) - 1.));
    // 1e-8 relative
    check("ARPACK, N = 200: max relative error of f_1..f_6", worst, 0., 1e-8);
  }
  {
    // free-free chain of 51 masses: a rigid mode (0 Hz), then
    // w_j = 2 sqrt(k/m) sin(j pi / (2 n)), n masses
    DiscreteSystem c;
    make_chain(c, 50, k, m, false, false);
    const ModalResult modes = compute_modes(c, 4);
    // the rigid mode: 0 Hz to 1e-6 Hz (its omega^2 is round-off)
    check("ARPACK, free-free: f_0 (Hz)", modes.frequencies[0], 0., 1e-6);
    for (unsigned int j = 1; j < 4; ++j)
    {
      const double f =
          2. * std::sqrt(k / m) * std::sin(j * M_PI / (2. * 51.)) / (2. * M_PI);
      std::ostringstream label;
      label << "ARPACK, free-free: f_" << j << " (Hz)";
      check(label.str(), modes.frequencies[j], f, 1e-8 * f);
    }
    // the rigid mode carries the whole mass along x
    check("free-free: effective mass of the rigid mode (kg)",
          modes.effective_mass[0][0],
          51. * m,
          1e-8 * 51. * m);
  }
  {
    // dense LAPACK fallback: a 3-DoF chain
    DiscreteSystem c;
    make_chain(c, 3, k, m, true, false);
    const ModalResult modes = compute_modes(c, 3);
    for (unsigned int j = 1; j <= 3; ++j)
    {
      std::ostringstream label;
      label << "dense LAPACK, 3-DoF chain: f_" << j << " (Hz)";
      const double f = fixed_free_frequency(j, 3);
      check(label.str(), modes.frequencies[j - 1], f, 1e-8 * f);
    }
  }
  {
    // sum of the effective masses of all modes = total mass N m
    DiscreteSystem c;
    make_chain(c, N, k, m, true, true);
    const ModalResult modes = compute_modes(c, N);
    double sum = 0.;
    for (const auto &e : modes.effective_mass)
      sum += e[0];
    check("total mass r.M r (kg)", modes.total_mass[0], N * m, 1e-12 * N * m);
    check("sum of the effective masses of all modes (kg)", sum, N * m, 1e-10 * N * m);
    for (unsigned int j = 1; j <= N; ++j)
    {
      const double f = fixed_free_frequency(j, N);
      if (std::abs(modes.frequencies[j - 1] - f) > 1e-8 * f)
        check("dense, all modes: f_j (Hz)", modes.frequencies[j - 1], f, 1e-8 * f);
    }
    bool thrown = false;
    try
    {
      compute_modes(c, N + 1);
    }
    catch (const std::exception &e)
    {
      thrown = message_of(e).find("free degrees of freedom") != std::string::npos;
    }
    expect(thrown, "more modes than free DoFs is refused");
  }
  {
    // Newmark on the chain: direct and iterative agree, mass matrix path,
    // energy conserved
    DiscreteSystem c;
    make_chain(c, N, k, m, true, true);
    for (unsigned int i = 1; i <= N; ++i)
      c.initial_displacement[i] = 0.01 * i;
    c.initial_velocity[N] = 0.5;
    c.initial_velocity[0] = 3.; // a fixed DoF: must be ignored
    NewmarkParameters direct, iterative, mumps;
    iterative.linear_solver = "iterative";
    mumps.linear_solver = "MUMPS";
    iterative.solver_tolerance = 1e-13;
    const double dt = 0.2 * std::sqrt(m / k);
    Newmark a(c, dt, direct, RayleighDamping());
    Newmark b(c, dt, iterative, RayleighDamping());
    Newmark f(c, dt, mumps, RayleighDamping());
    expect(a.linear_solver() == "KLU" && f.linear_solver() == "MUMPS",
           "chain: Newmark's solver resolved (auto: KLU; MUMPS)");
    const double e0 = a.energies().total();
    double drift = 0.;
    for (unsigned int i = 0; i < 500; ++i)
    {
      a.step();
      b.step();
      f.step();
      drift = std::max(drift, std::abs(a.energies().total() - e0));
    }
    Vector<double> d(a.displacement());
    d -= b.displacement();
    check("chain: Newmark direct vs iterative after 500 steps, max |dU| (m)",
          d.linfty_norm(),
          0.,
          1e-8 * a.displacement().linfty_norm());
    d = a.displacement();
    d -= f.displacement();
    check("chain: Newmark KLU vs MUMPS after 500 steps, max |dU| (m)",
          d.linfty_norm(),
          0.,
          1e-12 * a.displacement().linfty_norm());
    check("chain: relative drift of the total energy over 500 steps",
          drift / e0,
          0.,
          1e-12);
    check("chain: fixed DoF stays at zero", a.displacement()[0], 0., 0.);
  }
}

// (d) free-free chain: static analysis refused
void test_free_free_static()
{
  std::cout << "--- (d) free-free chain: singular stiffness" << std::endl;
  // k = 1000/3 and k < 0: spring stiffnesses k (1 + 0.37 sin e) of element e,
  // so that K is singular only up to round-off
  for (const double k : {1000., 1000. / 3., -1000. / 3.})
  {
    const std::string springs = k > 0. ? "k = " + std::to_string(k) : "varying k";
    for (const bool with_influence : {true, false})
      for (const std::string solver : {"direct", "MUMPS", "iterative"})
      {
        DiscreteSystem s;
        make_chain(s, 10, std::abs(k), 2., false, false);
        if (k < 0.)
          for (unsigned int e = 0; e < 10; ++e)
          {
            const double d = -0.37 * k * std::sin(e + 1.);
            s.stiffness.add(e, e, d);
            s.stiffness.add(e + 1, e + 1, d);
            s.stiffness.add(e, e + 1, -d);
            s.stiffness.add(e + 1, e, -d);
          }
        if (!with_influence)
          s.influence[0].reinit(0); // the factorisation itself must detect it
        s.constant_force[10] = 10.;
        std::string message;
        Vector<double> u;
        try
        {
          solve_static(s, 0., u, solver);
        }
        catch (const std::exception &e)
        {
          message = message_of(e);
        }
        std::cout << "     message: " << message << std::endl;
        expect(message.find("check the supports") != std::string::npos,
               "free-free chain, " + springs + ", " + solver +
                   (with_influence ? ", with" : ", without") +
                   " influence vector: exception mentions the supports");
      }
  }
}

// (e) step force on the SDOF
void test_step_force()
{
  std::cout << "--- (e) step force on the SDOF" << std::endl;
  const double k = 4. * M_PI * M_PI, m = 1., omega = std::sqrt(k / m), F = 3.;
  DiscreteSystem s;
  make_sdof(s, k, m);
  Vector<double> shape(1);
  shape[0] = F;
  s.time_dependent_loads.push_back(
      {shape, [](const double t) { return t >= 0. ? 1. : 0.; }});
  const double dt = 0.1 / omega;
  Newmark newmark(s, dt, NewmarkParameters(), RayleighDamping());
  // U = F/k (1 - cos omega t): 200 periods, so that the mean over the run is
  // F/k to about 1 / (2 pi 200)
  const unsigned int n_steps = static_cast<unsigned int>(200. * 2. * M_PI / omega / dt);
  double sum = 0., peak = 0.;
  for (unsigned int i = 0; i < n_steps; ++i)
  {
    newmark.step();
    sum += newmark.displacement()[0];
    peak = std::max(peak, newmark.displacement()[0]);
  }
  // 1 % relative
  check("step force: mean displacement (m) vs F/k", sum / n_steps, F / k, 0.01 * F / k);
  check("step force: peak displacement (m) vs 2F/k", peak, 2. * F / k, 0.01 * 2. * F / k);
  const auto e = newmark.energies();
  check("step force: total energy (J), external work = kinetic + internal",
        e.total(),
        0.,
        1e-12 * e.external_work);
}
// a point mass without stiffness and a model without mass or supports
void test_point_mass()
{
  std::cout << "--- point mass without stiffness, singular models" << std::endl;
  const double m = 2., F = 3.;
  DiscreteSystem s;
  s.reinit(1);
  s.lumped_mass[0] = m;
  s.constant_force[0] = F;
  s.initial_velocity[0] = 0.5;
  const double dt = 0.01;
  Newmark newmark(s, dt, NewmarkParameters(), RayleighDamping());
  for (unsigned int i = 0; i < 100; ++i)
    newmark.step();
  const double t = newmark.time();
  // constant acceleration: the trapezoidal rule is exact (round-off, 1e-13)
  check("point mass: U(t) = V0 t + F t^2 / (2m) (m)",
        newmark.displacement()[0],
        0.5 * t + 0.5 * F / m * t * t,
        1e-13);
  check("point mass: t after 100 steps (s)", t, 1., 1e-15);
  {
    std::string message;
    Vector<double> u;
    try
    {
      solve_static(s, 0., u);
    }
    catch (const std::exception &e)
    {
      message = message_of(e);
    }
    std::cout << "     message: " << message << std::endl;
    expect(message.find("check the supports") != std::string::npos,
           "static analysis of a point mass is refused");
  }
  {
    // a free DoF without mass and without stiffness
    DiscreteSystem z;
    make_chain(z, 3, 1000., 1., true, false);
    z.lumped_mass[3] = 0.;
    z.stiffness.set(3, 3, 0.);
    z.stiffness.set(2, 3, 0.);
    z.stiffness.set(3, 2, 0.);
    z.stiffness.add(2, 2, -1000.);
    std::string message;
    try
    {
      Newmark n(z, 0.01, NewmarkParameters(), RayleighDamping());
    }
    catch (const std::exception &e)
    {
      message = message_of(e);
    }
    std::cout << "     message: " << message << std::endl;
    expect(message.find("singular") != std::string::npos,
           "Newmark refuses a DoF without mass and stiffness");
  }
}

// (f) the linear solver a value of Time integration/Newmark/Linear solver picks
void test_linear_solver_choice()
{
  std::cout << "--- (f) choice of the linear solver" << std::endl;
  for (const std::string value : {"auto", "direct"})
  {
    expect(resolve_linear_solver(value, 19999) == "KLU" &&
               direct_solver_package(value, 19999) == "Amesos_Klu",
           value + " at 19999 DoFs: KLU");
    expect(resolve_linear_solver(value, 20000) == "MUMPS" &&
               direct_solver_package(value, 20000) == "Amesos_Mumps",
           value + " at 20000 DoFs: MUMPS");
    // a 3D continuum's rows (quadratic hexahedra: about 200 entries) from
    // 2000 DoFs, a frame's (about 20) not
    expect(resolve_linear_solver(value, 2000, 200.) == "MUMPS" &&
               direct_solver_package(value, 2000, 200.) == "Amesos_Mumps" &&
               resolve_linear_solver(value, 1999, 200.) == "KLU" &&
               resolve_linear_solver(value, 19999, 20.) == "KLU",
           value + ": 3D continua from 2000 DoFs, frames from 20000");
  }
  expect(resolve_linear_solver("KLU", 1000000) == "KLU" &&
             resolve_linear_solver("MUMPS", 10) == "MUMPS" &&
             direct_solver_package("MUMPS", 10) == "Amesos_Mumps",
         "KLU and MUMPS as named, whatever the size");
  expect(resolve_linear_solver("iterative", 10) == "iterative" &&
             direct_solver_package("iterative", 10) == "Amesos_Klu" &&
             direct_solver_package("iterative", 20000) == "Amesos_Mumps",
         "iterative: its factorisations as auto");
  std::string message;
  try
  {
    resolve_linear_solver("klu", 10);
  }
  catch (const std::exception &e)
  {
    message = message_of(e);
  }
  std::cout << "     message: " << message << std::endl;
  expect(message.find("Time integration/Newmark/Linear solver = klu") !=
             std::string::npos,
         "an unknown linear solver is refused naming the entry");
}
} // namespace

HATI_UNIT_TEST(newmark)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
  {
    test_undamped_sdof();
    test_damped_sdof();
    test_chain();
    test_free_free_static();
    test_step_force();
    test_point_mass();
    test_linear_solver_choice();
  }
  catch (const std::exception &e)
  {
    std::cout << "FAIL exception: " << e.what() << std::endl;
    return 1;
  }
  return finish();
}
} // namespace hati_unit_newmark

// Stability of the coupling (algorithms.md G3', doc/theory.md section 9):
// the spectral radius of one macro step of the real code path,
// HATICoupling::step(), applied to every unit state [U_E, dt V_E, U_I, DT V_I,
// DT^2 A_I, Lambda_n] of a small split frame with zero load (the method of the
// numpy prototype gc_frame.py, whose G3 interface problem gives 1.0006 to
// 1.064 on such a frame). The coupled scheme is stable when the radius is
// <= 1 + 1e-10 for every m; the frame is undamped, so the radius must also
// be 1 to 1e-8 (no artificial damping of the coupled modes either).
// The frame: the portal of parameter_files/portal_frame_split.prm (two
// portals joined by cross beams, column colA and beam beamAB explicit), with
// two elements a member, no gravity, no point masses on the interface nodes
// in one case and with them (owned by the explicit side) in the other.
// With frequency-range damping (A8 explicit, N4 implicit, xi = 5 % over
// 1-30 Hz, doc/theory.md G3' with memory variables) the memory variables of
// both parts join the state; within the A8 stable step (0.95 of it) the
// radius is still 1 to 1e-10 (the neutral interface-drift mode of velocity
// continuity, as the prototype gc_bar_damped_macro.py gives), the damped
// modes below; at 1.05 of it the radius is far above 1 (and 1 without
// damping at the same step).
#include "test_tools.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/base/mpi_environment.h>
#include <hati/model/decomposition.h>
#include <hati/model/model.h>
#include <hati/run/problem.h>
#include <hati/time/frequency_range_damping.h>
#include <hati/time/hati_coupling.h>

#include <cmath>
#include <complex>
#include <iostream>

namespace hati_unit_hati_stability
{

using namespace hati;

namespace
{
std::string frame_prm(const std::string &point_masses, const unsigned int n_elements)
{
  const std::string ne = std::to_string(n_elements);
  return "subsection Model\n"
         "  set Type = frame\n"
         "  subsection Frame\n"
         "    set Nodes = A0: 0, 0, 0; A1: 0, 0, 5; B0: 6, 0, 0; B1: 6, 0, 5; C0: 0, 4, "
         "0; "
         "C1: 0, 4, 5; D0: 6, 4, 0; D1: 6, 4, 5\n"
         "    set Materials = steel: 2.1e11, 0.3, 7850\n"
         "    set Sections = column: box, 0.3, 0.3, 0.01, 0.01; beam: box, 0.2, 0.4, "
         "0.008, "
         "0.012\n"
         "    set Members = colA: A0, A1, column, steel, " +
         ne + "; colB: B0, B1, column, steel, " + ne + "; colC: C0, C1, column, steel, " +
         ne + "; colD: D0, D1, column, steel, " + ne + "; beamAB: A1, B1, beam, steel, " +
         ne + "; beamCD: C1, D1, beam, steel, " + ne +
         "; crossAC: A1, C1, beam, steel, " + ne + "; crossBD: B1, D1, beam, steel, " +
         ne +
         "\n"
         "    set Supports = A0: clamped; B0: clamped; C0: clamped; D0: clamped\n"
         "    set Point masses = " +
         point_masses +
         "\n"
         "  end\n"
         "  subsection Decomposition\n"
         "    set Explicit members = colA, beamAB\n"
         "  end\n"
         "end\n"
         "subsection Loading\n"
         "  set Gravity = 0, 0, 0\n"
         "end\n";
}

/** Frequency-range damping with the branches @p b (none: undamped). */
DampingModel with_branches(const MaxwellBranches &b)
{
  return DampingModel{"frequency range", RayleighDamping(), b};
}

double spectral_radius(HATICoupling &coupling, double &smallest)
{
  const unsigned int N = coupling.state_size();
  LAPACKFullMatrix<double> G(N, N);
  Vector<double> x(N), y(N);
  for (unsigned int k = 0; k < N; ++k)
  {
    x = 0.;
    x[k] = 1.;
    coupling.set_state(x);
    coupling.step();
    coupling.get_state(y);
    for (unsigned int i = 0; i < N; ++i)
      G(i, k) = y[i];
  }
  G.compute_eigenvalues();
  double rho = 0.;
  smallest = 1e300;
  for (unsigned int i = 0; i < N; ++i)
  {
    rho = std::max(rho, std::abs(G.eigenvalue(i)));
    smallest = std::min(smallest, std::abs(G.eigenvalue(i)));
  }
  return rho;
}
/**
 * The largest eigenfrequency (rad/s) of the explicit subdomain @p system on
 * its own (free DoFs with mass, the interface free): the exact A8 stable
 * step is (2/omega_max)/sqrt(1 + sum alpha).
 */
double highest_frequency(const DiscreteSystem &system)
{
  std::vector<unsigned int> free;
  for (unsigned int i = 0; i < system.n_dofs(); ++i)
    if (!system.fixed[i] && system.lumped_mass[i] > 0.)
      free.push_back(i);
  LAPACKFullMatrix<double> A(free.size(), free.size());
  for (unsigned int a = 0; a < free.size(); ++a)
    for (unsigned int b = 0; b < free.size(); ++b)
      A(a, b) = system.stiffness.el(free[a], free[b]) /
                std::sqrt(system.lumped_mass[free[a]] * system.lumped_mass[free[b]]);
  A.compute_eigenvalues();
  double lambda = 0.;
  for (unsigned int i = 0; i < free.size(); ++i)
    lambda = std::max(lambda, A.eigenvalue(i).real());
  return std::sqrt(lambda);
}
} // namespace

HATI_UNIT_TEST(hati_stability)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unsigned int failures = 0;
  for (const std::string masses : {"", "A1: 500; B1: 500; C1: 500; D1: 500"})
  {
    ParameterHandler prm;
    Problem::declare_parameters(prm);
    prm.parse_input_from_string(frame_prm(masses, 2));
    // the one set-up path of hati (Problem), silent
    Problem problem(prm, ConditionalOStream(std::cout, false));
    problem.build_system();
    problem.decompose();
    const DiscreteSystem &system = problem.system;
    const Decomposition &decomposition = *problem.decomposition;
    const double dt_crit = 2. / decomposition.parts[0].system.highest_frequency_bound();
    std::cout << "frame (point masses: " << (masses.empty() ? "none" : masses)
              << "): explicit " << decomposition.parts[0].system.n_dofs()
              << " DoFs, implicit " << decomposition.parts[1].system.n_dofs()
              << " DoFs, interface " << decomposition.n_interface_dofs()
              << " DoFs, dt_crit " << dt_crit << " s" << std::endl;
    if (decomposition.n_interface_dofs() != 12)
    {
      std::cout << "FAIL interface DoFs: expected 12 (all six DoFs of A1 and B1)\n";
      ++failures;
    }
    for (const unsigned int m : {1u, 2u, 5u, 10u, 20u, 50u, 100u})
    {
      HATIParameters parameters;
      parameters.time_step_ratio = m;
      HATICoupling coupling(decomposition,
                            system.n_dofs(),
                            0.9 * dt_crit,
                            1.,
                            parameters,
                            NewmarkParameters());
      double smallest = 0.;
      const double rho = spectral_radius(coupling, smallest);
      const bool ok = rho <= 1. + 1e-10 && rho >= 1. - 1e-8;
      failures += ok ? 0 : 1;
      std::cout << (ok ? "ok   " : "FAIL ") << "m = " << m << ": spectral radius "
                << std::setprecision(15) << rho
                << " (limit 1 + 1e-10, undamped: >= 1 - 1e-8)" << std::setprecision(6)
                << std::endl;
    }
    // frequency-range damping: the memory variables in the state (G3')
    const MaxwellBranches branches = fit_maxwell_branches(0.05, 1., 30., 3).branches;
    // the exact A8 stable step of the explicit subdomain (the step check of
    // CD-Lagrange uses a bound of omega_max, about 20 % below it here)
    const double dt_a8_exact = 2. / highest_frequency(decomposition.parts[0].system) /
                               std::sqrt(1. + branches.alpha_sum());
    for (const unsigned int m : {1u, 2u, 5u, 10u})
    {
      HATIParameters parameters;
      parameters.time_step_ratio = m;
      HATICoupling coupling(decomposition,
                            system.n_dofs(),
                            0.95 * dt_a8_exact,
                            2., // above the check's bound of omega_max
                            parameters,
                            NewmarkParameters(),
                            with_branches(branches));
      double smallest = 0.;
      const double rho = spectral_radius(coupling, smallest);
      const bool ok = rho <= 1. + 1e-10 && rho >= 1. - 1e-10;
      failures += ok ? 0 : 1;
      std::cout << (ok ? "ok   " : "FAIL ") << "m = " << m
                << ", frequency-range damping (sum alpha " << branches.alpha_sum()
                << ", dt = 0.95 x the exact A8 step (2/omega_max)/sqrt(1 + sum alpha)): "
                   "spectral radius "
                << std::setprecision(15) << rho
                << " (expected 1 to 1e-10: the neutral interface-drift mode)"
                << std::setprecision(6) << std::endl;
    }
    // just above the exact A8 stable step (and well below the undamped
    // one): unstable, the memory variables are really in the explicit map;
    // undamped at the same step: radius 1
    for (const unsigned int m : {1u, 10u})
      for (const bool damped : {true, false})
      {
        HATIParameters parameters;
        parameters.time_step_ratio = m;
        HATICoupling coupling(decomposition,
                              system.n_dofs(),
                              1.05 * dt_a8_exact,
                              2., // above the check's bound of omega_max
                              parameters,
                              NewmarkParameters(),
                              with_branches(damped ? branches : MaxwellBranches()));
        double smallest = 0.;
        const double rho = spectral_radius(coupling, smallest);
        const bool ok = damped ? rho > 1.01 : std::abs(rho - 1.) <= 1e-10;
        failures += ok ? 0 : 1;
        std::cout << (ok ? "ok   " : "FAIL ") << "m = " << m << ", dt = 1.05 x the exact "
                  << "A8 step (2/omega_max)/sqrt(1 + sum alpha), "
                  << (damped ? "frequency-range damping" : "undamped")
                  << ": spectral radius " << std::setprecision(15) << rho
                  << (damped ? " (expected > 1.01: unstable above the A8 step)"
                             : " (expected 1 to 1e-10: within the undamped step)")
                  << std::setprecision(6) << std::endl;
      }
  }
  if (failures)
    std::cout << failures << " check(s) failed" << std::endl;
  else
    std::cout << "all checks passed" << std::endl;
  return failures == 0 ? 0 : 1;
}
} // namespace hati_unit_hati_stability

// Free decay in HATI with frequency-range damping (doc/theory.md A8 in the
// explicit part, N4 in the implicit part, G3' with the memory variables in
// the state), m = 10. The model: a steel cantilever column (box 0.3 x 0.3 x
// 0.01 m, 2 m) with a tip mass, its lower member implicit and its upper
// member (with the tip) explicit, set up through Problem like any run. The
// tip mass is chosen so the first mode lies at 1, 3.6, 6.2, 10 and 30 Hz
// (across the 1-30 Hz band of the fit, 2 %). The run starts from the static
// deflection under a lateral tip force (nearly the first mode) at rest; the
// logarithmic decrement of the tip displacement's peaks gives the damping
// ratio, the peaks' spacing the frequency. Reference: the fitted exact ratio
// MaxwellBranches::damping_ratio(f) at that frequency (the loss factor of
// the branches, doc/theory.md A8), within 5 % (the tolerance; the
// single-DoF CD-Lagrange and Newmark versions are in unit_maxwell_damping).
// Measured (m = 10 / m = 1): 1.016 / 1.016, 1.013 / 1.012, 1.014 / 1.014,
// 1.018 / 1.016 and 1.043 / 1.027 times the fitted ratio. The frequency is
// printed beside the lumped-mass one of the whole column (HATI's implicit
// part has the consistent mass, so its frequency is 2-7 % higher).
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include "test_tools.h"

#include <hati/base/mpi_environment.h>
#include <hati/model/decomposition.h>
#include <hati/model/model.h>
#include <hati/run/problem.h>
#include <hati/time/frequency_range_damping.h>
#include <hati/time/hati_coupling.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace hati_unit_hati_free_decay
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{
std::string column_prm(const double tip_mass)
{
  return "subsection Model\n"
         "  set Type = frame\n"
         "  subsection Frame\n"
         "    set Nodes = B: 0, 0, 0; M: 0, 0, 1; T: 0, 0, 2\n"
         "    set Materials = steel: 2.1e11, 0.3, 7850\n"
         "    set Sections = column: box, 0.3, 0.3, 0.01, 0.01\n"
         "    set Members = lower: B, M, column, steel, 2; upper: M, T, column, steel, "
         "2\n"
         "    set Supports = B: clamped\n"
         "    set Point masses = T: " +
         std::to_string(tip_mass) +
         "\n"
         "  end\n"
         "  subsection Decomposition\n"
         "    set Explicit members = upper\n"
         "  end\n"
         "end\n"
         "subsection Loading\n"
         "  set Gravity = 0, 0, 0\n"
         "end\n";
}

/** The DoF of component @p component at node @p node of the model. */
unsigned int find_dof(const Model &model,
                      const unsigned int n_dofs,
                      const std::string &node,
                      const std::string &component)
{
  for (unsigned int i = 0; i < n_dofs; ++i)
  {
    const DofDescription d = model.describe_dof(i);
    if (d.component == component && d.location == "node '" + node + "'")
      return i;
  }
  throw std::runtime_error("no DoF " + component + " at node " + node);
}

/** The free DoFs (not fixed, with mass) of @p s. */
std::vector<unsigned int> free_dofs(const DiscreteSystem &s)
{
  std::vector<unsigned int> free;
  for (unsigned int i = 0; i < s.n_dofs(); ++i)
    if (!s.fixed[i] && s.lumped_mass[i] > 0.)
      free.push_back(i);
  return free;
}

/** Lowest eigenfrequency (Hz) of K phi = omega^2 M_lumped phi. */
double lowest_frequency(const DiscreteSystem &s)
{
  const std::vector<unsigned int> free = free_dofs(s);
  LAPACKFullMatrix<double> A(free.size(), free.size());
  for (unsigned int a = 0; a < free.size(); ++a)
    for (unsigned int b = 0; b < free.size(); ++b)
      A(a, b) = s.stiffness.el(free[a], free[b]) /
                std::sqrt(s.lumped_mass[free[a]] * s.lumped_mass[free[b]]);
  A.compute_eigenvalues();
  double lambda = 1e300;
  for (unsigned int i = 0; i < free.size(); ++i)
    lambda = std::min(lambda, A.eigenvalue(i).real());
  return std::sqrt(lambda) / (2. * M_PI);
}

/** U = K^-1 F on the free DoFs, F = 1 kN along x at @p dof. */
void static_deflection(DiscreteSystem &s, const unsigned int dof)
{
  const std::vector<unsigned int> free = free_dofs(s);
  LAPACKFullMatrix<double> K(free.size(), free.size());
  Vector<double> f(free.size());
  for (unsigned int a = 0; a < free.size(); ++a)
  {
    for (unsigned int b = 0; b < free.size(); ++b)
      K(a, b) = s.stiffness.el(free[a], free[b]);
    f[a] = free[a] == dof ? 1e3 : 0.;
  }
  K.compute_lu_factorization();
  K.solve(f);
  s.initial_displacement = 0.;
  s.initial_velocity = 0.;
  for (unsigned int a = 0; a < free.size(); ++a)
    s.initial_displacement[free[a]] = f[a];
}

/**
 * Ratio (log decrement of the positive peaks, skipping the first two and
 * the last) and frequency (Hz, from the peaks' spacing) of @p u sampled
 * every @p dt.
 */
std::pair<double, double> decay(const std::vector<double> &u, const double dt)
{
  std::vector<unsigned int> peaks;
  for (unsigned int j = 1; j + 1 < u.size(); ++j)
    if (u[j] > u[j - 1] && u[j] >= u[j + 1] && u[j] > 0.)
      peaks.push_back(j);
  if (peaks.size() < 6)
    return {std::nan(""), std::nan("")};
  const unsigned int first = 2, last = peaks.size() - 2;
  const double n_periods = last - first;
  const double delta = std::log(u[peaks[first]] / u[peaks[last]]) / n_periods;
  return {delta / std::sqrt(4. * M_PI * M_PI + delta * delta),
          n_periods / ((peaks[last] - peaks[first]) * dt)};
}
} // namespace

HATI_UNIT_TEST(hati_free_decay)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MaxwellBranches b = fit_maxwell_branches(0.02, 1., 30., 3).branches;
  const double k_tip = 3. * 2.1e11 * (std::pow(0.3, 4) - std::pow(0.28, 4)) / 12. / 8.;
  const unsigned int m = 10;
  std::cout << "HATI (m = " << m << ") free decay of a cantilever's first mode, 2 % over "
            << "1-30 Hz\n    f (Hz)   lumped f    fitted xi   HATI xi" << std::endl;
  for (const double f : {1., 3.6, 6.2, 10., 30.})
  {
    const double omega = 2. * M_PI * f;
    // the tip mass that puts the first mode at f (less the column's share)
    const double tip_mass = std::max(10., k_tip / (omega * omega) - 0.24 * 182.);
    ParameterHandler prm;
    Problem::declare_parameters(prm);
    prm.parse_input_from_string(column_prm(tip_mass));
    Problem problem(prm, ConditionalOStream(std::cout, false));
    problem.build_system();
    const unsigned int tip = find_dof(*problem.model, problem.system.n_dofs(), "T", "ux");
    static_deflection(problem.system, tip);
    const double f_lumped = lowest_frequency(problem.system);
    problem.decompose();
    // the subdomains' initial state, as Problem::prepare_transient() copies it
    for (auto &part : problem.decomposition->parts)
      for (unsigned int i = 0; i < part.global_dofs.size(); ++i)
        part.system.initial_displacement[i] =
            problem.system.initial_displacement[part.global_dofs[i]];
    const Decomposition &decomposition = *problem.decomposition;
    const double dt = 0.5 * 2. / decomposition.parts[0].system.highest_frequency_bound() /
                      std::sqrt(1. + b.alpha_sum());
    HATIParameters parameters;
    parameters.time_step_ratio = m;
    HATICoupling coupling(decomposition,
                          problem.system.n_dofs(),
                          dt,
                          1.,
                          parameters,
                          NewmarkParameters(),
                          DampingModel{"frequency range", RayleighDamping(), b});
    const double DT = m * dt;
    const unsigned int n_steps = std::lround(40. / f_lumped / DT);
    std::vector<double> u{problem.system.initial_displacement[tip]};
    for (unsigned int i = 0; i < n_steps; ++i)
    {
      coupling.step();
      u.push_back(coupling.displacement()[tip]);
    }
    const auto [xi, f_hati] = decay(u, DT);
    const double reference = b.damping_ratio(f_hati);
    std::cout << "    " << std::setw(6) << f << "   " << std::setprecision(5) << f_lumped
              << "   " << f_hati << "    " << reference << "    " << xi << "   (tip mass "
              << tip_mass << " kg, dt " << dt << " s, " << n_steps << " macro steps)"
              << std::endl;
    check("f = " + std::to_string(f) + " Hz: HATI ratio / fitted ratio",
          xi / reference,
          1.,
          0.05);
  }
  return finish();
}
} // namespace hati_unit_hati_free_decay

// The Craig-Bampton reduction of HATI's implicit subdomain at set-up (C1,
// doc/theory.md 12.1): Problem::reduce_implicit_part().

#include <deal.II/base/exceptions.h>

#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/reduced_part.h>
#include <hati/base/messages.h>
#include <hati/run/problem.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hati
{
namespace
{
/** Modes compared at set-up: the first flexible free-interface ones. */
constexpr unsigned int checked_modes = 5;
/** A reduced frequency below this fraction of the cut-off is a rigid-body mode. */
constexpr double rigid_mode_fraction = 1e-3;
/** The cut-off should be at least this multiple of the damping band's top. */
constexpr double cutoff_over_damping_band = 3.;

/**
 * The frequency check of the reduction: the first checked_modes flexible
 * free-interface frequencies (Hz) of the reduced part (@p reduced) and of
 * the unreduced one (@p full, a shift-invert Lanczos run), printed on
 * @p out and returned as a summary.json object.
 */
SummaryValue frequency_check(const DiscreteSystem &full,
                             const ReducedImplicitPart &reduced,
                             const double cutoff,
                             const std::string &linear_solver,
                             const ConditionalOStream &out)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> all =
      reduced.reduction().frequencies(reduced.reduction().size());
  const unsigned int n_rigid = std::count_if(
      all.begin(), all.end(), [&](double f) { return f < rigid_mode_fraction * cutoff; });
  const unsigned int n_free = std::count(full.fixed.begin(), full.fixed.end(), false);
  const unsigned int n = std::min<unsigned int>(
      {checked_modes, static_cast<unsigned int>(all.size()) - n_rigid, n_free - n_rigid});
  SummaryValue check = SummaryValue::object();
  if (n == 0)
    return check;
  // shift-invert at a quarter of the first flexible reduced eigenvalue below
  // zero: the rigid-body modes come first, then the flexible ones. (At
  // compute_modes()'s tiny negative shift K - sigma M of a floating part is
  // nearly singular, and the Lanczos run of the 3D crane's girders did not
  // converge.)
  const double omega_1 = 2. * numbers::PI * all[n_rigid];
  const ModalProblem problem(full, false, nullptr, linear_solver, nullptr);
  const std::vector<Eigenpair> pairs =
      problem.modes_near(-0.25 * omega_1 * omega_1, n_rigid + n);
  std::vector<double> unreduced;
  for (const Eigenpair &pair : pairs)
    unreduced.push_back(std::sqrt(std::max(pair.lambda, 0.)) / (2. * numbers::PI));
  SummaryValue f_reduced = SummaryValue::list(), f_full = SummaryValue::list(),
               error = SummaryValue::list();
  out << "  reduction check, free-interface frequencies (Hz), reduced / unreduced "
         "implicit part:";
  for (unsigned int k = 0; k < n; ++k)
  {
    const double a = all[n_rigid + k], b = unreduced[n_rigid + k];
    f_reduced.push_back(a);
    f_full.push_back(b);
    error.push_back(a / b - 1.);
    out << (k ? ", " : " ") << std::setprecision(6) << a << " / " << b;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << " (" << n_rigid << " rigid-body modes; " << seconds << " s)" << std::endl;
  check.set("reduced", f_reduced);
  check.set("unreduced", f_full);
  check.set("relative_error", error);
  check.set("rigid_body_modes", n_rigid);
  return check;
}
} // namespace

void Problem::reduce_implicit_part()
{
  AssertThrow(decomposition, ExcInternalError());
  CraigBamptonSettings settings;
  settings.cutoff_frequency = decomposition_parameters.reduction_cutoff_frequency;
  settings.maximum_modes = decomposition_parameters.reduction_maximum_modes;
  settings.linear_solver = newmark_parameters.linear_solver;
  AssertThrow(newmark_parameters.mass == "consistent",
              ExcMessage("Model/Decomposition/Implicit reduction = Craig-Bampton reduces "
                         "with the consistent mass: set Time integration/Newmark/Mass = "
                         "consistent"));
  const DiscreteSystem &full = decomposition->parts[1].system;
  auto reduced =
      std::make_shared<ReducedImplicitPart>(full, decomposition->rows[1], settings);
  const CraigBamptonReduction &basis = reduced->reduction();
  const std::vector<double> &f = basis.fixed_interface_frequencies();
  const double highest = f.empty() ? 0. : f.back();
  out << "  implicit part reduced (Craig-Bampton): " << full.n_dofs() << " DoFs -> "
      << basis.size() << " coordinates, " << basis.n_boundary() << " boundary DoFs ("
      << reduced->n_point_load_rows() << " of point loads) and " << basis.n_modes()
      << " fixed-interface modes up to " << highest << " Hz (cut-off "
      << settings.cutoff_frequency << " Hz); set-up " << basis.set_up_time()
      << " s: constraint modes " << basis.set_up_phases()[0] << " s, modes "
      << basis.set_up_phases()[1] << " s (" << basis.lanczos_runs()
      << " Lanczos runs), reduced matrices " << basis.set_up_phases()[2] << " s"
      << std::endl;
  SummaryValue entry = SummaryValue::object();
  entry.set("modes", basis.n_modes());
  entry.set("boundary_dofs", basis.n_boundary());
  entry.set("cutoff_frequency", settings.cutoff_frequency);
  entry.set("highest_kept_frequency", highest);
  entry.set("set_up_time", basis.set_up_time());
  entry.set("set_up_time_constraint_modes", basis.set_up_phases()[0]);
  entry.set("set_up_time_modes", basis.set_up_phases()[1]);
  entry.set("set_up_time_reduced_matrices", basis.set_up_phases()[2]);
  entry.set("point_load_dofs", reduced->n_point_load_rows());
  entry.set("unreduced_dofs", full.n_dofs());
  try
  {
    entry.set("frequency_check",
              frequency_check(full,
                              *reduced,
                              settings.cutoff_frequency,
                              newmark_parameters.linear_solver,
                              out));
  }
  catch (const std::exception &e)
  {
    // a check, not a condition of the run: e.g. the Lanczos run of a
    // floating implicit part (its rigid-body modes) that does not converge
    warn("Model/Decomposition/Implicit reduction: the frequency check against the "
         "unreduced implicit part failed (" +
         one_line_message(e) + "); the run goes on without it");
  }
  const std::optional<double> ratio =
      decomposition_parameters.reduction_modal_damping_ratio;
  if (ratio)
  {
    reduced->set_modal_damping(*ratio);
    out << "  reduced part damped modally: ratio " << *ratio
        << " in each of its modes (Reduction modal damping ratio; the run's damping "
           "acts on the rest)"
        << std::endl;
  }
  entry.set("modal_damping_ratio", ratio ? SummaryValue(*ratio) : SummaryValue());
  initial_state_summary.emplace_back("reduction", entry);
  if (!ratio && damping.frequency_range() &&
      settings.cutoff_frequency < cutoff_over_damping_band * damping.upper_frequency)
  {
    std::ostringstream w;
    w << "Model/Decomposition/Reduction cutoff frequency = " << settings.cutoff_frequency
      << " Hz is below " << cutoff_over_damping_band
      << " times the upper frequency of the damping band (" << damping.upper_frequency
      << " Hz): the reduced part damps the modes it keeps only";
    warn(w.str());
  }
  decomposition->reduced = std::move(reduced);
}
} // namespace hati

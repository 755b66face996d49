#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <hati/analysis/static_analysis.h>
#include <hati/linear_algebra/direct_solver.h>
#include <hati/output/csv_file.h>
#include <hati/output/output_writer.h>
#include <hati/output/run_directory.h>
#include <hati/output/summary.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>
#include <hati/run/run_tools.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hati
{
namespace
{
/**
 * A static translation above this fraction of the model size gets a
 * warning: a linear analysis assumes small displacements.
 */
constexpr double large_translation = 0.1;
/**
 * Beyond these a linear static solution is not the structure's at all: a
 * translation larger than the model itself, or a rotation above 1 rad
 * (57 degrees; small-rotation theory takes sin(theta) = theta, 16 % off
 * there). Refused (summary.json "failed"), as a transient run that diverges.
 */
constexpr double invalid_translation = 1.;
constexpr double invalid_rotation = 1.; // rad

/**
 * Refuse the static solution @p U of @p problem if its largest rotation
 * passes invalid_rotation or its largest translation invalid_translation
 * times @p size (m); one line naming the DoF and its place.
 */
void check_validity(const Problem &problem, const Vector<double> &U, const double size)
{
  const DiscreteSystem &system = problem.system;
  types::global_dof_index t_max = U.size(), r_max = U.size();
  for (types::global_dof_index i = 0; i < U.size(); ++i)
  {
    if (system.fixed[i])
      continue;
    bool translation = false;
    for (unsigned int d = 0; d < 3; ++d)
      translation = translation || (system.influence[d].size() == U.size() &&
                                    system.influence[d][i] != 0.);
    types::global_dof_index &k = translation ? t_max : r_max;
    if (k == U.size() || std::abs(U[i]) > std::abs(U[k]))
      k = i;
  }
  const auto refuse = [&](const types::global_dof_index i, const std::string &bound)
  {
    const DofDescription d = problem.model->describe_dof(i);
    std::ostringstream s;
    s << "static analysis: the " << (d.rotation ? "rotation" : "translation")
      << (d.component.empty() ? "" : " " + d.component) << " = " << U[i]
      << (d.rotation ? " rad" : " m") << (d.location.empty() ? "" : " at " + d.location)
      << " (DoF " << i << ") exceeds " << bound
      << ": a linear (small-displacement) solution is not valid there (look for a "
         "load out of scale or a structure held too weakly)";
    AssertThrow(false, ExcMessage(s.str()));
  };
  if (r_max < U.size() && problem.model->describe_dof(r_max).rotation &&
      std::abs(U[r_max]) > invalid_rotation)
    refuse(r_max, "1 rad");
  if (t_max < U.size() && std::abs(U[t_max]) > invalid_translation * size)
  {
    std::ostringstream bound;
    bound << "the model size, " << size << " m";
    refuse(t_max, bound.str());
  }
}
} // namespace

void run_static_analysis(Problem &problem, RunDirectory &directory)
{
  const DiscreteSystem &system = problem.system;
  const auto start = std::chrono::steady_clock::now();
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  Vector<double> U, V(system.n_dofs());
  std::vector<double> forces;
  std::vector<std::array<double, 2>> tangent_forces;
  {
    TimerOutput::Scope scope(timer, "static solve");
    solve_static(system,
                 0.,
                 U,
                 problem.newmark_parameters.linear_solver,
                 false,
                 &forces,
                 &tangent_forces);
  }
  // a displacement beyond 1e3 model sizes is not a result (summary.json "failed")
  const Watchdog watchdog(*problem.model, system);
  watchdog.check_static(U);
  check_validity(problem, U, watchdog.model_size());
  const SummaryValue contact_entry = problem.report_static_contact_forces(forces);
  const SummaryValue friction_entry =
      problem.report_static_friction_forces(tangent_forces);
  OutputWriter writer(directory, system, *problem.model);
  OutputState s;
  s.time = 0.;
  s.displacement = &U;
  s.velocity = &V;
  // contacts.csv: the static contact forces (no impulses, no motion); with
  // friction the sticking state of the loaded frictional contacts (A9)
  const bool friction = has_friction(system.contacts);
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
  {
    const ContactRow &c = system.contacts[k];
    const double force = k < forces.size() ? forces[k] : 0.;
    s.gaps.push_back(c.initial_gap + c.apply(U));
    s.normal_velocities.push_back(0.);
    s.impulses.push_back(0.);
    s.forces.push_back(force);
    s.active.push_back(force > 0.);
    if (friction)
    {
      s.tangential_impulses.insert(s.tangential_impulses.end(), 2, 0.);
      s.slip_velocities.push_back(0.);
      s.friction_states.push_back(c.frictional() && force > 0. ? FrictionState::stick
                                                               : FrictionState::open);
    }
  }
  writer.write_history(s);
  writer.write_vtu(s);
  writer.finish();

  std::cout << "  static analysis (K U = F_ext(0), "
            << resolve_linear_solver(problem.newmark_parameters.linear_solver,
                                     system.n_dofs(),
                                     system.stiffness_row_length())
            << " solver):\n";
  for (const auto &m : system.monitors)
  {
    std::cout << "    " << m.name << ":";
    for (unsigned int i = 0; i < m.dofs.size(); ++i)
      std::cout << "  u" << m.labels[i] << " = " << std::setprecision(8) << m.value(i, U);
    std::cout << std::endl;
  }
  double umax = 0.;
  for (unsigned int d = 0; d < 3; ++d)
    for (unsigned int i = 0; i < system.influence[d].size(); ++i)
      if (system.influence[d][i] != 0.)
        umax = std::max(umax, std::abs(U[i]));
  // beyond a tenth of the model size a linear (small-displacement) solution
  // is no longer the structure's: said, not refused
  if (umax > large_translation * watchdog.model_size())
  {
    std::ostringstream s;
    s << "the largest translation, " << umax << " m, is " << std::setprecision(3)
      << 100. * umax / watchdog.model_size() << " % of the model size ("
      << watchdog.model_size()
      << " m): the static analysis is linear (small displacements), so this is "
         "outside its validity; check the loads, sections and supports";
    problem.warn(s.str());
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SummaryEntries summary = {{"analysis", "static"},
                            {"model", problem.model->description()},
                            {"n_dofs", system.n_dofs()},
                            {"max_translation", umax},
                            {"wall_time", wall}};
  if (contact_entry.kind() != SummaryValue::Kind::null)
    summary.emplace_back("static_contact_forces", contact_entry);
  if (friction_entry.kind() != SummaryValue::Kind::null)
    summary.emplace_back("static_friction_forces", friction_entry);
  if (!system.ropes.empty())
    summary.emplace_back("static_rope_tension", problem.report_rope_tensions(U));
  for (const auto &entry : problem.model->summary_entries(problem.static_contact_forces))
    summary.push_back(entry);
  write_summary(directory.path() + "/summary.json", summary, problem.warnings);
  std::cout << problem.model->results_table();
  std::cout << "  largest translation " << umax << " m; results in " << directory.path()
            << "/ (history.csv, solution.pvd, summary.json)" << std::endl;
  timer.print_summary();
}
} // namespace hati

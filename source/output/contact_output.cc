#include <hati/output/contact_output.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace hati
{
std::vector<double> initial_gaps(const DiscreteSystem &system)
{
  std::vector<double> gaps;
  for (const auto &c : system.contacts)
    gaps.push_back(c.initial_gap + c.apply(system.initial_displacement));
  return gaps;
}

ContactOutput::ContactOutput(const LawOutputContext &context,
                             const FrictionalContacts &friction)
    : context(context), friction(friction.any() ? &friction : nullptr),
      // the window of the mean contact forces: Output/Contact force window,
      // at most the End time (as its documentation says: a longer window
      // would only hold the whole run, and 1e20 s overflowed its count of
      // steps)
      statistics(context.system.contacts,
                 initial_gaps(context.system),
                 std::min(context.parameters.contact_force_window, context.end_time))
{
}

void ContactOutput::add_step(const LawSample &sample, const double dt)
{
  statistics.add_step(sample.time, dt, sample.impulses);
  if (friction)
    statistics.add_friction_step(
        sample.time, dt, sample.tangential_impulses, sample.slip_velocities);
}

void ContactOutput::finish(SummaryEntries &summary,
                           std::ostream &out,
                           const LawOutputTimes &times)
{
  summary.emplace_back("wall_time_contacts", times.rows);
  summary.emplace_back("wall_time_contact_statistics", times.outputs);
  if (friction)
  {
    // the nonsmooth Gauss-Seidel of the frictional clusters (A9): never silent
    summary.emplace_back("friction_iterations_max", friction->max_sweeps());
    summary.emplace_back("friction_unconverged", friction->unconverged());
    if (friction->unconverged() > 0)
      context.warn("Coulomb friction: " + std::to_string(friction->unconverged()) +
                   " contact cluster solutions did not converge to the relative "
                   "tolerance 1e-10 (nonsmooth Gauss-Seidel, at most 1000 sweeps); "
                   "their impulses are the last iterate");
  }
  summary.emplace_back("contacts", statistics.json());
  summary.emplace_back("contact_force_window", context.parameters.contact_force_window);
  const auto wheels = context.model.wheel_contacts();
  if (!wheels.empty())
    summary.emplace_back("wheels", statistics.json(wheels));
  // replaced atomically: never a part of it
  std::ostringstream episodes;
  statistics.write_episodes(episodes);
  context.directory.replace("contact_episodes.csv", episodes.str(), true);
  statistics.print_table(out);
}
} // namespace hati

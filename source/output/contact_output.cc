#include <hati/output/contact_output.h>
#include <hati/output/csv_file.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
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
  statistics.add_step(sample.time, dt, sample.impulses, sample.gaps);
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
    summary.emplace_back("wheels", wheels_json());
  // replaced atomically: never a part of it
  std::ostringstream episodes;
  statistics.write_episodes(episodes);
  context.directory.replace("contact_episodes.csv", episodes.str(), true);
  statistics.print_table(out);
  const auto loads = runway_loads();
  if (!loads.empty())
  {
    std::ostringstream csv;
    csv << "wheel,vertical_max,vertical_max_time,vertical_min,vertical_min_time,"
           "lateral_max,lateral_max_time,longitudinal_max,longitudinal_max_time\n";
    use_shortest_numbers(csv);
    out << "  runway loads (N, the largest and smallest mean over "
        << context.parameters.contact_force_window
        << " s; runway_loads.csv):\n"
           "          wheel  vertical max    at t (s)  vertical min    at t (s)   "
           "lateral max    at t (s)  longitudinal max    at t (s)\n";
    for (const RunwayLoad &l : loads)
    {
      csv << l.wheel;
      out << "    " << std::setw(11) << l.wheel;
      for (unsigned int k = 0; k < 4; ++k)
      {
        csv << ',' << l.value[k] << ',' << l.time[k];
        out << std::setw(k == 3 ? 18 : 14) << std::setprecision(6) << l.value[k]
            << std::setw(12) << l.time[k];
      }
      csv << '\n';
      out << '\n';
    }
    context.directory.replace("runway_loads.csv", csv.str(), true);
  }
}

std::vector<ContactOutput::RunwayLoad> ContactOutput::runway_loads() const
{
  std::vector<RunwayLoad> loads;
  if (!statistics.has_force_window())
    return loads; // the loads are windowed means
  for (const Model::RunwayWheel &wheel : context.model.runway_wheels())
  {
    const auto *vertical = statistics.entry(wheel.name);
    if (vertical == nullptr)
      continue;
    const auto *lateral = statistics.entry(wheel.lateral_contact);
    const int t = wheel.longitudinal_tangent;
    RunwayLoad l;
    l.wheel = wheel.name;
    l.value = {{vertical->peak_mean_force,
                vertical->min_mean_force,
                lateral ? lateral->peak_mean_force : 0.,
                t >= 0 ? vertical->peak_tangent_force[t] : 0.}};
    l.time = {{vertical->peak_mean_force_time,
               vertical->min_mean_force_time,
               lateral ? lateral->peak_mean_force_time : 0.,
               t >= 0 ? vertical->peak_tangent_force_time[t] : 0.}};
    loads.push_back(l);
  }
  return loads;
}

SummaryValue ContactOutput::wheels_json() const
{
  const auto wheels = context.model.wheel_contacts();
  const auto laterals = context.model.wheel_lateral_contacts();
  const auto loads = runway_loads();
  SummaryValue result = SummaryValue::object();
  for (unsigned int w = 0; w < wheels.size(); ++w)
  {
    const SummaryValue one = statistics.json({wheels[w]});
    if (one.members().empty())
      continue;
    SummaryValue entry = one.members()[0].second;
    // the lateral offset between the flanges (the lateral contact's max_offset)
    if (w < laterals.size())
      if (const auto *lateral = statistics.entry(laterals[w]))
        entry.set("max_lateral_offset", lateral->max_offset)
            .set("max_lateral_offset_time", lateral->max_offset_time);
    for (const RunwayLoad &l : loads)
      if (l.wheel == wheels[w])
      {
        static const char *const names[4] = {
            "vertical_max", "vertical_min", "lateral_max", "longitudinal_max"};
        SummaryValue load = SummaryValue::object();
        for (unsigned int k = 0; k < 4; ++k)
          load.set(names[k], l.value[k]).set(std::string(names[k]) + "_time", l.time[k]);
        entry.set("runway_load", std::move(load));
      }
    result.set(wheels[w], std::move(entry));
  }
  return result;
}
} // namespace hati

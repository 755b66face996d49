#include <hati/output/reaction_peaks.h>

#include <algorithm>
#include <iomanip>

namespace hati
{
Registry<PostprocessorFactory>::Entry ReactionPeaks::registration()
{
  return {"reaction springs",
          "largest and smallest force of every reaction spring (runway_reaction)",
          {},
          [](const PostprocessorInputs &inputs) -> std::unique_ptr<Postprocessor>
          {
            if (inputs.system.reaction_springs.empty())
              return nullptr;
            return std::make_unique<ReactionPeaks>(inputs);
          }};
}

ReactionPeaks::ReactionPeaks(const PostprocessorInputs &inputs)
    : system(inputs.system), peaks(system.reaction_springs.size())
{
  for (const ReactionSpring &spring : system.reaction_springs)
  {
    unsigned int k = 0;
    while (k < system.monitors.size() && system.monitors[k].name != spring.monitor)
      ++k;
    AssertThrow(k < system.monitors.size() &&
                    spring.component < system.monitors[k].dofs.size(),
                ExcMessage("reaction spring " + spring.name + ": no monitor point " +
                           spring.monitor));
    monitor_of.push_back(k);
  }
}

void ReactionPeaks::history_row(const OutputState &s)
{
  for (unsigned int k = 0; k < peaks.size(); ++k)
  {
    const ReactionSpring &spring = system.reaction_springs[k];
    const double f =
        spring.sign * spring.stiffness *
        system.monitors[monitor_of[k]].value(spring.component, *s.displacement);
    Peak &p = peaks[k];
    if (!p.any || f > p.max)
    {
      p.max = f;
      p.max_time = s.time;
    }
    if (!p.any || f < p.min)
    {
      p.min = f;
      p.min_time = s.time;
    }
    p.any = true;
  }
}

void ReactionPeaks::finish(SummaryEntries &summary, std::ostream &out) const
{
  // one entry per group, one object per name, one per direction
  std::vector<std::string> groups;
  for (const ReactionSpring &spring : system.reaction_springs)
    if (std::find(groups.begin(), groups.end(), spring.group) == groups.end())
      groups.push_back(spring.group);
  const auto flags = out.flags();
  const auto precision = out.precision();
  for (const std::string &group : groups)
  {
    out << "  " << group << " (N, spring forces at the history rows):\n"
        << "    " << std::setw(16) << "name" << std::setw(14) << "direction"
        << std::setw(14) << "max" << std::setw(11) << "at t (s)" << std::setw(14) << "min"
        << std::setw(11) << "at t (s)" << '\n';
    SummaryValue entry = SummaryValue::object();
    std::vector<std::string> names;
    for (const ReactionSpring &spring : system.reaction_springs)
      if (spring.group == group &&
          std::find(names.begin(), names.end(), spring.name) == names.end())
        names.push_back(spring.name);
    for (const std::string &name : names)
    {
      SummaryValue directions = SummaryValue::object();
      for (unsigned int k = 0; k < peaks.size(); ++k)
      {
        const ReactionSpring &spring = system.reaction_springs[k];
        if (spring.group != group || spring.name != name)
          continue;
        const Peak &p = peaks[k];
        directions.set(spring.direction,
                       SummaryValue::object()
                           .set("max", p.max)
                           .set("max_time", p.max_time)
                           .set("min", p.min)
                           .set("min_time", p.min_time));
        out << "    " << std::setw(16) << name << std::setw(14) << spring.direction
            << std::setprecision(6) << std::setw(14) << p.max << std::setw(11)
            << p.max_time << std::setw(14) << p.min << std::setw(11) << p.min_time
            << '\n';
      }
      entry.set(name, std::move(directions));
    }
    summary.emplace_back(group, std::move(entry));
  }
  out.flags(flags);
  out.precision(precision);
}
} // namespace hati

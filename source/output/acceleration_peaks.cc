#include <hati/output/acceleration_peaks.h>

#include <cmath>
#include <iomanip>

namespace hati
{
Registry<PostprocessorFactory>::Entry AccelerationPeaks::registration()
{
  return {
      "absolute accelerations",
      "largest absolute acceleration of every monitor point (max_absolute_acceleration)",
      {},
      [](const PostprocessorInputs &inputs) -> std::unique_ptr<Postprocessor>
      {
        if (inputs.system.monitors.empty())
          return nullptr;
        return std::make_unique<AccelerationPeaks>(inputs);
      }};
}

AccelerationPeaks::AccelerationPeaks(const PostprocessorInputs &inputs)
    : system(inputs.system), ground(inputs.ground_acceleration),
      peaks(system.monitors.size()), last_velocity(system.monitors.size())
{
}

void AccelerationPeaks::history_row(const OutputState &s)
{
  for (unsigned int k = 0; k < system.monitors.size(); ++k)
  {
    const auto &m = system.monitors[k];
    std::vector<double> &last = last_velocity[k];
    last.resize(m.dofs.size());
    double a2 = 0.;
    for (unsigned int i = 0; i < m.dofs.size(); ++i)
    {
      // translations only: a frame monitor's rotations (rx, ry, rz, rad/s^2)
      // are not part of the acceleration (m/s^2)
      const std::string &label = m.labels[i];
      if (label != "x" && label != "y" && label != "z")
        continue;
      const double v = m.value(i, *s.velocity);
      if (have_last && s.time > last_time)
      {
        const unsigned int d = label == "x" ? 0 : label == "y" ? 1 : 2;
        const double a = (v - last[i]) / (s.time - last_time) +
                         (ground[d] ? ground[d](0.5 * (s.time + last_time)) : 0.);
        a2 += a * a;
      }
      last[i] = v;
    }
    if (std::sqrt(a2) > peaks[k].first)
      peaks[k] = {std::sqrt(a2), s.time};
  }
  last_time = s.time;
  have_last = true;
}

void AccelerationPeaks::finish(SummaryEntries &summary, std::ostream &out) const
{
  SummaryValue json = SummaryValue::object();
  out << "  largest absolute acceleration of the monitor points (m/s^2, between "
         "history rows):\n";
  for (unsigned int k = 0; k < system.monitors.size(); ++k)
  {
    json.set(
        system.monitors[k].name,
        SummaryValue::object().set("value", peaks[k].first).set("time", peaks[k].second));
    out << "    " << std::setw(12) << system.monitors[k].name << std::setw(14)
        << peaks[k].first << " at t = " << peaks[k].second << " s\n";
  }
  summary.emplace_back("max_absolute_acceleration", json);
}
} // namespace hati

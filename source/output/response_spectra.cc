#include <deal.II/base/exceptions.h>

#include <hati/output/csv_file.h>
#include <hati/output/response_spectra.h>
#include <hati/output/response_spectrum.h>

#include <algorithm>
#include <sstream>

namespace hati
{
Registry<PostprocessorFactory>::Entry ResponseSpectra::registration()
{
  return {"response spectra",
          "pseudo-acceleration response spectra of the Output/Spectra monitor points and "
          "of the base excitation (spectra.csv)",
          {},
          [](const PostprocessorInputs &inputs) -> std::unique_ptr<Postprocessor>
          {
            if (inputs.output.spectra.empty())
              return nullptr;
            return std::make_unique<ResponseSpectra>(inputs);
          }};
}

void ResponseSpectra::check_request(const OutputParameters &output,
                                    const DiscreteSystem &system,
                                    const double row_interval)
{
  if (output.spectra.empty())
    return;
  for (const auto &name : output.spectra)
    if (std::none_of(system.monitors.begin(),
                     system.monitors.end(),
                     [&](const MonitorPoint &m) { return m.name == name; }))
    {
      std::string known;
      for (const auto &m : system.monitors)
        known += (known.empty() ? "" : ", ") + m.name;
      AssertThrow(false,
                  ExcMessage("Output/Spectra: no monitor point '" + name +
                             "' in the model (its monitor points: " +
                             (known.empty() ? "none" : known) + ")"));
    }
  const double shortest = output.spectrum_periods.front();
  if (row_interval > 0.1 * shortest * (1. + 1e-12))
  {
    std::ostringstream s;
    s << "Output/Spectra: the history rows are " << row_interval
      << " s apart (Output/History interval), more than a tenth of the shortest period "
      << shortest << " s (Output/Spectrum periods): the spectrum would miss its peaks; "
      << "set Output/History interval <= " << 0.1 * shortest << " s";
    AssertThrow(false, ExcMessage(s.str()));
  }
}

ResponseSpectra::ResponseSpectra(const PostprocessorInputs &inputs)
    : ground(inputs.ground_acceleration),
      damping_ratios(inputs.output.spectrum_damping_ratios),
      periods(inputs.output.spectrum_periods)
{
  for (const auto &name : inputs.output.spectra)
    for (const auto &m : inputs.system.monitors)
      if (m.name == name)
        for (unsigned int i = 0; i < m.labels.size(); ++i)
          for (unsigned int d = 0; d < 3; ++d)
            if (m.labels[i] == std::string(1, "xyz"[d]))
            {
              Channel c;
              c.name = m.name + "." + m.labels[i];
              c.monitor = &m;
              c.component = i;
              c.axis = d;
              channels.push_back(c);
            }
  for (unsigned int d = 0; d < 3; ++d)
    if (ground[d])
    {
      Channel c;
      c.name = std::string("ground.") + "xyz"[d];
      c.axis = d;
      c.ground = true;
      channels.push_back(c);
    }
}

void ResponseSpectra::history_row(const OutputState &s)
{
  const bool interval = have_last && s.time > last_time;
  const double middle = 0.5 * (s.time + last_time);
  if (interval)
    times.push_back(middle);
  for (auto &c : channels)
  {
    const double a_g = ground[c.axis] ? ground[c.axis](middle) : 0.;
    if (c.ground)
    {
      if (interval)
        c.values.push_back(a_g);
      continue;
    }
    const double v = c.monitor->value(c.component, *s.velocity);
    if (interval)
      c.values.push_back((v - c.last_velocity) / (s.time - last_time) + a_g);
    c.last_velocity = v;
  }
  last_time = s.time;
  have_last = true;
}

void ResponseSpectra::finish(SummaryEntries &, std::ostream &out) const
{
  out << "  response spectra (pseudo-acceleration, " << damping_ratios.size()
      << " damping ratios, " << periods.size() << " periods from " << periods.front()
      << " s to " << periods.back() << " s) of";
  for (const auto &c : channels)
    out << ' ' << c.name;
  out << ": spectra.csv\n";
}

void ResponseSpectra::write_files(RunDirectory &directory) const
{
  std::vector<std::vector<double>> spectra; // per ratio and channel
  for (const double xi : damping_ratios)
    for (const auto &c : channels)
      spectra.push_back(pseudo_acceleration_spectrum(times, c.values, periods, xi));
  std::string csv = "damping_ratio,period";
  for (const auto &c : channels)
    csv += "," + c.name;
  csv += '\n';
  for (unsigned int r = 0; r < damping_ratios.size(); ++r)
    for (unsigned int k = 0; k < periods.size(); ++k)
    {
      append_number(csv, damping_ratios[r]);
      csv += ',';
      append_number(csv, periods[k]);
      for (unsigned int c = 0; c < channels.size(); ++c)
      {
        csv += ',';
        append_number(csv, spectra[r * channels.size() + c][k]);
      }
      csv += '\n';
    }
  directory.replace("spectra.csv", csv, true);
}
} // namespace hati

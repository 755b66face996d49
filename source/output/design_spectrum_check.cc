#include <deal.II/base/exceptions.h>

#include <hati/loading/accelerogram.h>
#include <hati/loading/design_spectrum.h>
#include <hati/output/csv_file.h>
#include <hati/output/design_spectrum_check.h>
#include <hati/output/response_spectrum.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace hati
{
ComponentSpectrumCheck check_component(const std::vector<double> &periods,
                                       const std::vector<std::vector<double>> &spectra,
                                       const std::vector<double> &pgas,
                                       const std::vector<double> &target,
                                       const double target_pga)
{
  AssertThrow(!spectra.empty() && spectra.size() == pgas.size() &&
                  target.size() == periods.size() && !periods.empty(),
              dealii::ExcMessage("design spectrum check: no records to check"));
  ComponentSpectrumCheck c;
  c.periods = periods;
  c.target = target;
  c.n_records = spectra.size();
  c.enough_records = c.n_records >= min_ec8_records;
  for (std::size_t j = 0; j < periods.size(); ++j)
  {
    double sum = 0.;
    for (const auto &s : spectra)
      sum += s[j];
    const double value = sum / spectra.size();
    c.statistic.push_back(value);
    c.ratio.push_back(value / target[j]);
  }
  const auto lowest = std::min_element(c.ratio.begin(), c.ratio.end());
  c.min_ratio = *lowest;
  c.period_of_min_ratio = periods[lowest - c.ratio.begin()];
  c.passes_90_percent = c.min_ratio >= 0.9;
  double sum = 0.;
  for (const double a : pgas)
    sum += a;
  c.mean_pga = sum / pgas.size();
  c.target_pga = target_pga;
  c.pga_not_below_target = c.mean_pga >= target_pga;
  return c;
}

bool ComponentSpectrumCheck::passes() const
{
  return enough_records && passes_90_percent && pga_not_below_target;
}

namespace
{
/** @p x with 4 significant digits (a verdict's reason). */
std::string four_digits(const double x)
{
  std::ostringstream s;
  s << std::setprecision(4) << x;
  return s.str();
}
} // namespace

std::vector<std::string> ComponentSpectrumCheck::reasons() const
{
  std::vector<std::string> r;
  if (!enough_records)
    r.push_back(std::to_string(n_records) + (n_records == 1 ? " record" : " records") +
                ", EN 1998-1 3.2.3.1.2 asks for at least " +
                std::to_string(min_ec8_records));
  if (!passes_90_percent)
    r.push_back("the mean spectrum is at " + four_digits(min_ratio) +
                " of the target at T = " + four_digits(period_of_min_ratio) +
                " s, below 0.9");
  if (!pga_not_below_target)
    r.push_back("the mean PGA " + four_digits(mean_pga) +
                " m/s^2 is below the target's " + four_digits(target_pga) + " m/s^2");
  return r;
}

SummaryValue design_spectrum_check(const DesignSpectrum &target,
                                   const std::vector<CheckedRecord> &records,
                                   const std::string &units,
                                   const double scale,
                                   const double fundamental_period,
                                   const std::string &period_source,
                                   std::string &csv,
                                   std::ostream &out)
{
  const auto &range = target.parameters().period_range;
  const double first = std::max(0.2 * fundamental_period, range[0]);
  const double last = std::min(2. * fundamental_period, range[1]);
  AssertThrow(first < last,
              dealii::ExcMessage("design spectrum check: [0.2 T1, 2 T1] with T1 = " +
                                 shortest_number(fundamental_period) +
                                 " s does not meet Design spectrum/Period range (" +
                                 shortest_number(range[0]) + " to " +
                                 shortest_number(range[1]) + " s)"));
  const std::vector<double> periods = log_spaced_periods(first, last, 100);
  const double xi = target.parameters().damping_ratio;
  SummaryValue components = SummaryValue::object(), targets = SummaryValue::object();
  std::vector<std::pair<unsigned int, ComponentSpectrumCheck>> checks;
  bool all = true;
  SummaryValue reasons = SummaryValue::list();
  std::vector<std::string> reason_lines;
  for (unsigned int d = 0; d < 3; ++d)
  {
    std::vector<std::vector<double>> spectra;
    std::vector<double> pgas;
    SummaryValue names = SummaryValue::list();
    for (const auto &r : records)
      if (!r.files[d].empty())
      {
        const std::string entry =
            std::string("Suite/Records (") + r.name + " " + char('X' + d) + ")";
        const Accelerogram a = Accelerogram::read(r.files[d], units, scale, entry);
        spectra.push_back(
            pseudo_acceleration_spectrum(a.times(), a.values(), periods, xi));
        pgas.push_back(a.peak().first);
        names.push_back(r.name);
      }
    if (spectra.empty())
      continue;
    std::vector<double> t;
    for (const double T : periods)
      t.push_back(target(T, d));
    const ComponentSpectrumCheck c =
        check_component(periods, spectra, pgas, t, target.zero_period_value(d));
    all = all && c.passes();
    for (const std::string &r : c.reasons())
    {
      reasons.push_back(std::string(1, char('X' + d)) + ": " + r);
      reason_lines.push_back(std::string(1, char('X' + d)) + ": " + r);
    }
    SummaryValue ratio = SummaryValue::list();
    for (const double x : c.ratio)
      ratio.push_back(x);
    const std::string axis(1, char('X' + d));
    targets.set(axis, target.description(d));
    components.set(
        axis,
        SummaryValue::object()
            .set("records", names)
            .set("n_records", c.n_records)
            .set("enough_records", SummaryValue::boolean(c.enough_records))
            .set("min_ratio", c.min_ratio)
            .set("period_of_min_ratio", c.period_of_min_ratio)
            .set("passes_ec8_90_percent", SummaryValue::boolean(c.passes_90_percent))
            .set("mean_pga", c.mean_pga)
            .set("target_pga", c.target_pga)
            .set("pga_not_below_target", SummaryValue::boolean(c.pga_not_below_target))
            .set("ratio", ratio));
    checks.emplace_back(d, c);
  }
  AssertThrow(!checks.empty(),
              dealii::ExcMessage("design spectrum check: the suite has no record to "
                                 "check (no accelerogram file)"));
  SummaryValue period_list = SummaryValue::list();
  for (const double T : periods)
    period_list.push_back(T);
  std::ostringstream table;
  use_shortest_numbers(table);
  table << "period";
  for (const auto &[d, c] : checks)
    table << ",target." << char('x' + d) << ",mean." << char('x' + d) << ",ratio."
          << char('x' + d);
  table << '\n';
  for (std::size_t j = 0; j < periods.size(); ++j)
  {
    table << periods[j];
    for (const auto &[d, c] : checks)
      table << ',' << c.target[j] << ',' << c.statistic[j] << ',' << c.ratio[j];
    table << '\n';
  }
  csv = table.str();
  out << "hati: suite: design spectrum check (EN 1998-1 3.2.3.1.2), mean"
      << " of the records against the target over [0.2 T1, 2 T1] = [" << first << ", "
      << last << "] s, T1 = " << fundamental_period << " s (" << period_source << ")\n"
      << "  axis  records  min ratio  at T (s)  >= 90 %  mean PGA  target PGA\n";
  for (const auto &[d, c] : checks)
  {
    out << "  " << std::setw(4) << char('X' + d) << "  " << std::setw(7) << c.n_records
        << "  " << std::setw(9) << std::setprecision(4) << c.min_ratio << "  "
        << std::setw(8) << c.period_of_min_ratio << "  " << std::setw(7)
        << (c.passes_90_percent ? "yes" : "NO") << "  " << std::setw(8) << c.mean_pga
        << "  " << std::setw(10) << c.target_pga
        << (c.pga_not_below_target ? "" : "  (mean PGA below the target)") << "\n";
  }
  out << "  the suite " << (all ? "passes" : "does NOT pass") << " the EC8 check";
  for (std::size_t i = 0; i < reason_lines.size(); ++i)
    out << (i == 0 ? ": " : "; ") << reason_lines[i];
  out << std::endl;
  return SummaryValue::object()
      .set("target", targets)
      .set("damping_ratio", xi)
      .set("statistic", std::string("mean"))
      .set("scale", scale)
      .set("fundamental_period", fundamental_period)
      .set("fundamental_period_source", period_source)
      .set("period_range_checked", SummaryValue::list().push_back(first).push_back(last))
      .set("periods", period_list)
      .set("components", components)
      .set("passes_ec8", SummaryValue::boolean(all))
      .set("reasons", reasons);
}
} // namespace hati

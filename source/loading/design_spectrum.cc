#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hati/base/input_file.h>
#include <hati/base/names.h>
#include <hati/loading/design_spectrum.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace hati
{
namespace
{
/** @p x as a short text (10 digits). */
std::string ten_digit_text(const double x)
{
  std::ostringstream s;
  s << std::setprecision(10) << x;
  return s.str();
}
} // namespace

void DesignSpectrumParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Design spectrum");
  prm.declare_entry(
      "Type",
      "none",
      Patterns::Selection("none|EC8 type 1|EC8 type 2|table"),
      "Target pseudo-acceleration spectrum of the artificial records and of a suite's "
      "check (suite_summary.json design_spectrum_check): none, the elastic spectrum of "
      "EN 1998-1 3.2.2.2 of type 1 (large magnitudes) or type 2 (Ms <= 5.5), or a "
      "tabulated site or floor spectrum (Table file).");
  prm.declare_entry("Ground type",
                    "C",
                    Patterns::Selection("A|B|C|D|E"),
                    "EC8 ground type (EN 1998-1 Table 3.1), which sets the soil factor S "
                    "and the corner periods T_B, T_C, T_D.");
  prm.declare_entry("Peak ground acceleration",
                    "0",
                    Patterns::Double(0.),
                    "Design ground acceleration on rock a_g = gamma_I a_gR (m/s^2); the "
                    "records' peak is a_g S horizontally (a_vg vertically). > 0 for an "
                    "EC8 type.");
  prm.declare_entry("Damping ratio",
                    "0.05",
                    Patterns::Double(0., 1.),
                    "Viscous damping ratio of the spectrum (-): EC8 corrects its "
                    "spectrum by eta = sqrt(10 / (5 + 100 xi)) >= 0.55; a table is taken "
                    "as given at this ratio. The records are matched, and a suite "
                    "checked, at this ratio.");
  prm.declare_entry("Vertical",
                    "true",
                    Patterns::Bool(),
                    "true: the Z component follows the EC8 vertical spectrum "
                    "(EN 1998-1 3.2.2.3, a_vg/a_g 0.90 type 1, 0.45 type 2); false: the "
                    "horizontal one. A table applies to every component.");
  prm.declare_entry("Table file",
                    "",
                    Patterns::Anything(),
                    "Type = table: CSV of 'period, pseudo-acceleration' rows (s, m/s^2), "
                    "periods increasing, both > 0, an optional header line; "
                    "interpolated linearly in log-log. Its first row is the zero-period "
                    "value (the records' peak ground acceleration).");
  for (const char axis : {'Y', 'Z'})
    prm.declare_entry(std::string("Table file ") + axis,
                      "",
                      Patterns::Anything(),
                      std::string("Type = table: the table of the ") + axis +
                          " axis, as Table file (s, m/s^2; floor response spectra differ "
                          "per axis); empty: " +
                          axis + " takes Table file.");
  prm.declare_entry("Period range",
                    "0.02, 4",
                    Patterns::List(Patterns::Double(0.), 2, 2),
                    "Shortest and longest period (s) over which the records are matched "
                    "and a suite's spectra are computed.");
  prm.leave_subsection();
}

void DesignSpectrumParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Design spectrum");
  type = prm.get("Type");
  ground_type = prm.get("Ground type");
  peak_ground_acceleration = prm.get_double("Peak ground acceleration");
  damping_ratio = prm.get_double("Damping ratio");
  vertical = prm.get_bool("Vertical");
  table_file = Utilities::trim(prm.get("Table file"));
  for (unsigned int k = 0; k < 2; ++k)
    table_file_yz[k] = Utilities::trim(prm.get(std::string("Table file ") + "YZ"[k]));
  const auto range =
      Utilities::string_to_double(Utilities::split_string_list(prm.get("Period range")));
  prm.leave_subsection();
  period_range = {{range[0], range[1]}};
  AssertThrow(range[0] > 0. && range[1] > range[0],
              ExcMessage("Design spectrum/Period range: '" + ten_digit_text(range[0]) +
                         ", " + ten_digit_text(range[1]) +
                         "': two periods 0 < first < last (s) are expected"));
  AssertThrow(
      damping_ratio > 0. && damping_ratio < 1.,
      ExcMessage("Design spectrum/Damping ratio: " + ten_digit_text(damping_ratio) +
                 ": a ratio 0 < xi < 1 is "
                 "expected"));
  if (type == "EC8 type 1" || type == "EC8 type 2")
    AssertThrow(peak_ground_acceleration > 0.,
                ExcMessage("Design spectrum/Peak ground acceleration: " + type +
                           " needs a_g > 0 (m/s^2)"));
  if (type == "table")
  {
    AssertThrow(!table_file.empty(),
                ExcMessage("Design spectrum/Table file: Type = table needs the file of "
                           "'period, pseudo-acceleration' rows"));
    const auto read = [&](const std::string &file,
                          const std::string &entry,
                          std::vector<double> &periods,
                          std::vector<double> &values)
    {
      DesignSpectrum::read_table(file, entry, periods, values);
      AssertThrow(periods.front() <= range[0] * (1. + 1e-12) &&
                      periods.back() >= range[1] * (1. - 1e-12),
                  ExcMessage("Design spectrum/Period range: " + ten_digit_text(range[0]) +
                             " to " + ten_digit_text(range[1]) +
                             " s is not within the "
                             "table '" +
                             file + "' (" + ten_digit_text(periods.front()) + " to " +
                             ten_digit_text(periods.back()) +
                             " s): a table is not extrapolated"));
    };
    read(table_file, "Design spectrum/Table file", table_periods, table_values);
    for (unsigned int k = 0; k < 2; ++k)
      if (!table_file_yz[k].empty())
        read(table_file_yz[k],
             std::string("Design spectrum/Table file ") + "YZ"[k],
             table_periods_yz[k],
             table_values_yz[k]);
  }
}

Ec8Corners
ec8_corners(const unsigned int type, const std::string &ground_type, const bool vertical)
{
  Assert(type == 1 || type == 2, ExcInternalError());
  Ec8Corners c;
  if (vertical)
  {
    // EN 1998-1 Table 3.4
    c.TB = 0.05;
    c.TC = 0.15;
    c.TD = 1.;
    c.plateau = 3.;
    c.acceleration_ratio = type == 1 ? 0.9 : 0.45;
    return c;
  }
  // EN 1998-1 Tables 3.2 (type 1) and 3.3 (type 2): S, T_B, T_C, T_D
  static const char grounds[] = "ABCDE";
  static const double table[2][5][4] = {{{1.0, 0.15, 0.4, 2.0},
                                         {1.2, 0.15, 0.5, 2.0},
                                         {1.15, 0.20, 0.6, 2.0},
                                         {1.35, 0.20, 0.8, 2.0},
                                         {1.4, 0.15, 0.5, 2.0}},
                                        {{1.0, 0.05, 0.25, 1.2},
                                         {1.35, 0.05, 0.25, 1.2},
                                         {1.5, 0.10, 0.25, 1.2},
                                         {1.8, 0.10, 0.30, 1.2},
                                         {1.6, 0.05, 0.25, 1.2}}};
  const char *g = ground_type.size() == 1
                      ? std::find(grounds, grounds + 5, ground_type[0])
                      : grounds + 5;
  AssertThrow(g != grounds + 5,
              ExcMessage("Design spectrum/Ground type: '" + printable(ground_type) +
                         "': one of A, B, C, D, E is expected"));
  const double *row = table[type - 1][g - grounds];
  c.S = row[0];
  c.TB = row[1];
  c.TC = row[2];
  c.TD = row[3];
  return c;
}

double ec8_damping_correction(const double damping_ratio)
{
  return std::max(std::sqrt(10. / (5. + 100. * damping_ratio)), 0.55);
}

DesignSpectrum::DesignSpectrum(const DesignSpectrumParameters &parameters) : p(parameters)
{
  if (p.type == "EC8 type 1" || p.type == "EC8 type 2")
  {
    const unsigned int t = p.type == "EC8 type 1" ? 1 : 2;
    horizontal = ec8_corners(t, p.ground_type, false);
    vertical = ec8_corners(t, p.ground_type, true);
  }
  else
    AssertThrow(p.type == "table" && !p.table_periods.empty(),
                ExcMessage("Design spectrum/Type: '" + p.type +
                           "': a target spectrum is needed here"));
}

bool DesignSpectrum::is_vertical(const unsigned int axis) const
{
  return axis == 2 && p.vertical && p.type != "table";
}

bool DesignSpectrum::own_table(const unsigned int axis) const
{
  return axis > 0 && !p.table_periods_yz[axis - 1].empty();
}

const std::vector<double> &DesignSpectrum::table_periods(const unsigned int axis) const
{
  return own_table(axis) ? p.table_periods_yz[axis - 1] : p.table_periods;
}

const std::vector<double> &DesignSpectrum::table_values(const unsigned int axis) const
{
  return own_table(axis) ? p.table_values_yz[axis - 1] : p.table_values;
}

const std::string &DesignSpectrum::table_file(const unsigned int axis) const
{
  return own_table(axis) ? p.table_file_yz[axis - 1] : p.table_file;
}

double DesignSpectrum::operator()(const double period, const unsigned int axis) const
{
  const double T = std::max(period, 0.);
  if (p.type == "table")
  {
    const auto &x = table_periods(axis);
    const auto &y = table_values(axis);
    if (T <= x.front())
      return y.front();
    if (T >= x.back())
      return y.back();
    const std::size_t i = std::upper_bound(x.begin(), x.end(), T) - x.begin();
    const double s = std::log(T / x[i - 1]) / std::log(x[i] / x[i - 1]);
    return y[i - 1] * std::pow(y[i] / y[i - 1], s);
  }
  const Ec8Corners &c = is_vertical(axis) ? vertical : horizontal;
  const double a = p.peak_ground_acceleration * c.acceleration_ratio * c.S;
  const double top = a * c.plateau * ec8_damping_correction(p.damping_ratio);
  if (T <= c.TB)
    return a *
           (1. + T / c.TB * (c.plateau * ec8_damping_correction(p.damping_ratio) - 1.));
  if (T <= c.TC)
    return top;
  if (T <= c.TD)
    return top * c.TC / T;
  return top * c.TC * c.TD / (T * T);
}

double DesignSpectrum::zero_period_value(const unsigned int axis) const
{
  return (*this)(0., axis);
}

std::string DesignSpectrum::description(const unsigned int axis) const
{
  std::ostringstream s;
  s << p.type;
  if (p.type == "table")
    s << " " << table_file(axis);
  else
    s << ", ground type " << p.ground_type << ", a_g = " << p.peak_ground_acceleration
      << " m/s^2";
  s << ", " << 100. * p.damping_ratio << " % damping, "
    << (is_vertical(axis) ? "vertical" : "horizontal");
  return s.str();
}

void DesignSpectrum::read_table(const std::string &file,
                                const std::string &entry,
                                std::vector<double> &periods,
                                std::vector<double> &values)
{
  require_regular_file(file, entry, "spectrum table");
  std::ifstream in(file);
  AssertThrow(in, ExcMessage(entry + ": cannot open the spectrum table '" + file + "'"));
  periods.clear();
  values.clear();
  std::string line;
  unsigned int n = 0;
  bool first = true;
  while (std::getline(in, line))
  {
    ++n;
    // a UTF-8 byte-order mark (a spreadsheet's export) is not part of the row
    if (n == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
      line.erase(0, 3);
    // a '#' comment, a whole line or after a row
    const std::string text = Utilities::trim(line.substr(0, line.find('#')));
    if (text.empty())
      continue;
    const std::string at =
        entry + ": spectrum table '" + file + "', line " + std::to_string(n) + ": ";
    std::vector<std::string> parts = Utilities::split_string_list(text, ',');
    std::vector<double> row;
    for (const auto &part : parts)
    {
      char *end = nullptr;
      const double x = std::strtod(part.c_str(), &end);
      if (part.empty() || *end != '\0' || !std::isfinite(x))
        break;
      row.push_back(x);
    }
    if (row.size() != parts.size() && first)
    {
      first = false; // a header
      continue;
    }
    first = false;
    AssertThrow(row.size() == 2 && parts.size() == 2,
                ExcMessage(at + "'" + printable(text) +
                           "' is not 'period, pseudo-acceleration' (two numbers)"));
    AssertThrow(row[0] > 0. && row[1] > 0.,
                ExcMessage(at +
                           "the period and the pseudo-acceleration must be > 0 "
                           "(log-log interpolation), got '" +
                           printable(text) + "'"));
    AssertThrow(periods.empty() || row[0] > periods.back(),
                ExcMessage(at + "the periods must increase (" + printable(text) +
                           " after a period of " + ten_digit_text(periods.back()) +
                           " s)"));
    periods.push_back(row[0]);
    values.push_back(row[1]);
  }
  AssertThrow(periods.size() >= 2,
              ExcMessage(entry + ": spectrum table '" + file + "' has " +
                         std::to_string(periods.size()) +
                         " rows: at least two 'period, pseudo-acceleration' rows are "
                         "expected"));
}
} // namespace hati

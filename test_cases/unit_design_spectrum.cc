// Design spectra and the EC8 suite check (loading/design_spectrum.h,
// output/design_spectrum_check.h, issue #29):
// - the EN 1998-1 elastic spectra at the corner periods of every ground type,
//   both types, horizontal (Tables 3.2, 3.3) and vertical (Table 3.4),
//   against hand values written out here from the code's tables (1e-12);
// - the damping correction eta = sqrt(10 / (5 + 100 xi)) and its floor 0.55;
// - a tabulated spectrum, log-log interpolated, against the power law through
//   two rows, and its one-line errors (no rows, unsorted, non-positive);
// - the 90 % check of EN 1998-1 3.2.3.1.2 on a stored suite spectrum (three
//   records at five periods) against the mean, ratio and minimum worked out
//   by hand in the comments, once passing and once failing.
#include <deal.II/base/parameter_handler.h>

#include <hati/loading/design_spectrum.h>
#include <hati/output/design_spectrum_check.h>

#include "test_tools.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hati_unit_design_spectrum
{

using namespace hati;
using hati_test::check;
using hati_test::expect;

namespace
{
DesignSpectrumParameters ec8(const std::string &type,
                             const std::string &ground,
                             const double ag,
                             const double xi = 0.05)
{
  DesignSpectrumParameters p;
  p.type = type;
  p.ground_type = ground;
  p.peak_ground_acceleration = ag;
  p.damping_ratio = xi;
  return p;
}

void check_corners()
{
  // EN 1998-1 Table 3.2 (type 1) and 3.3 (type 2): S, T_B, T_C, T_D
  struct Row
  {
    const char *ground;
    double S, TB, TC, TD;
  };
  const Row type1[] = {{"A", 1.0, 0.15, 0.4, 2.0},
                       {"B", 1.2, 0.15, 0.5, 2.0},
                       {"C", 1.15, 0.2, 0.6, 2.0},
                       {"D", 1.35, 0.2, 0.8, 2.0},
                       {"E", 1.4, 0.15, 0.5, 2.0}};
  const Row type2[] = {{"A", 1.0, 0.05, 0.25, 1.2},
                       {"B", 1.35, 0.05, 0.25, 1.2},
                       {"C", 1.5, 0.1, 0.25, 1.2},
                       {"D", 1.8, 0.1, 0.3, 1.2},
                       {"E", 1.6, 0.05, 0.25, 1.2}};
  const double ag = 3.;
  for (unsigned int t = 1; t <= 2; ++t)
    for (const Row &r : (t == 1 ? type1 : type2))
    {
      const DesignSpectrum s(ec8("EC8 type " + std::to_string(t), r.ground, ag));
      const std::string name = "EC8 type " + std::to_string(t) + " " + r.ground + " ";
      const double top = 2.5 * ag * r.S; // eta = 1 at 5 %
      check(name + "S_a(0) = a_g S", s(0., 0), ag * r.S, 1e-12);
      check(name + "S_a(T_B / 2)", s(0.5 * r.TB, 0), ag * r.S * (1. + 0.5 * 1.5), 1e-12);
      check(name + "S_a(T_B) = 2.5 a_g S", s(r.TB, 0), top, 1e-12);
      check(name + "S_a(T_C) = 2.5 a_g S", s(r.TC, 1), top, 1e-12);
      check(
          name + "S_a(T_D) = 2.5 a_g S T_C / T_D", s(r.TD, 0), top * r.TC / r.TD, 1e-12);
      check(name + "S_a(4 s)", s(4., 0), top * r.TC * r.TD / 16., 1e-12);
      check(name + "zero-period value", s.zero_period_value(0), ag * r.S, 1e-12);
    }
  // vertical (Table 3.4): a_vg/a_g 0.90 (type 1), 0.45 (type 2); T_B 0.05,
  // T_C 0.15, T_D 1.0; plateau 3.0 a_vg; no soil factor
  for (unsigned int t = 1; t <= 2; ++t)
  {
    const DesignSpectrum s(ec8("EC8 type " + std::to_string(t), "D", ag));
    const double avg = (t == 1 ? 0.9 : 0.45) * ag;
    const std::string name = "EC8 type " + std::to_string(t) + " vertical ";
    check(name + "S_ve(0) = a_vg", s(0., 2), avg, 1e-12);
    check(name + "S_ve(0.05) = 3 a_vg", s(0.05, 2), 3. * avg, 1e-12);
    check(name + "S_ve(0.15) = 3 a_vg", s(0.15, 2), 3. * avg, 1e-12);
    check(name + "S_ve(1) = 3 a_vg 0.15", s(1., 2), 3. * avg * 0.15, 1e-12);
    check(name + "S_ve(2) = 3 a_vg 0.15 / 4", s(2., 2), 3. * avg * 0.15 / 4., 1e-12);
  }
  // Vertical = false: Z follows the horizontal spectrum
  DesignSpectrumParameters p = ec8("EC8 type 1", "C", ag);
  p.vertical = false;
  check("Vertical = false: S_a(0.5 s, Z) horizontal",
        DesignSpectrum(p)(0.5, 2),
        2.5 * ag * 1.15,
        1e-12);
  // damping: eta = sqrt(10 / 7) at 2 %, the floor 0.55 at 30 %
  check("eta(2 %)", ec8_damping_correction(0.02), std::sqrt(10. / 7.), 1e-15);
  check("eta(30 %) = 0.55", ec8_damping_correction(0.3), 0.55, 1e-15);
  check("EC8 type 1 C at 2 %: S_a(0.4 s)",
        DesignSpectrum(ec8("EC8 type 1", "C", ag, 0.02))(0.4, 0),
        2.5 * ag * 1.15 * std::sqrt(10. / 7.),
        1e-12);
}

/** Write @p text to a temporary file; its path. */
std::string table_file(const std::string &name, const std::string &text)
{
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("hati_unit_design_spectrum_" + name + ".csv"))
                               .string();
  std::ofstream(path) << text;
  return path;
}

void check_table()
{
  DesignSpectrumParameters p;
  p.type = "table";
  DesignSpectrum::read_table(
      table_file("ok",
                 "period, pseudo_acceleration\n# a floor spectrum\n"
                 "0.01, 2\n0.1, 8\n1, 4\n4, 1\n"),
      "Design spectrum/Table file",
      p.table_periods,
      p.table_values);
  const DesignSpectrum s(p);
  // between 0.1 s (8) and 1 s (4): S = 8 (T / 0.1)^(log(0.5) / log(10))
  check("table at 0.3 s (power law through two rows)",
        s(0.3, 0),
        8. * std::pow(3., std::log(0.5) / std::log(10.)),
        1e-12);
  check("table at a row", s(1., 2), 4., 1e-12);
  check("table zero-period value (first row)", s.zero_period_value(0), 2., 0.);
  // issue #59: a byte-order mark without a header keeps its first row, and a
  // '#' comment after a row is a comment
  {
    std::vector<double> x, y;
    DesignSpectrum::read_table(table_file("bom",
                                          "\xEF\xBB\xBF"
                                          "0.01, 2\n0.1, 8 # plateau\n1, 4\n"),
                               "Design spectrum/Table file",
                               x,
                               y);
    expect(x.size() == 3 && x[0] == 0.01 && y[0] == 2. && y[1] == 8.,
           "a table with a byte-order mark and no header: its 3 rows, the first kept, "
           "'# plateau' after a row a comment");
  }
  const std::pair<std::string, std::string> bad[] = {
      {"empty", "period, pseudo_acceleration\n"},
      {"unsorted", "0.1, 2\n0.5, 3\n0.3, 1\n"},
      {"negative", "0.1, 2\n0.5, -3\n"},
      {"zero_period", "0, 2\n0.5, 3\n"},
      {"three_columns", "0.1, 2, 3\n0.5, 3, 4\n"}};
  for (const auto &[name, text] : bad)
  {
    std::vector<double> x, y;
    try
    {
      DesignSpectrum::read_table(
          table_file(name, text), "Design spectrum/Table file", x, y);
      expect(false, "table '" + name + "' refused");
    }
    catch (const std::exception &e)
    {
      const std::string m = hati_test::message_of(e);
      expect(m.rfind("Design spectrum/Table file: spectrum table", 0) == 0 &&
                 m.find('\n') == std::string::npos,
             "table '" + name + "' refused: " + m);
    }
  }
}

/**
 * Issue #57: a table per axis (`Table file Y`, `Table file Z`) through the
 * parameter file: X and Y on `Table file`, Z on its own; a Z table that
 * does not cover the Period range is refused naming `Table file Z`.
 */
void check_axis_tables()
{
  const std::string x_file = table_file("x", "0.01, 2\n0.1, 8\n1, 4\n4, 1\n");
  const std::string z_file = table_file("z", "0.01, 1\n0.05, 3\n0.5, 3\n4, 0.5\n");
  const std::string short_file = table_file("short", "0.05, 1\n1, 3\n");
  const auto parse = [&](const std::string &z)
  {
    ParameterHandler prm;
    DesignSpectrumParameters::declare_parameters(prm);
    prm.enter_subsection("Design spectrum");
    prm.set("Type", "table");
    prm.set("Table file", x_file);
    prm.set("Table file Z", z);
    prm.leave_subsection();
    DesignSpectrumParameters p;
    p.parse_parameters(prm);
    return p;
  };
  const DesignSpectrum s(parse(z_file));
  check("Table file Z: Z at a row of its own table (0.5 s: 3)", s(0.5, 2), 3., 1e-12);
  check("Table file Z: Z between rows (0.2 s: the plateau 3)", s(0.2, 2), 3., 1e-12);
  check("Table file Z: X on Table file (1 s: 4)", s(1., 0), 4., 1e-12);
  check("Table file Y empty: Y on Table file (1 s: 4)", s(1., 1), 4., 1e-12);
  check("Table file Z: Z's zero-period value (its first row)",
        s.zero_period_value(2),
        1.,
        0.);
  expect(s.description(2).find(z_file) != std::string::npos &&
             s.description(0).find(x_file) != std::string::npos,
         "each axis's description names its table: " + s.description(2));
  try
  {
    parse(short_file);
    expect(false, "a Z table from 0.05 s refused for the Period range from 0.02 s");
  }
  catch (const std::exception &e)
  {
    const std::string m = hati_test::message_of(e);
    expect(m.find("is not within the table '" + short_file + "'") != std::string::npos,
           "a Z table not covering the Period range refused: " + m);
  }
  try
  {
    parse(x_file + ".missing");
    expect(false, "a missing Table file Z refused");
  }
  catch (const std::exception &e)
  {
    const std::string m = hati_test::message_of(e);
    expect(m.rfind("Design spectrum/Table file Z:", 0) == 0,
           "a missing Table file Z refused naming the entry: " + m);
  }
}

void check_suite_check()
{
  // a stored suite spectrum: three records at five periods (m/s^2), target 10
  const std::vector<double> periods = {0.2, 0.4, 0.6, 0.8, 1.0};
  const std::vector<double> target(5, 10.);
  const std::vector<std::vector<double>> spectra = {
      {12., 9., 10., 11., 8.}, {10., 10., 9., 9., 10.}, {11., 9., 8., 10., 9.5}};
  // mean: 11, 9.3333, 9, 10, 9.1667; ratio min 0.9 at 0.6 s: passes (>= 0.9)
  const auto pass = check_component(periods, spectra, {3., 3.25, 3.5}, target, 3.2);
  check("mean check: min ratio (hand: 0.9)", pass.min_ratio, 0.9, 1e-15);
  check("mean check: its period (hand: 0.6 s)", pass.period_of_min_ratio, 0.6, 0.);
  check("mean check: ratio at 1 s (hand: 27.5 / 30)", pass.ratio[4], 27.5 / 30., 1e-15);
  expect(pass.passes_90_percent, "mean check at 0.9 passes");
  check("mean PGA (hand: 3.25)", pass.mean_pga, 3.25, 1e-15);
  expect(pass.pga_not_below_target, "mean PGA 3.25 not below 3.2");
  // the third record at 0.6 s lower (8 -> 7.7): mean 8.9, ratio 0.89: fails
  auto lower = spectra;
  lower[2][2] = 7.7;
  const auto fail = check_component(periods, lower, {3., 3.2, 3.3}, target, 3.2);
  check("lowered mean check: min ratio (hand: 0.89)", fail.min_ratio, 0.89, 1e-15);
  expect(!fail.passes_90_percent, "mean check at 0.89 fails");
  expect(!fail.pga_not_below_target, "mean PGA 3.1667 below 3.2");
  expect(pass.passes() && pass.reasons().empty(),
         "three records at 0.9: the component passes");
  expect(!fail.passes() && fail.reasons().size() == 2,
         "lowered: fails with two reasons (ratio, PGA)");
  // the lowered suite's envelope (12, 10, 10, 11, 10) would pass at 1.0: EN
  // 1998-1 3.2.3.1.2 checks the mean whatever the number of records, and the
  // check has no other statistic to take
  // two records (the first two: mean 11, 9.5, 9.5, 10, 9; min ratio 9 / 10
  // at 1 s): the ratio passes, the count does not
  const std::vector<std::vector<double>> two = {spectra[0], spectra[1]};
  const auto few = check_component(periods, two, {3.3, 3.3}, target, 3.2);
  check("two records: min ratio (hand: 0.9 at 1 s)", few.min_ratio, 0.9, 1e-15);
  check("two records: its period", few.period_of_min_ratio, 1.0, 0.);
  expect(few.passes_90_percent && few.pga_not_below_target,
         "two records: ratio and PGA pass");
  expect(few.n_records == 2 && !few.enough_records && !few.passes(),
         "two records: refused its pass (EN 1998-1: at least 3)");
  expect(few.reasons().size() == 1 &&
             few.reasons()[0].find("at least 3") != std::string::npos,
         "two records: the reason names the count");
}
} // namespace

HATI_UNIT_TEST(design_spectrum)
{
  try
  {
    check_corners();
    check_table();
    check_axis_tables();
    check_suite_check();
  }
  catch (const std::exception &e)
  {
    expect(false, std::string("unexpected exception: ") + hati_test::message_of(e));
  }
  return hati_test::finish();
}
} // namespace hati_unit_design_spectrum

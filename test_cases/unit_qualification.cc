// The verdicts of a qualification (output/qualification.h, doc/theory.md
// 15.3, Q1, issue #54) by hand:
// - a stored summary.json text of a run (two beam members, a solid, three
//   contacts of which one two-sided, two wheels, a rope) with capacities
//   chosen so that each check has a passing and a failing item, and one
//   check (slip) not asked for: every row's demand, capacity (ratio x yield
//   for the stresses), ratio = demand / capacity written out, verdict,
//   where (station and time), no row for the unchecked slip; the CSV's
//   columns and the json's passes / n_fail;
// - a suite's statistic: the demand is the statistic, where the governing
//   member, the item the quantity's prefix;
// - the closing line names the failing checks, largest ratio first;
// - the one-line refusals of a negative capacity and a ratio at 0 or above 1.
#include <deal.II/base/parameter_handler.h>

#include <hati/output/qualification.h>
#include <hati/output/summary.h>

#include "test_tools.h"

#include <sstream>
#include <string>
#include <vector>

namespace hati_unit_qualification
{
using namespace hati;
using hati_test::check;
using hati_test::expect;

namespace
{
const char *const stored_summary = R"({
  "beam_stresses": {
    "girder_1": {"max_normal_stress": {"value": 2.0e8, "x": 10.0, "time": 3.06},
                 "max_von_mises": {"value": 2.2e8, "x": 10.0, "time": 3.06}},
    "end_carriage_1": {"max_normal_stress": {"value": 5.0e7, "x": 0.5, "time": 1.0},
                       "max_von_mises": {"value": 6.0e7, "x": 0.5, "time": 1.25}}},
  "solids": {"box_1": {"max_von_mises": {"value": 1.5e8, "time": 2.5, "point": [0, 1, 2]}}},
  "contacts": {
    "crane_wheel_1": {"n_impacts": 3, "max_uplift": 0.03, "max_uplift_time": 4.2},
    "crane_wheel_2": {"n_impacts": 0, "max_uplift": 0.001, "max_uplift_time": 0.5},
    "crane_wheel_1_lateral": {"n_impacts": 1, "max_offset": 0.012}},
  "wheels": {
    "crane_wheel_1": {"slip_distance": 0.2, "max_lateral_offset": 0.012,
                      "max_lateral_offset_time": 5.5},
    "crane_wheel_2": {"slip_distance": 0.01, "max_lateral_offset": 0.04,
                      "max_lateral_offset_time": 6.0}},
  "rope_tension": {"hoist_rope": {"min": 1.0e5, "max": 2.5e5, "slack_time": 0}},
  "status": "completed"
})";

QualificationParameters capacities()
{
  QualificationParameters p;
  p.yield_strength = 235e6;
  p.allowable_stress_ratio = 0.9; // allowable 211.5 MPa
  p.maximum_uplift = 0.025;
  p.maximum_slip = 0.; // not checked
  p.rope_capacity = 3.0e5;
  p.maximum_lateral_play = 0.03;
  return p;
}

void check_row(const std::vector<QualificationRow> &rows,
               const std::string &check_name,
               const std::string &item,
               const double demand,
               const double capacity,
               const bool passes,
               const std::string &where)
{
  for (const auto &r : rows)
    if (r.check == check_name && r.item == item)
    {
      const std::string what = check_name + " " + item;
      check(what + ": demand", r.demand, demand, 1e-12 * demand);
      check(what + ": capacity", r.capacity, capacity, 1e-12 * capacity);
      check(what + ": ratio = demand / capacity", r.ratio, demand / capacity, 1e-12);
      expect(r.passes == passes, what + ": verdict " + (passes ? "pass" : "fail"));
      expect(r.where == where, what + ": where '" + r.where + "' = '" + where + "'");
      return;
    }
  expect(false, "a row " + check_name + " " + item);
}

void check_run()
{
  const auto rows = qualify(run_demands(stored_summary), capacities());
  const double allowable = 0.9 * 235e6;
  check_row(rows, "stress", "girder_1", 2.2e8, allowable, false, "x = 10 m, t = 3.06 s");
  check_row(
      rows, "stress", "end_carriage_1", 6.0e7, allowable, true, "x = 0.5 m, t = 1.25 s");
  check_row(rows, "stress", "box_1", 1.5e8, allowable, true, "t = 2.5 s");
  check_row(rows, "uplift", "crane_wheel_1", 0.03, 0.025, false, "t = 4.2 s");
  check_row(rows, "uplift", "crane_wheel_2", 0.001, 0.025, true, "t = 0.5 s");
  check_row(rows, "lateral offset", "crane_wheel_1", 0.012, 0.03, true, "t = 5.5 s");
  check_row(rows, "lateral offset", "crane_wheel_2", 0.04, 0.03, false, "t = 6 s");
  check_row(rows, "rope", "hoist_rope", 2.5e5, 3.0e5, true, "");
  // two stresses + a solid, two uplifts (not the two-sided lateral contact),
  // two lateral offsets, one rope; slip not checked
  check("rows (slip not checked, no uplift of a two-sided contact)", rows.size(), 8, 0);
  for (const auto &r : rows)
    expect(r.check != "slip", "no slip row (Maximum slip = 0)");

  const std::string csv = qualification_csv(rows);
  expect(csv.rfind("check,item,demand,capacity,unit,ratio,verdict,where\n", 0) == 0,
         "qualification.csv header");
  // numbers in their shortest round-trip text (repr(2.2e8 / 2.115e8) in Python)
  expect(csv.find("stress,girder_1,2.2e+08,211500000,Pa,1.0401891252955082,fail,"
                  "\"x = 10 m, t = 3.06 s\"\n") != std::string::npos,
         "qualification.csv row of girder_1 (where quoted): " +
             csv.substr(csv.find("stress,girder_1"), 80));
  const std::string json = to_json(qualification_json(rows));
  expect(json.find("\"n_checks\":8") != std::string::npos &&
             json.find("\"n_fail\":3") != std::string::npos &&
             json.find("\"passes\":false") != std::string::npos,
         "qualification json: 8 checks, 3 fail, passes false: " +
             json.substr(json.size() - 60));
  std::ostringstream out;
  print_qualification(rows, out);
  const std::string text = out.str();
  const auto line = text.substr(text.find("hati: qualification:"));
  expect(line == "hati: qualification: 3 of 8 checks fail (crane_wheel_2 lateral offset "
                 "ratio 1.33 at t = 6 s; crane_wheel_1 uplift ratio 1.2 at t = 4.2 s; "
                 "girder_1 stress ratio 1.04 at x = 10 m, t = 3.06 s)\n",
         "closing line, largest ratio first: " + line);

  QualificationParameters none;
  expect(!none.enabled() && qualify(run_demands(stored_summary), none).empty(),
         "no capacity: no check, no row");
}

void check_suite()
{
  const std::vector<SuiteQuantity> statistic = {
      {"crane_wheel_1.peak_mean_force", 1.0e5, "art01"},
      {"crane_wheel_1.max_uplift", 0.02, "art03"},
      {"girder_1.max_von_mises", 1.0e8, "art05"},
      {"girder_1.max_normal_stress", 0.9e8, "art05"},
      {"hoist_rope.max_tension", 3.3e5, "art02"}};
  const auto rows = qualify(suite_demands(statistic), capacities());
  check("suite rows (stress, uplift, rope)", rows.size(), 3, 0);
  check_row(
      rows, "stress", "girder_1", 1.0e8, 0.9 * 235e6, true, "governing member art05");
  check_row(rows, "uplift", "crane_wheel_1", 0.02, 0.025, true, "governing member art03");
  check_row(rows, "rope", "hoist_rope", 3.3e5, 3.0e5, false, "governing member art02");
}

void refused(const std::string &entry, const std::string &value, const std::string &start)
{
  ParameterHandler prm;
  QualificationParameters::declare_parameters(prm);
  prm.enter_subsection("Qualification");
  prm.set(entry, value);
  prm.leave_subsection();
  try
  {
    QualificationParameters p;
    p.parse_parameters(prm);
    expect(false, "Qualification/" + entry + " = " + value + " refused");
  }
  catch (const std::exception &e)
  {
    const std::string m = hati_test::message_of(e);
    expect(m.rfind(start, 0) == 0, "Qualification/" + entry + " = " + value + ": " + m);
  }
}

void check_refusals()
{
  refused("Yield strength", "-235e6", "Qualification/Yield strength = -235e6: expected");
  refused("Rope capacity", "-1", "Qualification/Rope capacity = -1: expected a capacity");
  refused("Maximum uplift", "-0.01", "Qualification/Maximum uplift = -0.01: expected");
  refused("Allowable stress ratio", "0", "Qualification/Allowable stress ratio = 0:");
  refused("Allowable stress ratio", "1.2", "Qualification/Allowable stress ratio = 1.2:");
}
} // namespace

HATI_UNIT_TEST(qualification)
{
  try
  {
    check_run();
    check_suite();
    check_refusals();
  }
  catch (const std::exception &e)
  {
    expect(false, std::string("unexpected exception: ") + hati_test::message_of(e));
  }
  return hati_test::finish();
}
} // namespace hati_unit_qualification

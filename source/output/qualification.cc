#include <hati/output/csv_file.h>
#include <hati/output/qualification.h>
#include <hati/output/summary.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hati
{
namespace
{
using QualificationJson = nlohmann::ordered_json;

/** The checks: their summary.json group and key, their quantity in a suite, unit. */
struct CheckKind
{
  const char *check, *suite_suffix, *unit;
};
const CheckKind check_kinds[] = {{"stress", ".max_von_mises", "Pa"},
                                 {"uplift", ".max_uplift", "m"},
                                 {"slip", ".slip_distance", "m"},
                                 {"lateral offset", ".max_lateral_offset", "m"},
                                 {"rope", ".max_tension", "N"},
                                 {"derailment", ".derailment_offset", "m"}};

std::string
format_where(const QualificationJson &entry, const char *x_key, const char *time_key)
{
  // a result that says where itself (a response-spectrum bound)
  if (entry.contains("where") && entry["where"].is_string())
    return entry["where"].get<std::string>();
  std::ostringstream s;
  s << std::setprecision(4);
  if (x_key && entry.contains(x_key) && entry[x_key].is_number())
    s << "x = " << entry[x_key].get<double>() << " m, ";
  if (time_key && entry.contains(time_key) && entry[time_key].is_number())
    s << "t = " << entry[time_key].get<double>() << " s";
  std::string text = s.str();
  if (text.size() >= 2 && text.compare(text.size() - 2, 2, ", ") == 0)
    text.resize(text.size() - 2);
  return text;
}

double capacity_of(const std::string &check, const QualificationParameters &p)
{
  if (check == "stress")
    return p.yield_strength > 0. ? p.allowable_stress() : 0.;
  if (check == "uplift")
    return p.maximum_uplift;
  if (check == "slip")
    return p.maximum_slip;
  if (check == "lateral offset")
    return p.maximum_lateral_play;
  if (check == "rope")
    return p.rope_capacity;
  return 0.;
}

std::string unit_of(const std::string &check)
{
  for (const auto &k : check_kinds)
    if (check == k.check)
      return k.unit;
  return "";
}

} // namespace

void QualificationParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Qualification");
  prm.declare_entry("Yield strength",
                    "0",
                    Patterns::Double(),
                    "Yield strength of the steel (Pa), e.g. 235e6 for S235; the "
                    "allowable stress is Allowable stress ratio x Yield strength for "
                    "every beam member (von Mises at its extreme fibres, beam_stresses) "
                    "and solid (max_von_mises). 0: stresses not checked.");
  prm.declare_entry("Allowable stress ratio",
                    "0.9",
                    Patterns::Double(),
                    "Allowable stress over the yield strength (-), in (0, 1].");
  prm.declare_entry("Maximum uplift",
                    "0",
                    Patterns::Double(),
                    "Largest height a wheel (a one-sided contact) may lift off its "
                    "rail, max_uplift (m): the flange depth, or the gap of a "
                    "restraint. 0: not checked.");
  prm.declare_entry("Maximum slip",
                    "0",
                    Patterns::Double(),
                    "Largest slip of a wheel along its rail (m), its accumulated "
                    "slip_distance (a bound of its travel): the clearance to the end "
                    "stops. 0: not checked.");
  prm.declare_entry("Rope capacity",
                    "0",
                    Patterns::Double(),
                    "Largest rope tension allowed (N): the breaking force over the "
                    "safety factor. 0: not checked.");
  prm.declare_entry("Maximum lateral play",
                    "0",
                    Patterns::Double(),
                    "Largest lateral offset of a wheel from the middle of its flange "
                    "clearance, max_lateral_offset (m): the flange clearance plus what "
                    "the rail head allows. 0: not checked.");
  prm.leave_subsection();
}

void QualificationParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Qualification");
  const auto capacity = [&](const std::string &entry, const std::string &unit)
  {
    const double x = prm.get_double(entry);
    AssertThrow(std::isfinite(x) && x >= 0.,
                ExcMessage("Qualification/" + entry + " = " + prm.get(entry) +
                           ": expected a capacity >= 0 (" + unit + "; 0: not checked)"));
    return x;
  };
  yield_strength = capacity("Yield strength", "Pa");
  maximum_uplift = capacity("Maximum uplift", "m");
  maximum_slip = capacity("Maximum slip", "m");
  rope_capacity = capacity("Rope capacity", "N");
  maximum_lateral_play = capacity("Maximum lateral play", "m");
  allowable_stress_ratio = prm.get_double("Allowable stress ratio");
  AssertThrow(std::isfinite(allowable_stress_ratio) && allowable_stress_ratio > 0. &&
                  allowable_stress_ratio <= 1.,
              ExcMessage("Qualification/Allowable stress ratio = " +
                         prm.get("Allowable stress ratio") +
                         ": expected a ratio of the yield strength in (0, 1]"));
  prm.leave_subsection();
}

bool QualificationParameters::enabled() const
{
  return yield_strength > 0. || maximum_uplift > 0. || maximum_slip > 0. ||
         rope_capacity > 0. || maximum_lateral_play > 0.;
}

std::vector<QualificationDemand> run_demands(const std::string &summary_json)
{
  std::vector<QualificationDemand> demands;
  const QualificationJson s = QualificationJson::parse(summary_json, nullptr, false);
  if (s.is_discarded() || !s.is_object())
    return demands;
  const auto group = [&](const char *key) -> const QualificationJson *
  { return s.contains(key) && s[key].is_object() ? &s[key] : nullptr; };
  const auto add = [&](const std::string &check,
                       const std::string &item,
                       const QualificationJson &value,
                       const std::string &where)
  {
    if (value.is_number())
      demands.push_back({check, item, value.get<double>(), where});
  };
  for (const char *key : {"beam_stresses", "solids"})
    if (const auto *g = group(key))
      for (const auto &[name, e] : g->items())
        if (e.is_object() && e.contains("max_von_mises") &&
            e["max_von_mises"].is_object() && e["max_von_mises"].contains("value"))
          add("stress",
              name,
              e["max_von_mises"]["value"],
              format_where(e["max_von_mises"], "x", "time"));
  // the uplift of the wheels where the model has them (not of their
  // restraints), else of every one-sided contact
  const auto *wheels = group("wheels");
  if (const auto *g = group("contacts"))
    for (const auto &[name, e] : g->items())
      if (e.is_object() && e.contains("max_uplift") &&
          (!wheels || wheels->contains(name)))
        add("uplift", name, e["max_uplift"], format_where(e, nullptr, "max_uplift_time"));
  if (const auto *g = group("wheels"))
  {
    for (const auto &[name, e] : g->items())
      if (e.is_object() && e.contains("slip_distance"))
        add("slip", name, e["slip_distance"], "accumulated over the run");
    for (const auto &[name, e] : g->items())
      if (e.is_object() && e.contains("max_lateral_offset"))
        add("lateral offset",
            name,
            e["max_lateral_offset"],
            format_where(e, nullptr, "max_lateral_offset_time"));
  }
  if (const auto *g = group("rope_tension"))
    for (const auto &[name, e] : g->items())
      if (e.is_object() && e.contains("max"))
        add("rope", name, e["max"], "");
  // a wheel that left its rail (D2): the run stopped there, it fails
  if (const auto *d = group("derailment"))
    if (d->contains("wheel") && (*d)["wheel"].is_string() &&
        d->contains("lateral_offset") && (*d)["lateral_offset"].is_number() &&
        d->contains("derailment_offset") && (*d)["derailment_offset"].is_number())
    {
      add("derailment",
          (*d)["wheel"].get<std::string>(),
          (*d)["lateral_offset"],
          format_where(*d, nullptr, "time") + ", the run stopped there");
      demands.back().capacity = (*d)["derailment_offset"].get<double>();
    }
  return demands;
}

std::vector<QualificationDemand>
suite_demands(const std::vector<SuiteQuantity> &quantities)
{
  std::vector<QualificationDemand> demands;
  // in the order of the checks, each in the order of the suite's columns
  for (const auto &kind : check_kinds)
  {
    const std::string suffix = kind.suite_suffix;
    for (const SuiteQuantity &q : quantities)
      if (q.quantity.size() > suffix.size() &&
          q.quantity.compare(q.quantity.size() - suffix.size(), suffix.size(), suffix) ==
              0)
        demands.push_back({kind.check,
                           q.quantity.substr(0, q.quantity.size() - suffix.size()),
                           q.value,
                           "governing member " + q.governing_member});
  }
  return demands;
}

std::vector<QualificationRow> qualify(const std::vector<QualificationDemand> &demands,
                                      const QualificationParameters &parameters)
{
  std::vector<QualificationRow> rows;
  for (const auto &d : demands)
  {
    const double capacity =
        d.capacity > 0. ? d.capacity : capacity_of(d.check, parameters);
    if (capacity <= 0.)
      continue; // not checked
    QualificationRow r;
    r.check = d.check;
    r.item = d.item;
    r.demand = d.value;
    r.capacity = capacity;
    r.unit = unit_of(d.check);
    r.ratio = d.value / capacity;
    r.passes = r.ratio <= 1.;
    r.where = d.where;
    rows.push_back(r);
  }
  return rows;
}

std::string qualification_csv(const std::vector<QualificationRow> &rows)
{
  std::string out = "check,item,demand,capacity,unit,ratio,verdict,where\n";
  for (const auto &r : rows)
    out += csv_field(r.check) + ',' + csv_field(r.item) + ',' +
           shortest_number(r.demand) + ',' + shortest_number(r.capacity) + ',' + r.unit +
           ',' + shortest_number(r.ratio) + ',' + (r.passes ? "pass" : "fail") + ',' +
           csv_field(r.where) + '\n';
  return out;
}

SummaryValue qualification_json(const std::vector<QualificationRow> &rows)
{
  SummaryValue list = SummaryValue::list();
  unsigned int n_fail = 0;
  for (const auto &r : rows)
  {
    n_fail += !r.passes;
    list.push_back(SummaryValue::object()
                       .set("check", r.check)
                       .set("item", r.item)
                       .set("demand", r.demand)
                       .set("capacity", r.capacity)
                       .set("unit", r.unit)
                       .set("ratio", r.ratio)
                       .set("verdict", r.passes ? "pass" : "fail")
                       .set("where", r.where));
  }
  return SummaryValue::object()
      .set("rows", list)
      .set("n_checks", static_cast<unsigned int>(rows.size()))
      .set("n_fail", n_fail)
      .set("passes", SummaryValue::boolean(n_fail == 0));
}

void print_qualification(const std::vector<QualificationRow> &rows, std::ostream &out)
{
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << "  qualification (qualification.csv):\n"
      << "    " << std::left << std::setw(16) << "check" << std::setw(26) << "item"
      << std::right << std::setw(14) << "demand" << std::setw(14) << "capacity"
      << "  " << std::left << std::setw(5) << "unit" << std::right << std::setw(9)
      << "ratio"
      << "  verdict  where\n";
  std::vector<const QualificationRow *> failing;
  for (const auto &r : rows)
  {
    out << "    " << std::left << std::setw(16) << r.check << std::setw(26) << r.item
        << std::right << std::setprecision(5) << std::setw(14) << r.demand
        << std::setw(14) << r.capacity << "  " << std::left << std::setw(5) << r.unit
        << std::right << std::setprecision(3) << std::setw(9) << r.ratio << "  "
        << std::left << std::setw(7) << (r.passes ? "pass" : "FAIL") << "  " << r.where
        << std::right << '\n';
    if (!r.passes)
      failing.push_back(&r);
  }
  // the closing line: the failing checks, the largest ratios first
  std::stable_sort(failing.begin(),
                   failing.end(),
                   [](const QualificationRow *a, const QualificationRow *b)
                   { return a->ratio > b->ratio; });
  out << "hati: qualification: ";
  if (rows.empty())
    out << "no item to check";
  else if (failing.empty())
    out << "all " << rows.size() << " checks pass";
  else
  {
    out << failing.size() << " of " << rows.size() << " checks fail (";
    for (unsigned int k = 0; k < failing.size() && k < 3; ++k)
      out << (k > 0 ? "; " : "") << failing[k]->item << ' ' << failing[k]->check
          << " ratio " << std::setprecision(3) << failing[k]->ratio
          << (failing[k]->where.empty() ? ""
              : failing[k]->where.rfind("governing member", 0) == 0
                  ? ", " + failing[k]->where // a suite's
                  : " at " + failing[k]->where);
    out << (failing.size() > 3 ? "; ..." : "") << ')';
  }
  out << std::endl;
  out.flags(flags);
  out.precision(precision);
}
} // namespace hati

#include <deal.II/base/utilities.h>

#include <hati/base/summary_value.h>
#include <hati/output/csv_file.h>
#include <hati/output/suite_statistics.h>
#include <hati/output/summary.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace hati
{
namespace
{
/** Largest value with its member, mean and count of @p values (value, member index). */
struct Statistic
{
  double max = 0., mean = 0.;
  unsigned int n = 0, governing = 0;
};

/**
 * The values of @p quantity of the usable members @p members of @p results,
 * with the index of their member.
 */
std::vector<std::pair<double, unsigned int>>
member_values(const std::vector<MemberResult> &results,
              const std::vector<unsigned int> &members,
              const std::string &quantity)
{
  std::vector<std::pair<double, unsigned int>> values;
  for (const unsigned int i : members)
    if (results[i].usable())
      for (const auto &[key, value] : results[i].values)
        if (key == quantity)
          values.emplace_back(value, i);
  return values;
}

/** Whether @p quantity is a smallest value (`..._min`): its envelope is the minimum. */
bool smallest_value(const std::string &quantity)
{
  return quantity.size() > 4 && quantity.compare(quantity.size() - 4, 4, "_min") == 0;
}

/**
 * The statistic of @p values; `max` and the governing member are the
 * smallest value's where @p smallest.
 */
Statistic statistic_of(const std::vector<std::pair<double, unsigned int>> &values,
                       const bool smallest = false)
{
  Statistic s;
  double sum = 0.;
  for (const auto &[value, member] : values)
  {
    if (s.n == 0 || (smallest ? value < s.max : value > s.max))
    {
      s.max = value;
      s.governing = member;
    }
    sum += value;
    ++s.n;
  }
  s.mean = s.n > 0 ? sum / s.n : 0.;
  return s;
}

/** The spectra.csv text of a member: its column names and rows of numbers. */
struct SpectraTable
{
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

SpectraTable parse_spectra(const std::string &text)
{
  SpectraTable table;
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line))
    return table;
  table.columns = dealii::Utilities::split_string_list(line, ',');
  while (std::getline(in, line))
    if (!line.empty())
      table.rows.push_back(dealii::Utilities::string_to_double(
          dealii::Utilities::split_string_list(line, ',')));
  return table;
}
} // namespace

SuiteStatistics::SuiteStatistics(const std::vector<MemberResult> &results,
                                 const std::vector<std::string> &variation_paths,
                                 const std::string &statistic)
    : results(results), variation_paths(variation_paths), statistic(statistic)
{
}

std::vector<std::vector<unsigned int>> SuiteStatistics::groups() const
{
  std::vector<std::vector<unsigned int>> groups;
  std::vector<std::pair<double, unsigned int>> keys;
  for (unsigned int i = 0; i < results.size(); ++i)
  {
    const std::pair<double, unsigned int> key(results[i].scale, results[i].variation);
    const auto it = std::find(keys.begin(), keys.end(), key);
    if (it == keys.end())
    {
      keys.push_back(key);
      groups.push_back({i});
    }
    else
      groups[it - keys.begin()].push_back(i);
  }
  return groups;
}

std::string SuiteStatistics::group_name(const unsigned int group) const
{
  const auto all = groups();
  if (group >= all.size())
    return "";
  const MemberResult &first = results[all[group][0]];
  std::ostringstream s;
  s << "scale " << first.scale;
  if (!variation_paths.empty())
    s << ", variation " << first.variation;
  return s.str();
}

std::vector<std::string> SuiteStatistics::quantities() const
{
  std::vector<std::string> names;
  for (const auto &r : results)
    for (const auto &[name, value] : r.values)
      if (std::find(names.begin(), names.end(), name) == names.end())
        names.push_back(name);
  return names;
}

std::string SuiteStatistics::csv() const
{
  const auto names = quantities();
  std::string out = "member,record,scale,variation";
  for (const auto &path : variation_paths)
    out += "," + csv_field(path);
  out += ",status,error,wall_time";
  for (const auto &name : names)
    out += "," + name;
  out += '\n';
  for (const auto &r : results)
  {
    out += r.name + "," + r.record + ",";
    append_number(out, r.scale);
    out += "," + std::to_string(r.variation);
    for (const auto &value : r.variation_values)
      out += "," + csv_field(value);
    out += "," + r.status + "," + csv_field(r.error) + ",";
    append_number(out, r.wall_time);
    for (const auto &name : names)
    {
      out += ',';
      for (const auto &[key, value] : r.values)
        if (key == name)
          append_number(out, value);
    }
    out += '\n';
  }
  return out;
}

std::string SuiteStatistics::summary_json(const SummaryEntries &extra) const
{
  SummaryValue failed = SummaryValue::object(), derailed = SummaryValue::object();
  unsigned int usable = 0, n_derailed = 0;
  for (const auto &r : results)
    if (r.usable())
      ++usable;
    else if (r.status == "derailed") // a result (D2): which wheel and when
    {
      ++n_derailed;
      derailed.set(r.name, r.error);
    }
    else
      failed.set(r.name, r.error.empty() ? r.status : r.status + ": " + r.error);
  SummaryValue group_list = SummaryValue::list();
  for (const auto &members : groups())
  {
    const MemberResult &first = results[members[0]];
    SummaryValue variation = SummaryValue::object();
    for (unsigned int v = 0; v < variation_paths.size(); ++v)
      variation.set(variation_paths[v], first.variation_values[v]);
    SummaryValue names = SummaryValue::list(), quantities_json = SummaryValue::object();
    for (const unsigned int i : members)
      names.push_back(results[i].name);
    for (const auto &quantity : quantities())
    {
      const std::vector<std::pair<double, unsigned int>> values =
          member_values(results, members, quantity);
      if (values.empty())
        continue;
      const Statistic s = statistic_of(values, smallest_value(quantity));
      quantities_json.set(quantity,
                          SummaryValue::object()
                              .set("value", statistic == "mean" ? s.mean : s.max)
                              .set("max", s.max)
                              .set("mean", s.mean)
                              .set("n", s.n)
                              .set("governing_member", results[s.governing].name));
    }
    group_list.push_back(SummaryValue::object()
                             .set("scale", first.scale)
                             .set("variation", first.variation)
                             .set("variation_values", variation)
                             .set("members", names)
                             .set("quantities", quantities_json));
  }
  SummaryEntries entries = {{"statistic", statistic},
                            {"n_members", results.size()},
                            {"n_usable", usable},
                            {"n_failed", results.size() - usable - n_derailed},
                            {"failed", failed},
                            {"n_derailed", n_derailed},
                            {"derailed", derailed},
                            {"groups", group_list}};
  entries.insert(entries.begin(), extra.begin(), extra.end());
  std::string out = "{\n";
  for (unsigned int i = 0; i < entries.size(); ++i)
    out += "  \"" + entries[i].first + "\": " + to_json(entries[i].second) +
           (i + 1 < entries.size() ? ",\n" : "\n");
  return out + "}\n";
}

std::vector<std::pair<std::string, double>>
SuiteStatistics::group_statistic(const unsigned int group) const
{
  std::vector<std::pair<std::string, double>> result;
  for (const SuiteQuantity &q : group_quantities(group))
    result.emplace_back(q.quantity, q.value);
  return result;
}

std::vector<SuiteQuantity>
SuiteStatistics::group_quantities(const unsigned int group) const
{
  std::vector<SuiteQuantity> result;
  const auto all = groups();
  if (group >= all.size())
    return result;
  for (const auto &quantity : quantities())
  {
    const auto values = member_values(results, all[group], quantity);
    if (values.empty())
      continue;
    const Statistic s = statistic_of(values, smallest_value(quantity));
    result.push_back(
        {quantity, statistic == "mean" ? s.mean : s.max, results[s.governing].name});
  }
  return result;
}

std::string SuiteStatistics::spectra_csv() const
{
  std::map<unsigned int, SpectraTable> tables;
  std::vector<std::string> columns; // spectrum columns, in order of appearance
  for (unsigned int i = 0; i < results.size(); ++i)
    if (results[i].usable() && !results[i].spectra.empty())
    {
      tables[i] = parse_spectra(results[i].spectra);
      for (unsigned int c = 2; c < tables[i].columns.size(); ++c)
        if (std::find(columns.begin(), columns.end(), tables[i].columns[c]) ==
            columns.end())
          columns.push_back(tables[i].columns[c]);
    }
  if (tables.empty())
    return "";
  std::string out = "scale,variation,damping_ratio,period";
  for (const auto &c : columns)
    out += "," + c;
  out += '\n';
  for (const auto &members : groups())
  {
    // the rows of the group's first member with spectra set the periods
    const SpectraTable *reference = nullptr;
    for (const unsigned int i : members)
      if (tables.count(i) && reference == nullptr)
        reference = &tables[i];
    if (reference == nullptr)
      continue;
    for (unsigned int row = 0; row < reference->rows.size(); ++row)
    {
      const auto &ref = reference->rows[row];
      append_number(out, results[members[0]].scale);
      out += "," + std::to_string(results[members[0]].variation) + ",";
      append_number(out, ref[0]);
      out += ',';
      append_number(out, ref[1]);
      for (const auto &column : columns)
      {
        std::vector<std::pair<double, unsigned int>> values;
        for (const unsigned int i : members)
        {
          const auto it = tables.find(i);
          if (it == tables.end() || row >= it->second.rows.size() ||
              it->second.rows[row][0] != ref[0] || it->second.rows[row][1] != ref[1])
            continue;
          const auto &cols = it->second.columns;
          const auto c = std::find(cols.begin(), cols.end(), column) - cols.begin();
          if (c < static_cast<long>(cols.size()) &&
              c < static_cast<long>(it->second.rows[row].size()))
            values.emplace_back(it->second.rows[row][c], i);
        }
        out += ',';
        if (!values.empty())
        {
          const Statistic s = statistic_of(values);
          append_number(out, statistic == "mean" ? s.mean : s.max);
        }
      }
      out += '\n';
    }
  }
  return out;
}
} // namespace hati

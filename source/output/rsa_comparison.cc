// The comparison of a suite of time histories with the response-spectrum
// analysis of its model (rsa_comparison.csv, suite_summary.json).

#include <deal.II/base/exceptions.h>

#include <hati/output/csv_file.h>
#include <hati/output/rsa_comparison.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace hati
{
using RsaJson = nlohmann::json;

namespace
{
/** Whether @p text ends with @p suffix; @p stem gets what precedes it. */
bool ends_with(const std::string &text, const std::string &suffix, std::string &stem)
{
  if (text.size() <= suffix.size() ||
      text.compare(text.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  stem = text.substr(0, text.size() - suffix.size());
  return true;
}

/** The number at @p path in @p j, or false. */
bool number_at(const RsaJson &j, const std::vector<std::string> &path, double &value)
{
  const RsaJson *node = &j;
  for (const std::string &key : path)
  {
    if (!node->is_object() || !node->contains(key))
      return false;
    node = &(*node)[key];
  }
  if (!node->is_number())
    return false;
  value = node->get<double>();
  return true;
}
} // namespace

std::vector<ComparisonRow>
rsa_comparison_rows(const std::vector<std::pair<std::string, double>> &statistic,
                    const std::string &rsa_summary)
{
  std::ifstream in(rsa_summary);
  AssertThrow(in,
              ExcMessage("cannot read the response-spectrum analysis's " + rsa_summary));
  const RsaJson summary = RsaJson::parse(in, nullptr, false);
  AssertThrow(!summary.is_discarded() && summary.contains("response_spectrum"),
              ExcMessage(rsa_summary + " has no response_spectrum entry"));
  const RsaJson &rs = summary["response_spectrum"];
  std::vector<ComparisonRow> rows;
  for (const auto &[quantity, value] : statistic)
  {
    ComparisonRow row{quantity, "", value, 0.};
    std::string stem;
    bool found = false;
    if (ends_with(quantity, ".peak_mean_force", stem))
    {
      row.unit = "N";
      found = number_at(rs, {"contacts", stem, "max_force"}, row.response_spectrum);
    }
    else if (ends_with(quantity, ".max_absolute_acceleration", stem))
    {
      row.unit = "m/s^2";
      found = number_at(rs, {"max_absolute_acceleration", stem}, row.response_spectrum);
    }
    else if (ends_with(quantity, ".max_von_mises", stem))
    {
      row.unit = "Pa";
      found = number_at(rs, {"max_von_mises", stem}, row.response_spectrum);
    }
    else if (quantity.rfind("section_force.", 0) == 0)
    {
      const std::string force = quantity.substr(14);
      row.unit = force == "N" ? "N" : "N m";
      found = number_at(
          rs, {"section_force_envelope", force, "max_abs"}, row.response_spectrum);
    }
    if (found)
      rows.push_back(row);
  }
  return rows;
}

std::string rsa_comparison_csv(const std::vector<ComparisonRow> &rows)
{
  std::ostringstream csv;
  use_shortest_numbers(csv);
  csv << "quantity,unit,time_history,response_spectrum,ratio\n";
  for (const ComparisonRow &r : rows)
    csv << r.quantity << ',' << r.unit << ',' << r.time_history << ','
        << r.response_spectrum << ',' << r.ratio() << '\n';
  return csv.str();
}

SummaryValue rsa_comparison_summary(const std::vector<ComparisonRow> &rows,
                                    const std::string &statistic,
                                    const std::string &rsa_folder)
{
  SummaryValue quantities = SummaryValue::object();
  for (const ComparisonRow &r : rows)
    quantities.set(r.quantity,
                   SummaryValue::object()
                       .set("unit", r.unit)
                       .set("time_history", r.time_history)
                       .set("response_spectrum", r.response_spectrum)
                       .set("ratio", r.ratio()));
  return SummaryValue::object()
      .set("time_history_statistic", statistic)
      .set("response_spectrum_folder", rsa_folder)
      .set("quantities", quantities);
}

std::string rsa_comparison_table(const std::vector<ComparisonRow> &rows,
                                 const std::string &statistic)
{
  std::ostringstream s;
  s << "  response spectrum against the time histories (" << statistic
    << " of the records; ratio = response spectrum / time history):\n"
    << "    " << std::left << std::setw(44) << "quantity" << std::setw(7) << "unit"
    << std::right << std::setw(14) << "time history" << std::setw(14) << "resp. spectr."
    << std::setw(8) << "ratio" << '\n';
  for (const ComparisonRow &r : rows)
    s << "    " << std::left << std::setw(44) << r.quantity << std::setw(7) << r.unit
      << std::right << std::setprecision(6) << std::setw(14) << r.time_history
      << std::setw(14) << r.response_spectrum << std::fixed << std::setprecision(3)
      << std::setw(8) << r.ratio() << std::defaultfloat << '\n';
  return s.str();
}
} // namespace hati

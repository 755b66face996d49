#ifndef hati_output_rsa_comparison_h
#define hati_output_rsa_comparison_h

#include <hati/base/summary_value.h>

#include <string>
#include <utility>
#include <vector>

namespace hati
{
/**
 * One row of `rsa_comparison.csv` (doc/user_guide.md, "Response-spectrum
 * analysis and what the time history saves"): a quantity both a suite of
 * time histories and the response-spectrum analysis of its model give.
 */
struct ComparisonRow
{
  std::string quantity, unit;
  /** The suite's statistic (mean of the records, or their envelope). */
  double time_history = 0.;
  /** The response-spectrum analysis's value. */
  double response_spectrum = 0.;
  /** response_spectrum / time_history (-; 0 if the time history is 0). */
  double ratio() const
  {
    return time_history != 0. ? response_spectrum / time_history : 0.;
  }
};

/**
 * The rows of the comparison: for every quantity of @p statistic (a
 * suite's group statistic, SuiteStatistics::group_statistic()) that the
 * response-spectrum analysis whose summary.json is @p rsa_summary gives:
 * each wheel's `peak_mean_force` against its contact's `max_force`, the
 * section-force envelope `section_force.N|My|Mz` against the RSA's over the
 * same members, each monitor's `max_absolute_acceleration` against the
 * length of its combined acceleration peaks, each solid's `max_von_mises`.
 * Throws a one-line message if the file cannot be read.
 */
std::vector<ComparisonRow>
rsa_comparison_rows(const std::vector<std::pair<std::string, double>> &statistic,
                    const std::string &rsa_summary);

/** `rsa_comparison.csv`: quantity, unit, time_history, response_spectrum, ratio. */
std::string rsa_comparison_csv(const std::vector<ComparisonRow> &rows);

/** suite_summary.json `rsa_comparison`: per quantity its row, and where the RSA is. */
SummaryValue rsa_comparison_summary(const std::vector<ComparisonRow> &rows,
                                    const std::string &statistic,
                                    const std::string &rsa_folder);

/** The table for the terminal. */
std::string rsa_comparison_table(const std::vector<ComparisonRow> &rows,
                                 const std::string &statistic);
} // namespace hati

#endif

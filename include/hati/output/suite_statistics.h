#ifndef hati_output_suite_statistics_h
#define hati_output_suite_statistics_h

#include <hati/base/summary_value.h>
#include <hati/output/member_result.h>

#include <string>
#include <vector>

namespace hati
{
/** One quantity of a suite's statistic: `<item>.<quantity>`, its value, its governing
 * member. */
struct SuiteQuantity
{
  std::string quantity;
  double value = 0.;
  std::string governing_member;
};

/**
 * The files of a suite from its members' results (doc/user_guide.md,
 * "Qualifying a crane on a suite of records"). The statistic is taken over
 * the records of each group of members with the same scale factor and
 * variation, over the members whose results are usable (completed or
 * reused): `envelope` is the largest value, `mean` the mean; the governing
 * member of a quantity is the one with the largest value. A quantity named
 * `..._min` (a smallest value, e.g. `runway_load.vertical_min`) is the
 * other way round: its envelope and governing member are the smallest.
 */
class SuiteStatistics
{
public:
  /**
   * @p results: every member, in suite order; @p variation_paths: the
   * parameter of each Suite/Variations entry; @p statistic: `envelope` or `mean`.
   */
  SuiteStatistics(const std::vector<MemberResult> &results,
                  const std::vector<std::string> &variation_paths,
                  const std::string &statistic);

  /**
   * `suite.csv`: one row per member: member, record, scale, variation, the
   * value of each variation (column named by its parameter), status, error,
   * wall_time (s) and the key results (union over the members; empty where a
   * member has none).
   */
  std::string csv() const;

  /**
   * `suite_summary.json`: the statistic, the member counts, the failed
   * members with their errors, and per group (scale, variation) each
   * quantity's value of the statistic, max, mean, the number of members and
   * the governing member; @p extra entries (e.g. wall times) come first.
   */
  std::string summary_json(const SummaryEntries &extra = {}) const;

  /**
   * The statistic (the suite's: mean or envelope) of every quantity over
   * the usable members of the group @p group (0: the first scale factor
   * and variation), in the order of quantities().
   */
  std::vector<std::pair<std::string, double>>
  group_statistic(unsigned int group = 0) const;

  /** group_statistic() with the governing member of each quantity. */
  std::vector<SuiteQuantity> group_quantities(unsigned int group = 0) const;

  /** The number of groups (scale factor, variation). */
  unsigned int n_groups() const { return groups().size(); }

  /** The group @p group in words: `scale 1.5` and, with variations, `variation 2`. */
  std::string group_name(unsigned int group) const;

  /**
   * `suite_spectra.csv`: per group (scale, variation), damping ratio and
   * period the statistic of every spectrum column of the members'
   * spectra.csv (m/s^2); empty when no member has spectra.
   */
  std::string spectra_csv() const;

private:
  /** Indices of the members of each group, groups in order of appearance. */
  std::vector<std::vector<unsigned int>> groups() const;
  /** The quantities of the members, in order of first appearance. */
  std::vector<std::string> quantities() const;

  const std::vector<MemberResult> &results;
  const std::vector<std::string> variation_paths;
  const std::string statistic;
};
} // namespace hati

#endif

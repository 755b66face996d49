#ifndef hati_output_qualification_h
#define hati_output_qualification_h

#include <deal.II/base/parameter_handler.h>

#include <hati/base/summary_value.h>
#include <hati/output/suite_statistics.h>

#include <ostream>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * `Qualification` subsection (doc/user_guide.md, "The qualification
 * report"): the capacities the results of a transient run, a suite or a
 * response-spectrum analysis are checked against (doc/theory.md 15.3, Q1).
 * A capacity of 0 leaves its check out.
 */
struct QualificationParameters
{
  static void declare_parameters(ParameterHandler &prm);
  /** Parse and check: one-line errors naming the entry. */
  void parse_parameters(ParameterHandler &prm);

  /** Pa; 0: no stress check. */
  double yield_strength = 0.;
  /** The allowable stress over the yield strength (-), in (0, 1]. */
  double allowable_stress_ratio = 0.9;
  /** m; 0: no uplift check. */
  double maximum_uplift = 0.;
  /** m; 0: no slip check. */
  double maximum_slip = 0.;
  /** N; 0: no rope check. */
  double rope_capacity = 0.;
  /** m; 0: no lateral offset check. */
  double maximum_lateral_play = 0.;

  /** Whether any check is asked for (then the verdicts and the report are made). */
  bool enabled() const;
  /** The allowable stress (Pa): ratio x yield strength. */
  double allowable_stress() const { return allowable_stress_ratio * yield_strength; }
};

/**
 * One demand of a check: a result of the run or suite for one item (a
 * member, a wheel, a rope) and where it governs (the station and time of a
 * run, the governing member of a suite).
 */
struct QualificationDemand
{
  /**
   * `stress`, `uplift`, `slip`, `lateral offset`, `rope`, or `derailment`
   * (a run a wheel left its rail in, D2: the wheel's lateral offset against
   * its derailment offset, so that it fails).
   */
  std::string check, item;
  double value = 0.;
  std::string where;
  /** > 0: the capacity the result gives itself (a derailment's), not the parameters'. */
  double capacity = 0.;
};

/** One row of the verdict table (qualification.csv). */
struct QualificationRow
{
  std::string check, item;
  double demand = 0., capacity = 0.;
  std::string unit;
  /** demand / capacity (-). */
  double ratio = 0.;
  bool passes = true;
  std::string where;
};

/**
 * The demands in the summary.json text @p summary_json of a transient run
 * (or of a response-spectrum analysis): `beam_stresses.<m>.max_von_mises`
 * and `solids.<s>.max_von_mises` (stress), `contacts.<c>.max_uplift`
 * (uplift: of the `wheels` where the summary has them, not their
 * restraints; else of every one-sided contact), `wheels.<w>.slip_distance`
 * (slip), `.max_lateral_offset`
 * (lateral offset), `rope_tension.<r>.max` (rope), each with its station
 * and time where the summary gives them (or its own `where`).
 */
std::vector<QualificationDemand> run_demands(const std::string &summary_json);

/**
 * The demands of a suite's statistic @p quantities (suite.csv's columns:
 * `<item>.max_von_mises`, `.max_uplift`, `.slip_distance`,
 * `.max_lateral_offset`, `.max_tension`), each where its governing member.
 */
std::vector<QualificationDemand>
suite_demands(const std::vector<SuiteQuantity> &quantities);

/**
 * The verdicts (Q1): every demand whose check has a capacity in
 * @p parameters against it, ratio = demand / capacity, passing at ratio <= 1.
 */
std::vector<QualificationRow> qualify(const std::vector<QualificationDemand> &demands,
                                      const QualificationParameters &parameters);

/** `qualification.csv`: check,item,demand,capacity,unit,ratio,verdict,where. */
std::string qualification_csv(const std::vector<QualificationRow> &rows);

/** summary.json `qualification`: `rows` (the CSV's columns), `n_checks`, `n_fail`,
 * `passes`. */
SummaryValue qualification_json(const std::vector<QualificationRow> &rows);

/**
 * The verdict table on @p out and the closing line, e.g. `hati:
 * qualification: 3 of 41 checks fail (girder_1 stress ratio 1.12 at x = 10
 * m, t = 3.06 s; ...)`.
 */
void print_qualification(const std::vector<QualificationRow> &rows, std::ostream &out);
} // namespace hati

#endif

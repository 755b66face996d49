#ifndef hati_run_suite_plan_h
#define hati_run_suite_plan_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/** One record of `Suite/Records`: its name and its X, Y, Z files (empty: none). */
struct SuiteRecord
{
  std::string name;
  std::array<std::string, 3> files;
  /**
   * An artificial record (`Records = artificial`): its files are written
   * after the suite's checks (RecordGeneration::write()), so that a refused
   * suite writes nothing.
   */
  bool generated = false;
};

/**
 * One entry of `Suite/Variations`: the parameter path (its parts trimmed,
 * joined by `/`) and its values.
 */
struct SuiteVariation
{
  std::string path;
  std::vector<std::string> values;
};

/** The most members a suite may have (records x scale factors x variations). */
constexpr unsigned int max_suite_members = 10000;

/**
 * `subsection Suite` (doc/user_guide.md, "Qualifying a crane on a suite of
 * records"): the records, the scale factors and the parameter variations
 * whose every combination is one member run, and the statistic over the
 * records. Without records, variations and scale factors other than 1 the
 * run is a single run (active() is false).
 */
struct SuiteParameters
{
  static void declare_parameters(ParameterHandler &prm);
  /**
   * Read and check them; one-line errors name the entry: a record name
   * twice, a scale factor twice (numerically equal), an entry twice in
   * Variations, a variation of an entry the suite sets itself (Suite/...,
   * Output/Output directory, Loading/Accelerogram scale factor, Loading/
   * Accelerogram X|Y|Z with Records) or of Analysis/Type (a suite runs
   * transient analyses), more than max_suite_members members.
   * `Records = artificial` takes @p artificial
   * (RecordGeneration::suite_records(); refused if empty).
   */
  void parse_parameters(ParameterHandler &prm,
                        const std::vector<SuiteRecord> &artificial = {});

  /** The number of members: records (at least 1) x scale factors x variations. */
  unsigned int n_members() const;
  /** The number of combinations of the variations' values (1 without variations). */
  unsigned int n_variations() const;

  /** Whether the parameter file asks for a suite. */
  bool active() const;
  /** `envelope` or `mean`: Statistic, or by default mean from 7 records on. */
  std::string effective_statistic() const;

  std::vector<SuiteRecord> records;
  std::vector<double> scale_factors = {1.};
  std::vector<SuiteVariation> variations;
  /** As given: empty, `envelope` or `mean`. */
  std::string statistic;
  /** Suite/Fundamental period (s); 0: from a modal analysis. */
  double fundamental_period = 0.;
  /**
   * Suite/Response spectrum comparison: with a Design spectrum, compare the
   * suite with the response-spectrum analysis of its model.
   */
  bool response_spectrum_comparison = true;
};

/** One member run of a suite: which record, scale and variation, and its overrides. */
struct SuiteMember
{
  /** Position in the suite (0-based): records, then scales, then variations. */
  unsigned int index = 0;
  /** `<record>_s<scale>_<variation index>`: its folder in the suite's folder. */
  std::string name;
  std::string record;
  double scale = 1.;
  unsigned int variation = 0;
  /** The value of each Suite/Variations entry for this member. */
  std::vector<std::string> variation_values;
  /** `Subsection/Entry=value` overrides applied after the file and --set. */
  std::vector<std::string> overrides;
};

/**
 * The members of @p suite, in the order records, scale factors, variations
 * (the first variation varies slowest). @p folder is the suite's output
 * folder, @p base_scale the file's Loading/Accelerogram scale factor (the
 * member's factor is base_scale times its scale factor). Each member's
 * overrides set its accelerograms (unless Records is empty: the file's
 * own, record name `base`), its scale factor, its variation values, its
 * Output directory `<folder>/<name>` and reset `subsection Suite` and
 * `subsection Design spectrum` (the suite's target: a new one reuses the
 * members). Throws
 * a one-line message if a member's folder name would be longer than a file
 * name may be (255 bytes: a record name too long).
 */
std::vector<SuiteMember> plan_suite(const SuiteParameters &suite,
                                    const std::string &folder,
                                    const double base_scale);
} // namespace hati

#endif

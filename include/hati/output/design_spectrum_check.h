#ifndef hati_output_design_spectrum_check_h
#define hati_output_design_spectrum_check_h

#include <hati/base/summary_value.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
class DesignSpectrum;

/** The fewest records EN 1998-1 3.2.3.1.2 accepts to represent a spectrum. */
constexpr unsigned int min_ec8_records = 3;

/**
 * The check of EN 1998-1 3.2.3.1.2 for one component of a suite (DS2,
 * doc/theory.md 13.2; doc/user_guide.md, "Qualifying against a design spectrum"): at
 * least three records, the *mean* of their spectra against the target over
 * [0.2 T1, 2 T1], nowhere below 90 %, and the mean peak ground acceleration
 * not below the target's zero-period value. The mean whatever the number of
 * records: the envelope below seven records is EN 1998-1 4.3.3.4.3's rule
 * for the response values (Suite/Statistic), not for the records' spectra.
 */
struct ComponentSpectrumCheck
{
  /** The check periods (s), their target (m/s^2), the mean of the records' spectra
   * (m/s^2) and the ratio mean / target (-). */
  std::vector<double> periods, target, statistic, ratio;
  /** The number of records and whether it is at least min_ec8_records. */
  unsigned int n_records = 0;
  bool enough_records = false;
  /** Smallest ratio and its period (s). */
  double min_ratio = 0., period_of_min_ratio = 0.;
  /** min_ratio >= 0.9. */
  bool passes_90_percent = false;
  /** Mean of the records' peaks and the target's zero-period value (m/s^2). */
  double mean_pga = 0., target_pga = 0.;
  bool pga_not_below_target = false;
  /** enough_records, passes_90_percent and pga_not_below_target. */
  bool passes() const;
  /** Why the component fails, one sentence per failed condition (empty if it passes). */
  std::vector<std::string> reasons() const;
};

/**
 * The check of one component: @p spectra (one per record, m/s^2, at
 * @p periods), their peak accelerations @p pgas (m/s^2), the target at the
 * periods @p target and its zero-period value @p target_pga; the mean of
 * the spectra at each period against the target.
 */
ComponentSpectrumCheck check_component(const std::vector<double> &periods,
                                       const std::vector<std::vector<double>> &spectra,
                                       const std::vector<double> &pgas,
                                       const std::vector<double> &target,
                                       const double target_pga);

/** A suite's records for the check: the files of each global axis (empty: none). */
struct CheckedRecord
{
  std::string name;
  std::array<std::string, 3> files;
};

/**
 * `design_spectrum_check` of suite_summary.json: for each global axis that
 * a record has, the records read (Accelerogram::read(), @p units for
 * two-column files, times @p scale), their spectra at the target's damping
 * ratio over 100 periods equally spaced in log T over [0.2 T1, 2 T1]
 * (@p fundamental_period T1, s; the interval clipped to the Period range)
 * and check_component(). @p period_source says where T1 comes from. Also
 * returns, in @p csv, `design_spectrum_check.csv`: period, then per axis
 * the target, the mean and the ratio. Prints the table, the verdict and
 * its reasons to @p out. `passes_ec8` is false, with its `reasons`, if an
 * axis has fewer than three records, a mean below 90 % or a mean PGA below
 * the target's.
 */
SummaryValue design_spectrum_check(const DesignSpectrum &target,
                                   const std::vector<CheckedRecord> &records,
                                   const std::string &units,
                                   const double scale,
                                   const double fundamental_period,
                                   const std::string &period_source,
                                   std::string &csv,
                                   std::ostream &out);
} // namespace hati

#endif

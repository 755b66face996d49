#ifndef hati_run_record_generation_h
#define hati_run_record_generation_h

#include <deal.II/base/parameter_handler.h>

#include <hati/loading/artificial_records.h>
#include <hati/loading/design_spectrum.h>
#include <hati/run/suite_plan.h>

#include <memory>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The artificial records of a parameter file (doc/user_guide.md,
 * "Qualifying against a design spectrum"): `subsection Artificial records`
 * against `subsection Design spectrum`, written as PEER AT2 files in
 * `<output>/records/` (`art01_X.AT2`, ...), with `records.csv` (one row per
 * record and component: its peak, the target's, the deviation of its
 * spectrum, the iterations, the end velocity and displacement ratios),
 * `records_spectra.csv` (the target and every record's spectrum) and
 * `records.png` (scripts/plot_records.py). `Suite/Records = artificial`
 * runs them as a suite (suite_records()).
 */
class RecordGeneration
{
public:
  /**
   * Read both subsections of @p prm (one-line errors naming the entry);
   * the folder is `<Output/Output directory>/records`, by default
   * `output/<stem of @p parameter_file>/records`.
   */
  RecordGeneration(ParameterHandler &prm, const std::string &parameter_file);
  ~RecordGeneration();

  /** Whether records are asked for (Number > 0). */
  bool active() const { return records.number > 0; }

  /** The records as Suite/Records entries: `art01` with its component files. */
  std::vector<SuiteRecord> suite_records() const;

  /**
   * Generate every record (generate_record()), write its files and draw
   * records.png; prints a line per record and a summary. Throws a one-line
   * message if a record cannot meet the tolerance or a file cannot be
   * written.
   */
  void write() const;

  const DesignSpectrumParameters &spectrum_parameters() const { return spectrum; }

private:
  /** `art01` ... (two digits, three from 100 records on). */
  std::string record_name(const unsigned int index) const;

  DesignSpectrumParameters spectrum;
  ArtificialRecordParameters records;
  std::string folder;
};
} // namespace hati

#endif

#ifndef hati_output_postprocessor_h
#define hati_output_postprocessor_h

#include <hati/base/registry.h>
#include <hati/base/summary_value.h>
#include <hati/model/discrete_system.h>
#include <hati/output/output_writer.h>
#include <hati/output/run_directory.h>
#include <hati/parameters/run_parameters.h>

#include <array>
#include <functional>
#include <memory>
#include <ostream>

namespace hati
{
/**
 * A result computed from the states of a transient run at its history rows
 * (peaks, envelopes, spectra): it sees each row's OutputState and, at the
 * end, adds its summary.json entries and its lines of the terminal summary.
 * Registered in source/output/postprocessor.cc; every registered
 * post-processor that applies to the model (its factory returns one) runs.
 */
class Postprocessor
{
public:
  virtual ~Postprocessor() = default;

  /** Account for the state of one history row (whole model, time order). */
  virtual void history_row(const OutputState &state) = 0;

  /** Add the summary.json entries to @p summary and print the results on @p out. */
  virtual void finish(SummaryEntries &summary, std::ostream &out) const = 0;

  /** Write its own files into @p directory after finish() (none by default). */
  virtual void write_files(RunDirectory &directory) const { (void)directory; }
};

/** What a post-processor may use: the system, the ground motion, the Output parameters.
 */
struct PostprocessorInputs
{
  const DiscreteSystem &system;
  /** Ground acceleration per direction (m/s^2; empty: none). */
  const std::array<std::function<double(double)>, 3> &ground_acceleration;
  /** The Output parameters (Output/Spectra and its periods and damping ratios). */
  const OutputParameters &output;
};

/**
 * Makes a post-processor for @p inputs, or returns none if it does not
 * apply (e.g. a model without monitor points).
 */
using PostprocessorFactory =
    std::function<std::unique_ptr<Postprocessor>(const PostprocessorInputs &inputs)>;

/** The post-processors of transient runs, in the order they write their entries. */
const Registry<PostprocessorFactory> &postprocessor_registry();
} // namespace hati

#endif

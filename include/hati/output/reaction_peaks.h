#ifndef hati_output_reaction_peaks_h
#define hati_output_reaction_peaks_h

#include <hati/output/postprocessor.h>

#include <string>
#include <vector>

namespace hati
{
/**
 * The largest and smallest force of every reaction spring of the system
 * (DiscreteSystem::reaction_springs, `sign k u`, N) at the history rows,
 * with their times: summary.json `<group>.<name>.<direction>` = `{"max",
 * "max_time", "min", "min_time"}` (the crane's `runway_reaction`) and a
 * table on the terminal.
 */
class ReactionPeaks : public Postprocessor
{
public:
  /** Its entry of postprocessor_registry(): none without reaction springs. */
  static Registry<PostprocessorFactory>::Entry registration();

  explicit ReactionPeaks(const PostprocessorInputs &inputs);
  void history_row(const OutputState &s) override;
  void finish(SummaryEntries &summary, std::ostream &out) const override;

private:
  struct Peak
  {
    double max = 0., max_time = 0., min = 0., min_time = 0.;
    bool any = false;
  };
  const DiscreteSystem &system;
  /** Per spring: its monitor point's index. */
  std::vector<unsigned int> monitor_of;
  std::vector<Peak> peaks;
};
} // namespace hati

#endif

#ifndef hati_output_acceleration_peaks_h
#define hati_output_acceleration_peaks_h

#include <hati/output/postprocessor.h>

#include <utility>
#include <vector>

namespace hati
{
/**
 * The largest absolute acceleration of each monitor point (m/s^2), summary
 * entry `max_absolute_acceleration`: the relative velocity differenced
 * between two history rows plus the ground acceleration at the middle of
 * the interval (doc/user_guide.md, summary.json).
 */
class AccelerationPeaks : public Postprocessor
{
public:
  /**
   * Its entry of postprocessor_registry(), `absolute accelerations`: none
   * for a system without monitor points.
   */
  static Registry<PostprocessorFactory>::Entry registration();

  explicit AccelerationPeaks(const PostprocessorInputs &inputs);
  void history_row(const OutputState &s) override;
  void finish(SummaryEntries &summary, std::ostream &out) const override;

private:
  const DiscreteSystem &system;
  const std::array<std::function<double(double)>, 3> &ground;
  /** Per monitor: the peak (m/s^2) and its time (s). */
  std::vector<std::pair<double, double>> peaks;
  std::vector<std::vector<double>> last_velocity;
  double last_time = 0.;
  bool have_last = false;
};
} // namespace hati

#endif

#ifndef hati_output_response_spectra_h
#define hati_output_response_spectra_h

#include <hati/output/postprocessor.h>

#include <string>
#include <vector>

namespace hati
{
/**
 * The pseudo-acceleration response spectra of `Output/Spectra`
 * (doc/user_guide.md, "Response spectra"): at each history row the
 * absolute acceleration of every translation of the chosen monitor points
 * (the relative velocity differenced between two rows plus the ground
 * acceleration, at the middle of the interval, as AccelerationPeaks) and
 * the ground acceleration of every excited axis, and at the end the spectra
 * of these series (pseudo_acceleration_spectrum(), exact for the series
 * linear between the samples) per damping ratio and period in
 * `spectra.csv`: columns `damping_ratio, period, <monitor>.<axis>...,
 * ground.<axis>...` (-, s, m/s^2).
 */
class ResponseSpectra : public Postprocessor
{
public:
  /** Its entry of postprocessor_registry(), `response spectra`: none without
   * Output/Spectra. */
  static Registry<PostprocessorFactory>::Entry registration();

  explicit ResponseSpectra(const PostprocessorInputs &inputs);
  void history_row(const OutputState &s) override;
  void finish(SummaryEntries &summary, std::ostream &out) const override;
  /** Compute the spectra and replace `spectra.csv` by them. */
  void write_files(RunDirectory &directory) const override;

  /**
   * Refuse (one line) a request of @p output whose monitor names are not
   * monitor points of @p system, or whose history rows @p row_interval (s)
   * apart are more than a tenth of the shortest period: called before the
   * run writes anything (Problem::prepare_transient()).
   */
  static void check_request(const OutputParameters &output,
                            const DiscreteSystem &system,
                            const double row_interval);

private:
  /** One series: a monitor component (MonitorPoint::value()) or a ground axis. */
  struct Channel
  {
    std::string name;
    const MonitorPoint *monitor = nullptr;
    unsigned int component = 0;
    unsigned int axis = 0;
    bool ground = false;
    double last_velocity = 0.;
    std::vector<double> values;
  };

  const std::array<std::function<double(double)>, 3> &ground;
  const std::vector<double> damping_ratios, periods;
  std::vector<Channel> channels;
  /** The middle of each interval between two history rows (s). */
  std::vector<double> times;
  double last_time = 0.;
  bool have_last = false;
};
} // namespace hati

#endif

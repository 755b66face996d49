#ifndef hati_loading_accelerogram_h
#define hati_loading_accelerogram_h

#include <string>
#include <vector>

namespace hati
{
/**
 * A recorded ground acceleration a_g(t) (m/s^2), sampled at times t_i and
 * linearly interpolated between them (algorithms.md section 4); zero before
 * the first and after the last sample.
 *
 * Readers:
 * - PEER NGA `.AT2` (units of g): four header lines, the fourth either
 *   `NPTS=  4000, DT=   .0100 SEC, ...` or `4000   0.0100  NPTS, DT`, then the
 *   values, any number per line; the count must equal NPTS. Sample i is at
 *   t = i DT.
 * - two-column text `time value` (other files), with the units given; lines
 *   starting with '#' and empty lines are skipped; times must increase.
 *
 * Anything malformed is an error naming the file and the line. The path
 * must be a regular file (checked with stat() before opening: a FIFO or a
 * device is refused at once); an AT2 header needs 1e-6 s <= DT <= 1 s and
 * NPTS <= 1e8, a two-column file at most 1e8 samples.
 */
class Accelerogram
{
public:
  /**
   * Read @p filename; @p units ("g", "m/s^2" or "cm/s^2") applies to
   * two-column files (AT2 files are in g), @p scale multiplies every value.
   * Errors start with @p entry, the parameter that named the file (e.g.
   * `Loading/Accelerogram X`), when it is not empty.
   */
  static Accelerogram read(const std::string &filename,
                           const std::string &units,
                           double scale,
                           const std::string &entry = "");

  /** a_g(t) in m/s^2, linear interpolation. */
  double operator()(const double t) const;

  /** Largest |a_g| (m/s^2) and the time at which it occurs (s). */
  std::pair<double, double> peak() const;

  const std::vector<double> &times() const { return t; }
  const std::vector<double> &values() const { return a; }

private:
  std::vector<double> t, a;
};

/** Standard gravity used to convert accelerations in g (m/s^2). */
constexpr double standard_gravity = 9.80665;
} // namespace hati

#endif

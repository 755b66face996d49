#ifndef hati_run_run_tools_h
#define hati_run_run_tools_h

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <hati/output/output_writer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace hati
{
/** Steps between two outputs of interval @p interval (s); 0 means every step. */
inline unsigned long steps_between(const double interval, const double dt)
{
  if (interval <= 0.)
    return 1;
  return std::max<unsigned long>(1, std::llround(interval / dt));
}

/** Throw a one-line message if @p u holds a NaN or an Inf at time @p t (s). */
inline void check_finite(const dealii::Vector<double> &u, const double t)
{
  if (!std::isfinite(u.l2_norm()))
  {
    std::ostringstream s;
    s << "the solution became non-finite (NaN or Inf) at t = " << t << " s";
    AssertThrow(false, dealii::ExcMessage(s.str()));
  }
}

/**
 * The state of an integrator with contacts for the output writer; the
 * impulses act over @p impulse_duration (s: the step, or 0 for an instant).
 */
template <class Integrator>
OutputState contact_state(const Integrator &integrator, const double impulse_duration)
{
  OutputState s;
  s.time = integrator.time();
  s.displacement = &integrator.displacement();
  s.velocity = &integrator.velocity();
  s.gaps = integrator.gaps();
  s.normal_velocities = integrator.normal_velocities();
  s.impulses = integrator.impulses();
  s.active = integrator.active();
  s.impulse_duration = impulse_duration;
  return s;
}

/** Progress lines of a long run, at most every @p interval seconds of wall time. */
class Progress
{
public:
  Progress(const double interval, const double end_time);

  /** Whether a progress line is due (and, if so, the next one counts from now). */
  bool due();

  /** Print the simulated time @p t (s), its fraction, the step and the remaining time. */
  void print(const double t, const unsigned long step) const;

  /** Wall time since the construction (s). */
  double wall_time() const;

private:
  const double interval, end_time;
  const std::chrono::steady_clock::time_point start;
  std::chrono::steady_clock::time_point last;
};
} // namespace hati

#endif

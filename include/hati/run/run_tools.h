#ifndef hati_run_run_tools_h
#define hati_run_run_tools_h

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <hati/model/model.h>
#include <hati/output/output_writer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace hati
{
/**
 * Steps between two outputs of interval @p interval (s); 0 means every step.
 * At most @p limit (an interval far beyond the run, e.g. 1e20 s, gives no
 * output between the first and the last step instead of an overflowed
 * rounding).
 */
inline unsigned long steps_between(const double interval,
                                   const double dt,
                                   const unsigned long limit = 1ul << 62)
{
  if (interval <= 0.)
    return 1;
  const double steps = interval / dt;
  if (!(steps < static_cast<double>(limit)))
    return limit;
  return std::max<unsigned long>(1, std::llround(steps));
}

/**
 * The finite-state watchdog of a run (issue #19, finding 3): every
 * displacement (and rotation) must stay finite and within
 * displacement_factor times the model size L, every velocity finite. L (m)
 * is the largest of Model::size(), the initial gaps of the contacts, the
 * initial displacements and 1 m. The transient loops check the state at
 * every output row and besides every step of Newmark, every check_interval
 * steps of CD-Lagrange and every check_interval micro steps of HATI (at
 * least every macro step; its global state is assembled for a check): one
 * pass over U and V, negligible beside the steps between two checks. Past the bound the
 * run stops with one line naming the quantity, its value, the DoF's place
 * and the time (summary.json: "failed").
 */
class Watchdog
{
public:
  /** The bound of |u| in model sizes (m per m, or rad per m). */
  static constexpr double displacement_factor = 1e3;
  /** CD-Lagrange (micro) steps between two checks besides those at output rows. */
  static constexpr unsigned long check_interval = 256;

  /** The bound of @p model, whose system @p system is (call after build()). */
  Watchdog(const Model &model, const DiscreteSystem &system);

  /**
   * Throw a one-line message if a displacement of @p u exceeds the bound
   * or is not finite, or a velocity of @p v (may be null) is not finite, at
   * time @p t (s).
   */
  void check(const dealii::Vector<double> &u,
             const dealii::Vector<double> *v,
             const double t) const;

  /**
   * The same for the solution @p u of a static analysis: a displacement
   * beyond the bound is a load out of scale or a structure held too
   * weakly, not a result (the message says so, without a time).
   */
  void check_static(const dealii::Vector<double> &u) const;

  /** The model size L (m). */
  double model_size() const { return size; }

private:
  /** The message of a state check() refused; @p t null: a static solution. */
  [[noreturn]] void fail(const dealii::Vector<double> &u,
                         const dealii::Vector<double> *v,
                         const double *t) const;
  /** Whether every displacement of @p u is within the bound (false for a NaN). */
  bool within_bound(const dealii::Vector<double> &u) const;

  const Model &model;
  double size;
};

/**
 * Watchdog::check() of @p u, @p v at @p t (s); on a failure the rows of
 * @p writer so far are flushed first (best effort), so that the files end
 * at the last output row before the divergence. Call it before a row.
 */
void check_state(const Watchdog &watchdog,
                 OutputWriter &writer,
                 const dealii::Vector<double> &u,
                 const dealii::Vector<double> *v,
                 const double t);

/**
 * The state of an integrator with contacts for the output writer, with the
 * displacement @p U and velocity @p V it gives; the impulses act over
 * @p impulse_duration (s: the step, or 0 for an instant).
 */
template <class Integrator>
OutputState contact_state(const Integrator &integrator,
                          const double impulse_duration,
                          const dealii::Vector<double> &U,
                          const dealii::Vector<double> &V)
{
  OutputState s;
  s.time = integrator.time();
  s.displacement = &U;
  s.velocity = &V;
  s.gaps = integrator.gaps();
  s.normal_velocities = integrator.normal_velocities();
  s.impulses = integrator.impulses();
  s.active = integrator.active();
  s.impulse_duration = impulse_duration;
  return s;
}

/** contact_state() with the integrator's displacement() and velocity(). */
template <class Integrator>
OutputState contact_state(const Integrator &integrator, const double impulse_duration)
{
  return contact_state(
      integrator, impulse_duration, integrator.displacement(), integrator.velocity());
}

/** Progress lines of a long run, at most every @p interval seconds of wall time. */
class Progress
{
public:
  /**
   * Lines every @p interval s of wall time for a run from @p start_time to
   * @p end_time (s of simulated time; a restart starts after 0).
   */
  Progress(const double interval, const double end_time, const double start_time = 0.);

  /** Whether a progress line is due (and, if so, the next one counts from now). */
  bool due();

  /** Print the simulated time @p t (s), its fraction, the step and the remaining time. */
  void print(const double t, const unsigned long step) const;

  /** Wall time since the construction (s). */
  double wall_time() const;

private:
  const double interval, end_time, start_time;
  const std::chrono::steady_clock::time_point start;
  std::chrono::steady_clock::time_point last;
};
} // namespace hati

#endif

#ifndef hati_run_time_loop_h
#define hati_run_time_loop_h

#include <deal.II/base/timer.h>

#include <hati/base/summary_value.h>

namespace hati
{
class Problem;
class RunDirectory;

/**
 * The time loop of a transient run with every output, shared by the
 * stepping integrators (CDLagrange, Newmark and HATICoupling, explicitly
 * instantiated in source/run/time_loop.cc): `ceil(T / dt)` steps, rows of
 * history.csv and energy.csv every `History interval`, VTU snapshots every
 * `Output interval` (rounded to whole steps) and at the last step, the
 * Watchdog's checks (run_tools.h) at output times and between them, a
 * warning if HATI makes fewer than ten macro steps, contact statistics
 * (every step, or every micro step of HATI), then summary.json with
 * @p summary (the method's own entries) first and the terminal summary.
 * SIGINT/SIGTERM stop the loop after a complete step.
 */
template <class Integrator>
void run_time_loop(Integrator &integrator,
                   Problem &problem,
                   RunDirectory &directory,
                   dealii::TimerOutput &timer,
                   SummaryEntries summary);
} // namespace hati

#endif

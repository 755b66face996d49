#ifndef hati_time_event_driven_h
#define hati_time_event_driven_h

#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>
#include <hati/parameters/run_parameters.h>
#include <hati/time/energies.h>

#include <functional>
#include <memory>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Event-driven reference integrator for small rigid or elastic systems:
 * CVODE (SUNDIALS 6, Adams method) integrates `M A + K U = F_ext(t)`
 * between impacts, CVODE's root finding locates each impact as a zero of a
 * gap `g_k = g0_k + L_k U` crossed downwards, and Newton's restitution law
 * is applied at the event as the LCP (doc/theory.md, eq. ED1)
 *
 *   0 <= L V+ + e L V-  _|_  lambda >= 0,   V+ = V- + M^-1 L^T lambda.
 *
 * It is exact up to the ODE tolerances (impact times of the bouncing ball
 * to ~1e-10 s) but cannot pass a Zeno accumulation point nor follow a
 * persistent contact: it stops with an error after a set number of events
 * or when a contact would stay closed. It refuses models with many DoFs.
 * deal.II 9.4 has no CVODE wrapper with root finding, so this class uses
 * the SUNDIALS C interface directly.
 */
class EventDriven
{
public:
  EventDriven(const DiscreteSystem &system, const TimeIntegrationParameters &parameters);
  ~EventDriven();

  /**
   * Integrate to @p t_out, calling @p on_event right after every impact
   * (the state then holds the post-impact velocity and the impulses).
   */
  void advance_to(const double t_out, const std::function<void()> &on_event);

  double time() const { return t; }
  const Vector<double> &displacement() const { return U; }
  const Vector<double> &velocity() const { return V; }
  std::vector<double> gaps() const;
  std::vector<double> normal_velocities() const;
  /** Impulses of the current event (N s); zero between events. */
  const std::vector<double> &impulses() const { return lambda; }
  /** Contacts of the current event. */
  const std::vector<bool> &active() const { return is_active; }
  unsigned int n_events() const { return events; }
  /** Exact energies: kinetic 1/2 V.MV, internal, works of loads and impulses. */
  Energies energies() const;

  /** Right-hand side of the first-order system (used by the CVODE callback). */
  void rhs(const double t, const double *y, double *ydot) const;
  /** Gap functions (used by the CVODE callback). */
  void gap_functions(const double *y, double *g) const;

private:
  void apply_impact(const std::vector<int> &roots);

  const DiscreteSystem &system;
  const TimeIntegrationParameters parameters;
  struct Cvode;
  std::unique_ptr<Cvode> cvode;
  double t = 0.;
  Vector<double> U, V, U0;
  mutable Vector<double> work_f, work_u, work_ku;
  std::vector<double> lambda;
  std::vector<bool> is_active;
  unsigned int events = 0;
  double contact_work = 0.;
};
} // namespace hati

#endif

#ifndef hati_time_cd_lagrange_h
#define hati_time_cd_lagrange_h

#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Discrete energies of the CD-Lagrange scheme at time t_n (J). The kinetic
 * energy is the staggered one, `1/2 V_{n-1/2} . M V_{n+1/2}`, so that
 * `kinetic + internal - external_work - contact_work` is constant to
 * round-off (doc/theory.md, eq. E1).
 */
struct Energies
{
  double kinetic = 0.;
  double internal = 0.;
  double external_work = 0.;
  double contact_work = 0.;
  /** Energy dissipated by damping (J), >= 0. */
  double dissipated = 0.;
  double total() const
  {
    return kinetic + internal + dissipated - external_work - contact_work;
  }
};

/**
 * The CD-Lagrange explicit event-capturing contact/impact integrator
 * (paper (3), algorithms.md A1-A6): central differences on a lumped mass,
 * velocity-level Lagrange multipliers for the contacts, Newton's
 * restitution law, no event detection and no penalty parameter.
 *
 * State: displacement U_n at integer times, velocity V_{n+1/2} at half
 * times. The integrator only sees a DiscreteSystem: it does not know
 * whether it holds a point mass, a bar or a solid.
 *
 * The stiffness is copied once into an operator scaled by `dt M^-1`, its
 * rows padded to a fixed width (ELLPACK) so that the row loop is unrolled at
 * compile time (bench/explicit_throughput.sh), so that the hot loop of a step is one pass
 * over U (A1) and one fused pass computing `V_free = V + dt M^-1 (F_ext - K U)` (A2-A3);
 * contacts (A4-A6) only touch the contact DoFs.
 */
class CDLagrange
{
public:
  /**
   * Prepare the integrator with time step @p dt (s). Throws, printing the
   * critical step `dt_crit = 2 / omega_max`, if `dt > safety * dt_crit`.
   * The initial half-step velocity is
   * `V_{1/2} = V_0 + dt/2 M^-1 (F_ext(0) - K U_0)`.
   */
  CDLagrange(const DiscreteSystem &system, const double dt, const double safety_factor);

  /** One step t_n -> t_{n+1}: (A1)-(A6). */
  void step();

  /** Critical time step 2 / omega_max (s); +infinity without stiffness. */
  double critical_time_step() const { return dt_crit; }
  double time_step() const { return dt; }
  double time() const { return t; }
  unsigned long step_number() const { return n_steps; }

  /** U_n. */
  const Vector<double> &displacement() const { return U; }
  /** V_{n+1/2}: the velocity on the step after t_n (right limit at impacts). */
  const Vector<double> &velocity() const { return *V; }

  /** Contact gaps g_k(U_n) (m), the same order as system.contacts. */
  const std::vector<double> &gaps() const { return gap; }
  /** Normal velocities L_k V_{n+1/2} (m/s). */
  std::vector<double> normal_velocities() const;
  /** Impulses lambda_k of the last step (N s); zero for inactive contacts. */
  const std::vector<double> &impulses() const { return lambda; }
  /** Whether contact k was active (g_k <= 0) in the last step (A4). */
  const std::vector<bool> &active() const { return is_active; }

  /** Discrete energies at t_n (computes K U_n: call at output times). */
  Energies energies() const;

private:
  void apply_contacts();

  const DiscreteSystem &system;
  const double dt;
  double dt_crit;
  double t = 0.;
  unsigned long n_steps = 0;

  // scaled stiffness dt M^-1 K in rows padded to row_width (free DoFs only)
  unsigned int row_width = 0;
  std::vector<unsigned int> column;
  std::vector<double> value;
  // dt M^-1 F_constant and dt M^-1 for the time-dependent loads
  /** External constant force with lumped-mass acceleration loads (N). */
  Vector<double> force;
  /** Time-dependent load shapes as this integrator applies them (N). */
  std::vector<Vector<double>> load_shapes;
  Vector<double> dt_minv_force;
  Vector<double> dt_minv;
  std::vector<Vector<double>> dt_minv_load_shapes;

  Vector<double> U;
  Vector<double> U0;
  Vector<double> velocity_a, velocity_b;
  Vector<double> *V;      // V_{n+1/2}
  Vector<double> *V_prev; // V_{n-1/2}

  // contacts
  std::vector<double> gap, lambda;
  std::vector<bool> is_active;
  std::vector<std::vector<unsigned int>> coupled_with;
  double contact_work = 0.;
  double time_dependent_work = 0.;
};
} // namespace hati

#endif

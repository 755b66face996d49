#ifndef hati_time_cd_lagrange_h
#define hati_time_cd_lagrange_h

#include <deal.II/lac/vector.h>

#include <hati/base/wall_clock.h>
#include <hati/model/discrete_system.h>
#include <hati/time/cd_lagrange_kernels.h>
#include <hati/time/energies.h>
#include <hati/time/force_law.h>
#include <hati/time/maxwell_memory.h>
#include <hati/time/rayleigh_damping.h>
#include <hati/time/unilateral_contacts.h>

#include <any>
#include <array>
#include <limits>
#include <memory>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The CD-Lagrange explicit event-capturing contact/impact integrator
 * (paper (3), algorithms.md A1-A7): central differences on a lumped mass,
 * velocity-level Lagrange multipliers for the contacts, Newton's
 * restitution law, no event detection and no penalty parameter, and
 * Rayleigh damping `C = a0 M + a1 K` (A7, doc/theory.md 1.6).
 *
 * State: displacement U_n at integer times, velocity V_{n+1/2} at half
 * times. The integrator only sees a DiscreteSystem: it does not know
 * whether it holds a point mass, a bar or a solid.
 *
 * The stiffness is copied once into an operator scaled by `dt M^-1`, its
 * rows grouped by their number of entries and padded to the group's width
 * (sliced ELLPACK) so that the row loop is unrolled at compile time
 * (bench/explicit_throughput.sh; rows wider than every compiled width, those
 * of solids, in CSR without padding), so that the hot loop of a
 * step is one pass over U (A1) and one fused pass computing `V_free = V + dt M^-1 (F_ext
 * - K U)` (A2-A3); contacts (A4-A6) only touch the contact DoFs. With damping (A7) a
 * second kernel of the same shape computes `V_free = c1 V + c2 dt M^-1 (F_ext - K U - a1
 * K V)` and the damping force, `c1 = (1 - a0 dt/2) / (1 + a0 dt/2)`, `c2 = 1 / (1 + a0
 * dt/2)`; the undamped loop is unchanged. With frequency-range damping (A8) the memory
 * variables (MaxwellMemory) are updated after (A1) and a third kernel
 * computes `V_free = V + dt M^-1 (F_ext - K (U + S))`, still one pass over
 * the rows of K. The force laws of the system (ForceLaw, e.g. the ropes
 * of R1) add their forces to the external force of the update, in
 * registration order (force_law_registry()).
 */
class CDLagrange
{
public:
  /**
   * Prepare the integrator with time step @p dt (s) and Rayleigh damping
   * @p damping (`C = a0 M + a1 K` with the lumped M, a0 in 1/s, a1 in s;
   * none by default). Throws, printing the critical step
   * `dt_crit = (2 / omega_max) (sqrt(1 + xi^2) - xi)`,
   * `xi = a1 omega_max / 2` (A7; `2 / omega_max` without stiffness damping),
   * if `dt > safety_factor * dt_crit` (@p safety_factor, -). The initial
   * half-step velocity is `V_{1/2} = V_0 + dt/2 M^-1 G_0` with
   * `G_0 = F_ext(0) - K U_0 - C V_0` (doc/theory.md 1.1).
   *
   * With Maxwell branches @p branches (frequency-range damping, A8; not
   * combined with Rayleigh damping) the memory variables start at zero and
   * the critical step is `dt_crit = (2 / omega_max) / sqrt(1 + sum alpha)`.
   * The force laws' shares of `omega_max^2` (ForceLaw::omega_squared_bound())
   * are added to the model's.
   */
  CDLagrange(const DiscreteSystem &system,
             const double dt,
             const double safety_factor,
             const RayleighDamping &damping = RayleighDamping(),
             const MaxwellBranches &branches = MaxwellBranches());

  /**
   * One step t_n -> t_{n+1}: (A1)-(A7), i.e. predict(), free_velocity(),
   * finish_step().
   */
  void step();

  class CouplingView;
  /** The integrator as the coupling drives it (HATICoupling, G2-G3'). */
  CouplingView coupling_view();

  /**
   * The vectors of the linear state between two steps, {U_n, V_{n+1/2},
   * V_{n-1/2}, d_n}: the coupling adds the response to the interface
   * multiplier by superposition (G3') and reads and sets the state (the
   * macro-step map). `d_n = dt M^-1 D_n` (m/s) is the damping force of the
   * last update (A7), all zeros without damping. The dissipated energy is
   * quadratic in the state: the coupling corrects it with add_dissipated().
   * With frequency-range damping (A8) `d_n = dt M^-1 K S_n` and the memory
   * variables (memory()) are part of the state too.
   */
  std::array<Vector<double> *, 4> linear_state() { return {{&U, V, V_prev, &d_prev}}; }

  /** Everything a step changes, to redo steps (coupling with contacts). */
  struct Snapshot
  {
    Vector<double> U, V, V_prev, d_prev;
    /** The memory variables q_l and the branch work (A8). */
    std::vector<Vector<double>> q;
    double branch_work = 0.;
    double t = 0.;
    unsigned long n_steps = 0;
    double time_dependent_work = 0., dissipated = 0.;
    /** The state of each force law (ForceLaw::save(), e.g. the ropes' of R1). */
    std::vector<std::any> laws;
  };
  void save(Snapshot &snapshot) const;
  void restore(const Snapshot &snapshot);

  /** Diagonal of M^-1 (1/kg), zero on fixed DoFs. */
  const Vector<double> &inverse_mass() const { return minv; }

  /**
   * Critical time step (s): `(2 / omega_max) (sqrt(1 + xi^2) - xi)`,
   * `xi = a1 omega_max / 2` (A7; `2 / omega_max` for a1 = 0), or
   * `(2 / omega_max) / sqrt(1 + sum alpha)` with frequency-range damping
   * (A8); +infinity without stiffness.
   */
  double critical_time_step() const { return dt_crit; }
  /**
   * The stability check of the constructor without building the integrator
   * (A7, A8): `dt_crit` (s) of @p system with this damping; throws the
   * constructor's message if `dt > safety_factor dt_crit`. A run checks its
   * step with it before a long static solve.
   */
  static double stability_limit(const DiscreteSystem &system,
                                const double dt,
                                const double safety_factor,
                                const RayleighDamping &damping = RayleighDamping(),
                                const MaxwellBranches &branches = MaxwellBranches());
  double time_step() const { return dt; }
  double time() const { return t; }
  unsigned long step_number() const { return n_steps; }
  /**
   * Wall time spent in the contact resolution (A4-A6) of every step so
   * far (s), redone steps included: estimated from one step in
   * SampledWallClock::sample_every.
   */
  double contact_seconds() const { return contact_clock.seconds(); }

  /** U_n. */
  const Vector<double> &displacement() const { return U; }
  /** V_{n+1/2}: the velocity on the step after t_n (right limit at impacts). */
  const Vector<double> &velocity() const { return *V; }
  /**
   * The integer-time velocity at t_n into @p v (m/s): `(V_{n-1/2} +
   * V_{n+1/2}) / 2`, half of the step's impulses included (the velocity of
   * HATI's continuity, CouplingView::integer_velocity(); a restart's V_0,
   * RunState), zero on fixed DoFs.
   */
  void integer_velocity(Vector<double> &v) const;
  /**
   * The forces of the last step's impulses on the DoFs into @p r (N):
   * `M (V_{n+1/2} - V_{n-1/2}) / dt - G_n`, `G_n = F_ext(t_n) + F_laws -
   * K U_n - D_n` (A2-A7), i.e. `L^T r_n / dt` of the contacts' and the
   * bilateral rows' impulses (A4-A6) and of whatever else the step added
   * (HATI's interface force), round-off elsewhere. A restart adds them to
   * its `G_0` (DiscreteSystem::initial_contact_reaction, doc/theory.md 1.1).
   * With Rayleigh damping `D_n` is the one the restart's first half step
   * takes, `C V_n` at the integer-time velocity (initial_state()), so that
   * the restart's V_{1/2} is V_{n+1/2} (the unbroken run's `D_n` differs by
   * `C (V_{n-1/2} - V_n)`: 5.2e-10 of the velocities, restart.py).
   */
  void contact_force(Vector<double> &r) const;

  /** Contact gaps g_k(U_n) (m), the same order as system.contacts. */
  const std::vector<double> &gaps() const { return contacts->gaps(); }
  /** Normal velocities L_k V_{n+1/2} (m/s). */
  std::vector<double> normal_velocities() const;
  /** Impulses lambda_k of the last step (N s); zero for inactive contacts. */
  const std::vector<double> &impulses() const { return contacts->impulses(); }
  /** Whether contact k was active (g_k <= 0) in the last step (A4). */
  const std::vector<bool> &active() const { return contacts->active(); }
  /**
   * Coulomb friction (A9): tangential impulses and states of the last
   * step, friction work, the Gauss-Seidel counts.
   */
  const FrictionalContacts &friction() const { return contacts->friction(); }

  /** Mass-proportional Rayleigh coefficient a0 (1/s). */
  double mass_damping_coefficient() const { return a0; }
  /** Stiffness-proportional Rayleigh coefficient a1 (s). */
  double stiffness_damping_coefficient() const { return a1; }
  /** Whether a0 or a1 is non-zero (the damped kernel is used, A7). */
  bool damped() const { return a0 != 0. || a1 != 0.; }
  /** The memory variables of frequency-range damping (A8; inactive without). */
  const MaxwellMemory &memory() const { return branches; }

  /**
   * Energy dissipated by the damping since t = 0 (J): the work of the
   * damping force with the velocities of the updates,
   * `sum_j 1/2 (U_{j+1} - U_j) . (D_j + D_{j+1})` (doc/theory.md 1.6);
   * with frequency-range damping that work less the energy the branches
   * store (A8).
   */
  double dissipated_energy() const;
  /** Add @p energy (J) to dissipated_energy() (corrections of the coupling). */
  void add_dissipated(const double energy) { dissipated += energy; }

  /**
   * Discrete energies at t_n (computes K U_n: call at output times); the
   * internal energy includes the force laws' (ForceLaw::stored_energy()).
   */
  Energies energies() const;

  /**
   * The force laws of the system (e.g. the ropes of R1), in registration
   * order: their states at t_n, statistics and summaries.
   */
  const std::vector<std::unique_ptr<ForceLaw>> &force_laws() const { return laws; }

private:
  /** (A1), then the memory update (A8); see CouplingView::predict(). */
  void predict();
  /** (A2)-(A3), (A7), see CouplingView::free_velocity(). */
  void free_velocity(const bool with_loads = true);
  /** V_free becomes V_{n+3/2}, then (A4)-(A6), see CouplingView::finish_step(). */
  void finish_step(const bool with_contacts = true);
  /** The stability check of the constructor (A7, A8): throws if dt > safety dt_crit. */
  void check_time_step(const double safety_factor);
  /**
   * stability_limit() with the laws made and the damping reduced to a1 and
   * the branches (whether any, sum alpha).
   */
  static double stability_limit(const DiscreteSystem &system,
                                const std::vector<std::unique_ptr<ForceLaw>> &laws,
                                const double dt,
                                const double safety_factor,
                                const double a1,
                                const bool with_branches,
                                const double alpha_sum);
  /** dt M^-1 K in row_groups. */
  void build_stiffness_operator();
  /** The constant force and the load shapes as this integrator applies them. */
  void build_loads();
  /** V_{1/2}, V_{-1/2} and d_0 from the initial state (A7, doc/theory.md 1.1). */
  void initial_state();
  /**
   * `dt M^-1 F_ext(t_{n+1})` with the time-dependent loads, in one pass
   * that also books their work on the step (A2-A3); returns step_force.
   */
  const double *load_step_force();
  /**
   * The pass of load_step_force() for the @p L loads from @p first on,
   * starting from `dt M^-1 F_constant` or, with @p Accumulate, from @p a
   * (the loads before them): more than three loads go in groups of three,
   * each load added in the same order as in one pass.
   */
  template <unsigned int L, bool Accumulate>
  void load_pass(const unsigned int n, double *a, const unsigned int first);

  const DiscreteSystem &system;
  const double dt;
  /** Rayleigh coefficients a0 (1/s), a1 (s) (A7). */
  const double a0, a1;
  /** Factors of the damped update, `(1 - a0 dt/2) / (1 + a0 dt/2)` and `1 / (1 + a0
   * dt/2)`. */
  const double c1, c2;
  double dt_crit;
  double t = 0.;
  unsigned long n_steps = 0;
  /** The contact resolution's wall time (contact_seconds(), sampled). */
  SampledWallClock contact_clock;

  /**
   * The scaled stiffness dt M^-1 K (free DoFs only), its rows grouped by
   * padded width (sliced ELLPACK), rows wider than every compiled kernel
   * (solids) and empty rows in one CSR group.
   */
  std::vector<cd_lagrange_kernels::RowGroup> row_groups;
  /** Each row's damping or branch work of a step (summed in row order). */
  std::vector<double> row_work;
  // dt M^-1 F_constant and dt M^-1 for the time-dependent loads
  /** External constant force with lumped-mass acceleration loads (N). */
  Vector<double> force;
  /** Time-dependent load shapes as this integrator applies them (N). */
  std::vector<Vector<double>> load_shapes;
  Vector<double> dt_minv_force;
  Vector<double> dt_minv;
  Vector<double> minv;
  /** Lumped mass (kg), zero on fixed DoFs. */
  Vector<double> mass;
  /** Zero vector: the load term of a homogeneous step. */
  Vector<double> zero_force;
  std::vector<Vector<double>> dt_minv_load_shapes;
  /** Where the damped kernel writes S V_{n+1/2} (nullptr: nowhere). */
  double *stiffness_velocity_out = nullptr;
  /** dt M^-1 F_ext(t_{n+1}) of the current step (load_step_force()). */
  Vector<double> step_force;
  /** Amplitudes of the time-dependent loads at t_{n+1} and t_n, their velocities. */
  std::vector<double> load_amplitude, load_previous_amplitude, load_velocity;
  /** The step whose amplitudes load_amplitude holds. */
  unsigned long amplitude_step = std::numeric_limits<unsigned long>::max();
  std::vector<const double *> load_shape_data, load_force_data;

  Vector<double> U;
  Vector<double> U0;
  Vector<double> velocity_a, velocity_b;
  Vector<double> *V;      // V_{n+1/2}
  Vector<double> *V_prev; // V_{n-1/2}
  /** `dt M^-1 D_n` (m/s), the damping force of the last update (A7). */
  Vector<double> d_prev;
  /** Work of the damping forces since t = 0 (J). */
  double dissipated = 0.;
  /** Memory variables of frequency-range damping (A8). */
  MaxwellMemory branches;

  double time_dependent_work = 0.;
  /**
   * The force laws in registration order (force_law_registry()): their
   * forces join the external loads (A2-A3), their rows' impulses follow
   * the free velocity (A4-A6).
   */
  std::vector<std::unique_ptr<ForceLaw>> laws;
  /** The laws that add forces, and those with rows. */
  std::vector<ForceLaw *> forcing_laws, row_laws;
  /**
   * The laws that switch contact rows off (ForceLaw::gates_rows(), e.g. the
   * flanges, D1) and their flags, one per row of system.contacts, which the
   * contacts' law reads (UnilateralContacts::switch_off()).
   */
  std::vector<ForceLaw *> gating_laws;
  std::vector<bool> rows_off;
  /**
   * The contacts' law among them (always there, possibly without rows):
   * the gaps, impulses and friction record that the outputs and the
   * coupling's superposition read and write.
   */
  UnilateralContacts *contacts = nullptr;
};
/**
 * The explicit integrator as the HATI coupling drives it (G2-G3',
 * HATICoupling, RampSuperposition): the phases of a step, the interface
 * force, the integer-time velocity and what the superposition of the unit
 * ramp responses writes back (state vectors, contact state, works). One
 * seam instead of public access to the integrator's internals; every call
 * is inline, so the coupling's micro-step loop costs what direct access
 * would. A view refers to its integrator, which must outlive it.
 *
 * A micro step: predict(), free_velocity(), any add_force() or
 * add_dof_force(), then finish_step(), then integer_velocity() if needed.
 */
class CDLagrange::CouplingView
{
public:
  explicit CouplingView(CDLagrange &integrator) : integrator(&integrator) {}

  /** (A1) `U_{n+1} = U_n + dt V_{n+1/2}`; the time advances to t_{n+1}. */
  void predict() { integrator->predict(); }

  /**
   * (A2)-(A3) the free velocity `V_free = V_{n+1/2} + dt M^-1 (F_ext(t_{n+1})
   * - K U_{n+1})`; with damping (A7)
   * `(1 + a0 dt/2) V_free = (1 - a0 dt/2) V_{n+1/2} + dt M^-1 (F_ext(t_{n+1})
   * - K U_{n+1} - a1 K V_{n+1/2})`, i.e. the damping force
   * `D_{n+1} = a0 M (V_{n+1/2} + V_free)/2 + a1 K V_{n+1/2}`, whose work
   * is booked in dissipated_energy(). Without the external loads if
   * @p with_loads is false (the homogeneous response of the coupling's unit
   * ramp, G3'); the rope forces (R1) go with the loads: they are part of
   * the actual step, not of the linear ramp response.
   */
  void free_velocity(const bool with_loads = true)
  {
    integrator->free_velocity(with_loads);
  }

  /**
   * Add a force @p force (N) along the row @p row acting over the whole step:
   * `V_free += dt M^-1 row^T force` (the interface force `C_E^T Lambda_j`
   * of G2). It is not scaled by the damping factor `c2` and not part of the
   * damping force D_{n+1} (A7).
   */
  void add_force(const SparseRow &row, const double force)
  {
    row.add_transpose(force, integrator->dt_minv, *integrator->V_prev);
  }
  /** add_force() for a row with the coefficient 1 on DoF @p i alone. */
  void add_dof_force(const unsigned int i, const double force)
  {
    (*integrator->V_prev)[i] += integrator->dt_minv[i] * force;
  }

  /**
   * The velocity at the integer time t_{n+1} of DoF @p i (G2, G3'),
   * `(V_{n+1/2} + V_{n+3/2}) / 2 = V_{n+1/2} + dt/2 M^-1 (F_{n+1} + r_{n+1})`,
   * valid after finish_step(): `F_{n+1}` the whole force of the update
   * (damping D_{n+1} included, A7) and `r_{n+1}` the impulses of the step
   * (contacts, bilateral rows; A4-A6) divided by dt. A DoF without an
   * impulse has `(V_{n+1/2} + V_free) / 2`; on a DoF that a closed contact
   * holds the impulse stands for the contact force, which the free velocity
   * lacks (doc/theory.md 9.2).
   */
  double integer_velocity(const unsigned int i) const
  {
    return 0.5 * ((*integrator->V)[i] + (*integrator->V_prev)[i]);
  }

  /** V_free becomes V_{n+3/2}; then the contacts (A4)-(A6) if @p with_contacts. */
  void finish_step(const bool with_contacts = true)
  {
    integrator->finish_step(with_contacts);
  }

  /**
   * With a non-null @p out (n_dofs() entries), the damped steps write
   * `S V_{n+1/2}`, `S = dt M^-1 K`, the stiffness part of the damping
   * force (A7), into it (the coupling's dissipated energy, G3');
   * nullptr stops it.
   */
  void record_stiffness_velocity(double *out)
  {
    integrator->stiffness_velocity_out = out;
  }

  /** `d_n = dt M^-1 D_n` (m/s), the damping force of the last update (A7). */
  const Vector<double> &damping_force() const { return integrator->d_prev; }

  /**
   * The time-dependent load shapes as the integrator applies them (N per
   * unit amplitude; acceleration loads with the lumped mass).
   */
  const std::vector<Vector<double>> &applied_load_shapes() const
  {
    return integrator->load_shapes;
  }

  /**
   * The trapezoidal weight `1/2 (a_l(t_n) + a_l(t_{n+1}))` of time-dependent
   * load @p l over the last step (its amplitudes as the step took them).
   */
  double load_step_weight(const unsigned int l) const
  {
    return 0.5 * (integrator->load_previous_amplitude[l] + integrator->load_amplitude[l]);
  }

  /**
   * With a non-null @p pattern (one flag per contact), the next steps take
   * the contacts flagged as active whatever their gap and solve (A5) as
   * bilateral constraints, `W lambda = -q` without the sign condition: the
   * linear response of the explicit part for a given active set (the
   * coupling's ramp responses); its frictional contacts stick (A9: tangent
   * rows as equalities) unless flagged in @p sliding (one flag per contact,
   * or nullptr: their tangent rows are left out). nullptr restores (A4)-(A5).
   */
  void prescribe_active_set(const std::vector<bool> *pattern,
                            const std::vector<bool> *sliding = nullptr)
  {
    integrator->contacts->prescribe_active_set(pattern, sliding);
  }

  /**
   * With a non-null @p pattern (one flag per contact), the next steps take
   * the flagged contacts as active and the others as open whatever their
   * gaps, and solve (A5) with its sign conditions and friction as usual:
   * the coupling's corrections with the contacts' closures frozen
   * (HATICoupling, doc/theory.md 9.6). nullptr restores (A4).
   */
  void freeze_activation(const std::vector<bool> *pattern)
  {
    integrator->contacts->freeze_activation(pattern);
  }

  /** @name What the superposition (G3') adds to the integrator's record */
  /** @{ */
  /** Set the gap (m) and impulse (N s) of contact @p k. */
  void set_contact_state(const unsigned int k, const double gap_k, const double impulse)
  {
    integrator->contacts->set_state(k, gap_k, impulse);
  }
  /** Add @p work (J) to the contact work. */
  void add_contact_work(const double work) { integrator->contacts->add_work(work); }
  /** The friction record (A9), which a redone pass replaces. */
  FrictionalContacts &friction() { return integrator->contacts->friction(); }
  /** Add @p work (J) to the external work. */
  void add_external_work(const double work) { integrator->time_dependent_work += work; }
  /** Add @p energy (J) to the dissipated energy. */
  void add_dissipated(const double energy) { integrator->add_dissipated(energy); }
  /**
   * The memory variables of frequency-range damping (A8), part of the
   * linear state: the ramp responses carry their own (G3').
   */
  MaxwellMemory &memory() { return integrator->branches; }
  /** @} */

private:
  CDLagrange *integrator;
};

inline CDLagrange::CouplingView CDLagrange::coupling_view()
{
  return CouplingView(*this);
}
} // namespace hati

#endif

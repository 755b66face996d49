#ifndef hati_time_force_law_h
#define hati_time_force_law_h

#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <hati/base/registry.h>
#include <hati/base/summary_value.h>
#include <hati/contact/friction_solver.h>
#include <hati/time/energies.h>

#include <any>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

class DiscreteSystem;
class LawOutput;
struct LawOutputContext;

/**
 * The state of the force laws after one step (or micro step) as the outputs
 * take it (ForceLaw::sample()): today the columns of the contacts' law
 * (UnilateralContacts), one entry per row of DiscreteSystem::contacts.
 * HATI records one per micro step and hands the final ones to the outputs
 * (HATICoupling::after_micro_step; the superposition corrects them, G3').
 */
struct LawSample
{
  /** The time of the state (s). */
  double time = 0.;
  /** Gaps (m), normal velocities `L_k V` (m/s) and impulses (N s) per row. */
  std::vector<double> gaps, normal_velocities, impulses;
  /** Whether each row was active in the step (A4). */
  std::vector<bool> active;
  /**
   * With friction (A9; empty otherwise): the tangential impulses (N s, two
   * per row), the slip velocity of each touching row (m/s) and its state.
   */
  std::vector<double> tangential_impulses, slip_velocities;
  std::vector<FrictionState> friction_states;
  /**
   * A sample of every step for the laws' outputs (LawOutput::add_step()):
   * a law may leave out the columns that only the output rows and the
   * coupling read (the contacts: the normal velocities), which would cost
   * every step.
   */
  bool every_step = false;
};

/**
 * A result that ends a transient run before its End time (ForceLaw::run_end(),
 * e.g. a wheel that has left its rail, D2): the run stops after the step in
 * which it happened, summary.json says `status` = status, and the terminal
 * prints message; it is a result, not an error (exit code 0).
 */
struct RunEnd
{
  /** The summary.json `status`, e.g. `derailed`. */
  std::string status;
  /** The one-line message, e.g. `crane_wheel_3 derailed at t = 4.213 s: ...`. */
  std::string message;
  /** The time at which it happened (s). */
  double time = 0.;
};

/**
 * One force law of a DiscreteSystem as the explicit integrator (CD-Lagrange,
 * and through it HATI's explicit part) and the outputs see it
 * (doc/architecture.md, "Force laws"). A law is one or both of
 *  - a force: a nonlinear force that joins the external force of the
 *    update (A2-A3, e.g. the ropes of R1; adds_forces(), start(), step()),
 *  - rows: sparse rows of the velocity-level operator `L` whose impulses
 *    the integrator applies after the free velocity (A4-A6, e.g. the
 *    unilateral contacts with their friction, A9, and the constraint rows
 *    of ties and rigid links, B1; has_rows(), start_rows(),
 *    apply_impulses(): the law forms its Delassus blocks `L M^-1 L^T`
 *    itself),
 * with its work and stored energy for the balance (E1, add_energies()),
 * the state a step changes (the coupling redoes steps, G3'; save(),
 * restore()), its share of the critical step (A7, omega_squared_bound())
 * its summary entries (add_summary()), its outputs (sample() of a step,
 * make_output(): statistics, summary entries and files of a run) and the
 * methods that can run it (refusal()). The integrator holds one
 * instance per law its system holds (make_force_laws()) and calls them in
 * registration order: the forces are summed in that order, and the rows of
 * different laws are resolved one law after the other (one sweep of a block
 * Gauss-Seidel), never in one cluster, so rows that must be solved together
 * with the contacts' (the tie and rigid-link rows, B1) belong to the
 * contacts' law (UnilateralContacts).
 *
 * A law is a class deriving from this one and an entry of
 * force_law_registry() whose factory returns an instance when the system
 * holds data of the law (its own member of DiscreteSystem, e.g. `ropes`,
 * or DiscreteSystem::law_data under the law's name) and nullptr otherwise.
 */
class ForceLaw
{
public:
  virtual ~ForceLaw() = default;

  /** The law's registered name (force_law_registry()), e.g. `ropes`. */
  virtual std::string name() const = 0;

  /** @name A force (R1, A2-A3) */
  /** @{ */
  /** Whether the law adds a force to the update (start(), step()). */
  virtual bool adds_forces() const { return false; }

  /**
   * At t = 0: the law's state at @p U (`U_0`) and its force added to @p f
   * (N; the `G_0` of the initial half step, doc/theory.md 1.1).
   */
  virtual void start(const Vector<double> &U, Vector<double> &f)
  {
    (void)U;
    (void)f;
  }

  /**
   * One step of (A2)-(A3): the force at @p U (`U_{n+1}`) added to @p a as
   * `dt M^-1 F` (with @p dt_minv = `dt M^-1`, zero on fixed DoFs), its work
   * on the step booked with the step's velocity @p V (`V_{n+1/2}`) and time
   * step @p dt (trapezoidal, so that E1 closes), the law's statistics.
   */
  virtual void step(const Vector<double> &U,
                    const Vector<double> &V,
                    const Vector<double> &dt_minv,
                    const double dt,
                    double *a)
  {
    (void)U;
    (void)V;
    (void)dt_minv;
    (void)dt;
    (void)a;
  }

  /**
   * The energy the law's force stores as the balance books it (J),
   * `Phi(U_0) - work`; add_energies() adds it to the internal energy (E1).
   */
  virtual double stored_energy() const { return 0.; }

  /**
   * The DoFs on which the law's force depends nonlinearly: HATI does not
   * superpose a unit ramp response that moves one of them (G3', the
   * responses are linear), it integrates the step instead.
   */
  virtual std::vector<types::global_dof_index> nonlinear_dofs() const { return {}; }

  /**
   * A bound of the change of the law's force, relative to its force scale,
   * when every DoF of nonlinear_dofs() moves by at most @p du (m): HATI
   * superposes a unit-ramp response that moves those DoFs while this is
   * at most RampSuperposition::nonlinear_force_tolerance (G3'). By default
   * 0 for @p du = 0 and infinity otherwise (never superposed).
   */
  virtual double relative_force_change(const double du) const
  {
    return du == 0. ? 0. : std::numeric_limits<double>::infinity();
  }

  /**
   * The force (N) the last step applied on each DoF of nonlinear_dofs(),
   * in that order, into @p f (HATI's superposition books its work on the
   * corrected velocities, G3'). Nothing by default (a law without
   * nonlinear_dofs()).
   */
  virtual void applied_force(double *f) const { (void)f; }

  /**
   * Add @p work (J) to the law's work on the structure: what a
   * superposition (G3') changed of the trapezoid of step() (E1).
   */
  virtual void add_superposed_work(const double work) { (void)work; }
  /** @} */

  /** @name Rows of the velocity-level operator (A4-A6) */
  /** @{ */
  /** Whether the law has rows whose impulses apply_impulses() adds. */
  virtual bool has_rows() const { return false; }

  /**
   * At t = 0, after the initial half step: the rows at @p U (`U_0`), with
   * @p dt_minv = `dt M^-1` (e.g. the clusters of rows that share a DoF).
   */
  virtual void start_rows(const Vector<double> &U, const Vector<double> &dt_minv)
  {
    (void)U;
    (void)dt_minv;
  }

  /**
   * (A4)-(A6) after (A2)-(A3): the impulses of the step at @p U
   * (`U_{n+1}`) with @p v_before (`V_{n+1/2}`, e.g. for Newton's
   * restitution) and @p inverse_mass (`M^-1`, zero on fixed DoFs): @p v,
   * the free velocity, becomes `V_{n+3/2} = V_free + M^-1 L^T lambda`; the
   * impulses' work is booked (E1).
   */
  virtual void apply_impulses(const Vector<double> &U,
                              const Vector<double> &v_before,
                              const Vector<double> &inverse_mass,
                              Vector<double> &v)
  {
    (void)U;
    (void)v_before;
    (void)inverse_mass;
    (void)v;
  }
  /** @} */

  /** @name Conditions on the rows of other laws (e.g. D1) */
  /** @{ */
  /**
   * Whether the law decides that some rows of DiscreteSystem::contacts do
   * not act in a step whatever their gaps (gate_rows()).
   */
  virtual bool gates_rows() const { return false; }

  /**
   * At @p t (`t_{n+1}`) and @p U (`U_{n+1}`), before the impulses (A4):
   * set the entries of @p off (one per row of DiscreteSystem::contacts) of
   * the rows the law governs, true for a row that does not act in this step
   * (out of the active set whatever its gap; a prescribed or frozen active
   * set, CDLagrange::CouplingView, is taken as it is), false for one that
   * acts as usual. The other entries are left as they are.
   */
  virtual void gate_rows(const double t, const Vector<double> &U, std::vector<bool> &off)
  {
    (void)t;
    (void)U;
    (void)off;
  }

  /**
   * The result that ends the run at the current state (e.g. a derailment,
   * D2), or nullptr while the run goes on (the default). The time loop
   * asks after every (macro) step.
   */
  virtual const RunEnd *run_end() const { return nullptr; }
  /** @} */

  /**
   * The law's terms of the energy balance (E1) added to @p e: by default
   * stored_energy() to the internal energy; the contacts set the contact
   * work and the friction dissipation.
   */
  virtual void add_energies(Energies &e) const { e.internal += stored_energy(); }

  /**
   * The critical step the law imposes, as its share of `omega_max^2`
   * (rad^2/s^2): a bound of the largest eigenvalue of `M^-1 K_law`, with
   * `K_law` the law's tangent stiffness, for a law whose stiffness the
   * model's bound (DiscreteSystem::highest_frequency_bound()) leaves out.
   * CD-Lagrange takes `omega_max^2 = omega_K^2 + sum omega_law^2` into its
   * `dt_crit` (A7): a bound of the sum (Weyl's inequality for the symmetric
   * `M^-1/2 (K + K_law) M^-1/2`), where the smaller of separate critical
   * steps would not be one. 0 (the default): none (a law of rows imposes
   * none: its impulses are solved exactly, A5).
   */
  virtual double omega_squared_bound() const { return 0.; }

  /**
   * Save everything a step changes into @p state (CDLagrange::Snapshot:
   * the coupling redoes steps). Reuses the storage @p state holds from a
   * previous save of the same law.
   */
  virtual void save(std::any &state) const = 0;
  /** Set the state saved by save(). */
  virtual void restore(const std::any &state) = 0;

  /**
   * After a transient run: the law's summary.json entries added to
   * @p summary and its lines of the terminal summary printed on @p out
   * (none by default).
   */
  virtual void add_summary(SummaryEntries &summary, std::ostream &out) const
  {
    (void)summary;
    (void)out;
  }

  /** @name Outputs */
  /** @{ */
  /**
   * The law's columns of @p s at the integrator's current state, with
   * @p V its velocity (`V_{n+1/2}` of CD-Lagrange), e.g. the contacts'
   * gaps, normal velocities, impulses, active flags and friction columns
   * (none by default). Fills the vectors of @p s in place: a sample reused
   * from step to step allocates nothing.
   */
  virtual void sample(const Vector<double> &V, LawSample &s) const
  {
    (void)V;
    (void)s;
  }

  /**
   * The law's share of a transient run's outputs (LawOutput: statistics of
   * every step from the samples, summary.json entries, terminal lines and
   * files), or nullptr (the default) when it has none. The output may keep
   * a reference to the law: it lives no longer than the integrator.
   */
  virtual std::unique_ptr<LawOutput> make_output(const LawOutputContext &context) const;
  /** @} */

  /**
   * Why the method @p method (a value of `Time integration/Method`) cannot
   * integrate a system holding this law: a one-line message, or empty if
   * it can. CD-Lagrange and HATI (its explicit part) drive every law
   * (`HATI` also checks the subdomains, Model/Decomposition); the others
   * (`Newmark`, `event-driven`) drive none, so by default they are refused
   * with a message that names the law. check_force_laws() asks every law.
   */
  virtual std::string refusal(const std::string &method) const;

  /**
   * The law's data (DiscreteSystem::law_data under name()) of a part of the
   * system, renumbered (HATI's subdomains, Model/Decomposition:
   * extract_subsystem()): @p local is the part's index of every DoF of the
   * system, -1 for a DoF the part does not hold, and @p fixed the system's
   * fixed flags (a fixed DoF may be dropped, as from a contact row). An
   * empty result: the part holds none of the law. By default refused (an
   * ExcMessage that names the law): a law whose data holds DoF indices
   * overrides this to renumber them.
   */
  virtual std::any part_data(const std::vector<int> &local,
                             const std::vector<bool> &fixed) const;
};

/** Makes the law for @p system, or nullptr if the system has no data of it. */
using ForceLawFactory =
    std::function<std::unique_ptr<ForceLaw>(const DiscreteSystem &system)>;

/**
 * The force laws, in the order the integrator applies them (their forces
 * are summed in this order), registered in source/time/force_law.cc; a
 * test or a plugin may add() its own before the integrators are built.
 */
Registry<ForceLawFactory> &force_law_registry();

/** An instance of every registered law that @p system holds, in registration order. */
std::vector<std::unique_ptr<ForceLaw>> make_force_laws(const DiscreteSystem &system);

/**
 * Throws (ExcMessage) the first refusal of @p method by a law of @p system
 * (ForceLaw::refusal(), registration order): the runners of the methods
 * that do not drive the laws call it before their set-up.
 */
void check_force_laws(const DiscreteSystem &system, const std::string &method);

/**
 * DiscreteSystem::law_data of @p full renumbered into @p part
 * (ForceLaw::part_data() of each law that has data; @p local as there):
 * extract_subsystem()'s share of the laws. Data that no registered law
 * takes is refused, naming its key.
 */
void extract_law_data(const DiscreteSystem &full,
                      const std::vector<int> &local,
                      DiscreteSystem &part);

/**
 * The sample of @p laws at velocity @p V into @p sample (its time is left
 * as it is): ForceLaw::sample() of every law, in order.
 */
void sample_force_laws(const std::vector<std::unique_ptr<ForceLaw>> &laws,
                       const Vector<double> &V,
                       LawSample &sample);
} // namespace hati

#endif

#ifndef hati_time_hati_coupling_h
#define hati_time_hati_coupling_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/model/decomposition.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/damping.h>
#include <hati/time/energies.h>
#include <hati/time/interface_problem.h>
#include <hati/time/newmark.h>
#include <hati/time/ramp_superposition.h>
#include <hati/time/rayleigh_damping.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hati
{
/** The `Time integration/HATI` subsection. */
struct HATIParameters
{
  /** Declare "Time step ratio" and "Coupling method" (the caller enters the subsection).
   */
  static void declare_parameters(ParameterHandler &prm);
  /** Read them; throws a one-line error for a ratio outside [1, max_time_step_ratio]. */
  void parse_parameters(ParameterHandler &prm);

  /**
   * Largest Time step ratio (-): the unit-ramp responses hold m micro steps
   * (about 2 GB for the bridge crane at m = 10000).
   */
  static constexpr long max_time_step_ratio = 10000;

  /** m = DT / dt (-), integer from 1 to max_time_step_ratio. */
  unsigned int time_step_ratio = 1;
  /**
   * "macro-linear": (G3'), continuity at the macro-step ends with the
   * multiplier linear in time over the macro step (the stable variant).
   */
  std::string coupling_method = "macro-linear";
  /**
   * "Superposition": whether macro steps with contacts or ropes within reach
   * are superposed when they may be (true) or always redone (false, a check).
   */
  bool superposition = true;
};

/**
 * The heterogeneous asynchronous time integrator (paper (4)-(10),
 * Gravouil-Combescure; doc/theory.md section 9): the explicit subdomain
 * integrated by CD-Lagrange with the micro step dt, the implicit one by
 * Newmark with the macro step DT = m dt, glued at the interface DoFs by
 * Lagrange multipliers Lambda (interface forces, acting as `C_E^T Lambda`
 * on the explicit side and `C_I^T Lambda` on the implicit side, with
 * `C_E = +1`, `C_I = -1` on the interface DoF pairs, or the general rows of
 * a tie across, G3'', doc/theory.md 11.3).
 *
 * One macro step [t_n, t_{n+m}] (step()) with the interface problem (G3'),
 * the multiplier linear in time over the macro step:
 * - (G1) the free implicit step: Newmark over DT without interface force;
 * - (G2) m explicit micro steps under the known part `(1 - j/m) Lambda_n`
 *   of `Lambda_j = (1 - j/m) Lambda_n + (j/m) Lambda_{n+m}`, with the
 *   contacts;
 * - (G3') one interface solve
 *   `(C_E V_ramp + gamma DT C_I M_eff^-1 C_I^T) Lambda_{n+m}
 *    = -(C_E V^E_a + C_I V^I_free)`, velocity continuity at t_{n+m} with
 *   the integer-time explicit velocity; the matrix is assembled and
 *   inverted once (n_G x n_G, small); `V_ramp` is the explicit response to a unit ramp
 *   `(j/m) e_k` from rest, computed once with the explicit integrator's own
 *   code path, and the part `Lambda_{n+m}` is added to the explicit state
 *   by superposition;
 * - (G4) the implicit link `A_link = M_eff^-1 C_I^T Lambda_{n+m}`.
 *
 * The interface work (G5) is each side's own discrete work of the
 * interface forces, so that Energies::total() is constant to round-off.
 * Contacts within reach of the ramp response (its nonzero DoFs): the pass
 * runs with the guess `Lambda_{n+m} = Lambda_n`; while their pushing set
 * (impulse > 0, and bilateral rows) stays the same over the pass, the
 * correction is superposed with the ramp response computed for that set
 * (contacts of the set bilateral; cached per set) after checking that the
 * LCP of every micro step keeps the set; otherwise the micro steps are
 * redone with the now-known multipliers and Lambda_{n+m} corrected until
 * the macro-end continuity holds (doc/theory.md 9.6; redone_macro_steps(),
 * interface_iterations(), ramp_patterns()).
 *
 * This class is the macro step itself (step(): G1-G5, micro_steps()); it
 * drives the explicit integrator through CDLagrange::CouplingView. The
 * interface solve (the rows C_E, C_I, H_I, H^-1, the link columns) is
 * InterfaceProblem; the unit-ramp responses, their cache per active set,
 * the pass record and the superposition with its limits are
 * RampSuperposition.
 */
class HATICoupling
{
public:
  /**
   * @param decomposition the two subdomains and the interface; it must
   *        outlive the coupling.
   * @param n_global_dofs number of DoFs of the whole model (outputs).
   * @param dt micro step (s), checked against the explicit dt_crit.
   * @param damping Rayleigh damping (A7), or the Maxwell branches of
   *        frequency-range damping (A8 in the explicit part, N4 in the
   *        implicit one, not combined with Rayleigh damping): the memory
   *        variables are part of both states and of the unit-ramp response
   *        (G3'); none by default.
   */
  HATICoupling(const Decomposition &decomposition,
               const unsigned int n_global_dofs,
               const double dt,
               const double safety_factor,
               const HATIParameters &parameters,
               const NewmarkParameters &newmark_parameters,
               const DampingModel &damping = DampingModel());

  /** One macro step t_n -> t_{n+m}: (G1), (G2), (G3'), (G4). */
  void step();

  /** Time at the end of the last macro step (s). */
  double time() const { return implicit.time(); }
  /** Macro step DT = m dt (s). */
  double time_step() const { return implicit.time_step(); }
  /** Micro step dt (s). */
  double micro_time_step() const { return explicit_integrator.time_step(); }
  unsigned int time_step_ratio() const { return m; }
  /** Critical step of the explicit subdomain (s). */
  double critical_time_step() const { return explicit_integrator.critical_time_step(); }

  /**
   * Displacement of the whole model (global numbering; interface: explicit
   * copy). With @p history_dofs_only and a reduced implicit part, only its
   * DoFs of set_history_dofs() are recovered from the reduced coordinates;
   * its others keep the values of the last full call.
   */
  const Vector<double> &displacement(const bool history_dofs_only = false) const;
  /** Velocity of the whole model (explicit part at the half step, as CD-Lagrange). */
  const Vector<double> &velocity(const bool history_dofs_only = false) const;
  /**
   * Velocity of the whole model at the macro-step end t_n (m/s): the
   * implicit part's `V_n` and the explicit part's integer-time velocity
   * (CDLagrange::integer_velocity(), the velocity of the continuity, G3'),
   * the explicit one on the interface DoFs (a restart's V_0, RunState).
   */
  const Vector<double> &integer_velocity() const;
  /**
   * The forces of the explicit part's last impulses (contacts, bilateral
   * rows) on the whole model's DoFs (N, CDLagrange::contact_force()),
   * without the interface force `C_E^T Lambda_{n+m}` of the last micro
   * step (zero on the implicit part): a restart's contact reaction
   * (RunState).
   */
  Vector<double> contact_force() const;
  /** The interface multiplier at the macro-step end, Lambda_n (N; RunState). */
  const Vector<double> &interface_multiplier() const { return lambda_n; }

  /**
   * The DoFs (global numbering) whose displacements and velocities the
   * history rows read: those of a reduced implicit part (C1) among them
   * are the ones displacement(true) and velocity(true) recover (a product
   * with these rows of T only, not the whole basis).
   */
  void set_history_dofs(const std::vector<types::global_dof_index> &displacement_dofs,
                        const std::vector<types::global_dof_index> &velocity_dofs);

  /**
   * Linear functionals of the whole model's displacement (rows over the
   * global DoFs, Model::output_functionals()) that output_functionals()
   * evaluates from a reduced implicit part's coordinates, `(L_I T) q + L_E
   * u_E` (C1, doc/theory.md 12.2), without recovering the DoFs they read.
   * Returns false (nothing set) without a reduced implicit part or rows.
   */
  bool set_output_functionals(const std::vector<SparseRow> &rows);
  /**
   * The values of the functionals of set_output_functionals() for the
   * current displacement; null if none are set (or the reduced coordinates
   * are not finite: the full expansion is then read).
   */
  const Vector<double> *output_functionals() const;

  /**
   * Keep the current whole displacement for later (expand_deferred()): the
   * stress envelope's rows of a reduced implicit part are expanded by
   * batches, `U = T Q` (CraigBamptonReduction::expand_many(), C1). Returns
   * false and keeps nothing without a reduced part or with reduced
   * coordinates that are not finite: the caller reads displacement() now.
   */
  bool defer_displacement();
  /** Number of displacements kept by defer_displacement() (-). */
  unsigned int n_deferred() const { return deferred.times.size(); }
  /**
   * The kept displacements in full (global numbering), in the order kept:
   * @p f(time, U) for each; then none is kept.
   */
  void expand_deferred(const std::function<void(double, const Vector<double> &)> &f);

  /** Contact gaps, normal velocities, impulses, active flags (explicit subdomain). */
  const std::vector<double> &gaps() const { return explicit_integrator.gaps(); }
  std::vector<double> normal_velocities() const
  {
    return explicit_integrator.normal_velocities();
  }
  const std::vector<double> &impulses() const { return explicit_integrator.impulses(); }
  /** The force laws of the explicit subdomain (e.g. the ropes of R1). */
  const std::vector<std::unique_ptr<ForceLaw>> &force_laws() const
  {
    return explicit_integrator.force_laws();
  }
  const std::vector<bool> &active() const { return explicit_integrator.active(); }

  /** Energies of both subdomains and the interface work (G5). */
  Energies energies() const;

  /**
   * @name The state of the macro-step map, for the stability test:
   * [U_E, dt V_E, U_I, DT V_I, DT^2 A_I, Lambda_n] (scaled so that every
   * block has the units of a displacement, the multipliers in N), then,
   * with frequency-range damping, the memory variables q_l of the explicit
   * and of the implicit part (m).
   */
  /** @{ */
  unsigned int state_size() const;
  void get_state(Vector<double> &x) const;
  void set_state(const Vector<double> &x);
  /** @} */

  /** Largest |C_E V_E + C_I V_I| at a macro-step end so far (m/s). */
  double interface_velocity_jump() const { return max_jump; }
  /** Coulomb friction of the explicit subdomain (A9): its record and counts. */
  const FrictionalContacts &friction() const { return explicit_integrator.friction(); }
  /** Macro steps whose micro steps were redone because of contacts. */
  unsigned long redone_macro_steps() const { return n_redone; }
  /** Largest number of interface corrections in one macro step. */
  unsigned int interface_iterations() const { return max_iterations; }
  /**
   * The passes of micro steps the redone macro steps ran after their first
   * one (one per correction of Lambda_{n+m}, the converged one included).
   */
  unsigned long redo_passes() const { return n_redo_passes; }
  /**
   * Corrections of Lambda_{n+m} halved by the safeguard
   * (RampSuperposition::safeguarded_corrections).
   */
  unsigned long correction_halvings() const { return n_halvings; }
  /**
   * Redone macro steps whose continuity had no root within
   * RampSuperposition::accepted_discontinuity (the smallest residual kept),
   * and the largest such residual relative to the interface velocities.
   */
  unsigned long discontinuous_macro_steps() const { return n_discontinuous; }
  double largest_discontinuous_residual() const { return largest_discontinuity; }
  /**
   * Redone macro steps whose corrections stalled and whose kept pass ran
   * with the contacts' closures frozen at the best pass's (converged, or
   * kept as the best iterate: then also a discontinuous macro step;
   * doc/theory.md 9.6 item 6),
   * and the largest gap (m) of a contact those passes took as closed while
   * open, or as open while closed (the closure's error: at most one micro
   * step's approach).
   */
  unsigned long frozen_closure_macro_steps() const { return n_frozen; }
  double largest_frozen_closure_gap() const { return largest_frozen_gap; }
  /**
   * Redone macro steps whose frozen-closure corrections stalled and went on
   * with Newton's corrections on their pass's own Jacobian
   * (frozen_jacobian(), doc/theory.md 9.6 item 8).
   */
  unsigned long jacobian_macro_steps() const { return n_jacobians; }
  /** Active sets of the contacts within reach whose ramp response was computed. */
  unsigned long ramp_patterns() const { return superposition->ramp_patterns(); }

  /**
   * Wall time of the explicit part (the first pass of every macro step,
   * the superpositions and the redone passes), the implicit steps, the
   * interface (s).
   */
  double explicit_seconds() const
  {
    return phase_seconds(0) + phase_seconds(3) + redo_seconds();
  }
  double implicit_seconds() const { return phase_seconds(1); }
  double interface_seconds() const { return phase_seconds(2); }
  /**
   * Within explicit_seconds(): the superpositions (G3': the checks and the
   * products with the ramp responses, A7/A8 dissipation included) and the
   * redone macro steps (their passes and corrections) (s).
   */
  double superposition_seconds() const { return phase_seconds(3); }
  double redo_seconds() const { return seconds[4]; }
  /** Wall time of the explicit part's contact resolution (s), within explicit_seconds().
   */
  double contact_seconds() const { return explicit_integrator.contact_seconds(); }
  /** Set-up: factorisation, ramp response, interface matrix (s). */
  double setup_seconds() const { return setup; }
  /**
   * Within explicit_seconds(): the samples of the contacts taken for
   * after_micro_step() alone (no contact within reach of the ramp), the
   * statistics' share of the micro step (s; timed on one in
   * SampledWallClock::sample_every and scaled).
   */
  double statistics_sample_seconds() const { return sample_clock.seconds(); }

  const Newmark &implicit_part() const { return implicit; }
  unsigned int n_interface_dofs() const { return interface->size(); }

  /** The contact state of the explicit subdomain after one micro step. */
  using ContactSample = hati::ContactSample;

  /**
   * Called after every micro step with the contact state of the explicit
   * subdomain (contact statistics and contacts.csv at the micro-step
   * resolution); for redone macro steps, with the final pass only.
   */
  std::function<void(const ContactSample &)> after_micro_step;

private:
  /**
   * The m micro steps (G2) from the current explicit state with
   * `Lambda_j = (1 - j/m) Lambda_n + (j/m) lambda_end`: the pass with the
   * guess `lambda_end = Lambda_n` (@p pass: record what the superposition
   * needs), or a redo with the full multiplier.
   */
  void micro_steps(const Vector<double> &lambda_end, const bool pass);
  /**
   * The active set changed within the macro step: redo the micro steps
   * with the full multiplier Lambda_{n+m} and correct it with @p H_inverse
   * until the macro-end continuity holds (doc/theory.md 9.6).
   */
  void redo_micro_steps(const DenseColumns &H_inverse);
  /**
   * The correction of a redone macro step after
   * RampSuperposition::plain_corrections plain ones: Broyden's inverse
   * update of @p B (set to @p H_inverse on first use) with the secant
   * `B (r_{k-1} - r_k) = dLambda_{k-1}` (@p step on entry), then @p step =
   * `B r_k` (doc/theory.md 9.6). Converges where the plain correction with
   * the ramp's H^-1 contracts slowly (sticking friction within reach, an
   * implicit part stiffer at the interface than the ramp assumes).
   */
  void broyden_step(const DenseColumns &H_inverse,
                    FullMatrix<double> &B,
                    Vector<double> &step,
                    const Vector<double> &last_residual,
                    const Vector<double> &residual) const;
  /**
   * After a redone macro step kept a pass with frozen closures: count it,
   * measure its closures' gaps, unfreeze.
   */
  void frozen_closures();
  /** The one-line error of a redone macro step that did not converge. */
  std::string not_converged_message(const double norm, const double scale) const;
  /**
   * The Jacobian `dr / dLambda_{n+m}` of the macro-end continuity residual
   * @p r0 at @p lambda of the pass with the closures frozen, by one pass per
   * interface row (with the closures frozen the pass is affine in Lambda
   * except where an impulse's sign or a friction state switches),
   * pseudo-inverted into @p J_inverse (its singular values
   * below 1e-12 of the largest dropped). redo_micro_steps() then corrects
   * with Newton's `Lambda -= J^+ r` (doc/theory.md 9.6 item 8).
   */
  void frozen_jacobian(const Vector<double> &lambda,
                       const Vector<double> &r0,
                       LAPACKFullMatrix<double> &J_inverse);
  /** Fill @p sample from the explicit integrator. */
  void take_sample(ContactSample &sample) const;
  /**
   * The whole model's values in @p global from the implicit integrator's
   * @p state and the explicit part's @p explicit_part: with a reduced part
   * (C1) its DoFs expanded into @p buffer, all of them or, with @p partial
   * (once a full call filled @p buffer and @p global, and the coordinates
   * are finite), those of set_history_dofs(), which with the explicit part
   * are then the only entries of @p global updated.
   */
  struct PartialExpansion;
  const Vector<double> &whole_state(const Vector<double> &state,
                                    const Vector<double> &explicit_part,
                                    Vector<double> &buffer,
                                    Vector<double> &global,
                                    const PartialExpansion *partial) const;
  /** @p global = the implicit and explicit parts in the global numbering. */
  const Vector<double> &to_global(const Vector<double> &implicit_part,
                                  const Vector<double> &explicit_part,
                                  Vector<double> &global) const;

  const Decomposition &decomposition;
  const unsigned int m;
  /** HATIParameters::superposition. */
  const bool superpose_steps;
  CDLagrange explicit_integrator;
  /** The coupling's access to the explicit integrator's steps (G2). */
  CDLagrange::CouplingView explicit_view;
  Newmark implicit;
  /** (G3'-G4) the interface rows, H_I, the link. */
  std::unique_ptr<InterfaceProblem> interface;
  /** (G3') the unit-ramp responses and their superposition. */
  std::unique_ptr<RampSuperposition> superposition;

  /** Lambda_n, Lambda_{n+m} and their difference (N). */
  Vector<double> lambda_n, lambda_m, delta_lambda;
  /** The interface increments and end velocity of the current pass. */
  InterfaceIncrements increments;

  // per macro step with contacts in reach: the contact state of every
  // micro step (replayed to after_micro_step), a pool whose first
  // n_recorded entries are in use, reused without allocation
  bool record_contacts = false;
  std::vector<ContactSample> contact_record;
  unsigned int n_recorded = 0;
  ContactSample sample;

  double interface_work = 0.;
  double max_jump = 0.;
  unsigned long n_redone = 0;
  unsigned int max_iterations = 0;
  unsigned long n_redo_passes = 0;
  unsigned long n_halvings = 0;
  unsigned long n_discontinuous = 0;
  double largest_discontinuity = 0.;
  unsigned long n_frozen = 0;
  /** Redone macro steps corrected with their frozen pass's Jacobian. */
  unsigned long n_jacobians = 0;
  double largest_frozen_gap = 0.;
  /**
   * The active set of every micro step taken from the best pass while
   * redo_micro_steps() corrects with the closures frozen (empty: from the
   * gaps, A4).
   */
  std::vector<std::vector<bool>> frozen_activation;
  /**
   * Explicit first passes, implicit, interface, superposition (s, summed
   * over the macro steps timed: one in SampledWallClock::sample_every, so
   * that a macro step of m = 1 reads the clock once in 16), redo (s, every
   * redone macro step).
   */
  double seconds[5] = {0., 0., 0., 0., 0.};
  unsigned long n_macro_steps_seen = 0, n_macro_steps_timed = 0;
  /** seconds[k] scaled from the timed macro steps to all of them. */
  double phase_seconds(const unsigned int k) const
  {
    return n_macro_steps_timed == 0
               ? 0.
               : seconds[k] * double(n_macro_steps_seen) / double(n_macro_steps_timed);
  }
  SampledWallClock sample_clock;
  double setup = 0.;
  mutable Vector<double> global_U, global_V, expanded_U, expanded_V;
  /** Implicit DoFs of set_history_dofs() and their rows of T. */
  struct PartialExpansion
  {
    std::vector<unsigned int> rows;
    FullMatrix<double> basis;
    mutable Vector<double> values;
  };
  PartialExpansion history_displacement, history_velocity;
  /** The functionals of set_output_functionals(): `L_I T` and `L_E`. */
  struct ReducedFunctionals
  {
    FullMatrix<double> implicit_basis;
    std::vector<SparseRow> explicit_rows;
    mutable Vector<double> values;
  };
  ReducedFunctionals functionals;
  /** The states of defer_displacement(): times, reduced coordinates, explicit part. */
  struct DeferredStates
  {
    std::vector<double> times;
    std::vector<double> coordinates;
    std::vector<Vector<double>> explicit_displacements;
  };
  DeferredStates deferred;
  CDLagrange::Snapshot snapshot;
};
} // namespace hati

#endif

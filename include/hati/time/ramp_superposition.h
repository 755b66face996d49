#ifndef hati_time_ramp_superposition_h
#define hati_time_ramp_superposition_h

#include <deal.II/lac/vector.h>

#include <hati/contact/friction_solver.h>
#include <hati/model/discrete_system.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/column_matrices.h>
#include <hati/time/interface_problem.h>
#include <hati/time/rayleigh_damping.h>

#include <algorithm>
#include <map>
#include <memory>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The contact state of the explicit subdomain after one micro step: the
 * force laws' sample (ForceLaw::sample()).
 */
using ContactSample = LawSample;

/**
 * What the micro steps of a macro step give the interface problem, one
 * entry per interface pair (G3', G5).
 */
struct InterfaceIncrements
{
  /** `C_E V` at the integer time t_{n+m} (m/s). */
  Vector<double> v_end;
  /** `sum_j dt C_E V_{j-1/2}` (m), the interface displacement increment. */
  Vector<double> increment_sum;
  /** `sum_j (2j - 1)/(2m) dt C_E V_{j-1/2}` (m), for the work of the ramp (G5). */
  Vector<double> increment_weighted;
};

/**
 * The explicit response to unit interface ramps and its superposition
 * (doc/theory.md 9.2 and 9.6, G3'). The micro steps of a macro step run
 * with the guess `Lambda_{n+m} = Lambda_n` (the pass); the correction
 * `dLambda` is then added to the explicit state by superposition of the
 * response to the unit ramps `(j/m) e_l` from rest, computed once with the
 * explicit integrator's own code path (a private CDLagrange, without
 * loads).
 *
 * Contacts within reach of that response (its nonzero DoFs): the pass
 * records their impulses, gaps and normal velocities; while their pushing
 * set (impulse > 0, and bilateral rows) stays the same over the pass, the
 * response computed with that set bilateral is used (cached per set, up to
 * max_cached_patterns) after superpose() has checked that the LCP of every
 * micro step keeps the set; otherwise HATICoupling redoes the micro steps
 * (max_corrections, continuity_tolerance). Ropes (R1) are nonlinear like
 * the contacts and, like their impulses, their forces are part of the pass
 * and never of the ramp: a macro step whose response reaches a rope's DoFs
 * is always redone. With damping (A7) the
 * dissipated energy is quadratic in the state: the pass records the
 * velocities, `S V` and damping forces on the reach, and
 * ramp_dissipation() adds the ramp's part. With frequency-range damping
 * (A8) the ramp response carries its own memory variables q_l, superposed
 * with the state (they are linear in it), and its branch forces per micro
 * step for the dissipated energy.
 *
 * The limits are the named constants below.
 */
class RampSuperposition
{
public:
  /**
   * @name Limits
   */
  /** @{ */
  /**
   * At most this many pattern responses are cached; the cache is emptied
   * when full (each holds at most about m (contacts + reach) n_G entries,
   * stored sparse; the braked crane with its rope computes 367 over the
   * whole Rinaldi record, its process peaking at 250 MB).
   */
  static constexpr unsigned int max_cached_patterns = 512;
  /**
   * A contact pushes in a micro step of the pass if its impulse is above
   * this fraction of the largest impulse of the pass (round-off, A5).
   */
  static constexpr double pushing_impulse_fraction = 1e-10;
  /**
   * superpose(): relative tolerance of the LCP checks, on the impulses
   * (fraction of the largest one) and on the normal velocities (fraction
   * of the largest one, plus velocity_tolerance_floor m/s).
   */
  static constexpr double lcp_check_tolerance = 1e-9;
  /** Absolute part of the velocity check of superpose() (m/s). */
  static constexpr double velocity_tolerance_floor = 1e-15;
  /**
   * Redone macro steps: the macro-end continuity holds when the residual is
   * at most this fraction of the largest interface velocity (or zero).
   */
  static constexpr double continuity_tolerance = 1e-8;
  /** Redone macro steps: corrections of Lambda_{n+m} before giving up. */
  static constexpr unsigned int max_corrections = 60;
  /**
   * Redone macro steps that reach max_corrections: the iterate with the
   * smallest residual is kept if that residual is at most this fraction of
   * the largest interface velocity (counted and warned of); beyond it the
   * run stops. Where a contact closes within the macro step, the macro-end
   * velocity jumps when Lambda_{n+m} moves the closure by one micro step,
   * so the continuity may have no root (doc/theory.md 9.6).
   */
  static constexpr double accepted_discontinuity = 1e-2;
  /**
   * Redone macro steps: from this correction on, a correction that grew
   * the residual is halved (at most max_halvings times in a row) and the
   * secant update starts again from H^-1 (HATICoupling::redo_micro_steps();
   * doc/theory.md 9.6): a contact that switches between passes made the
   * secant corrections cycle. Macro steps that converge before it are
   * computed as without it. At this correction a macro step that has not
   * converged also goes on from its best iterate with the contacts'
   * activations frozen at that iterate's (doc/theory.md 9.6 item 6).
   */
  static constexpr unsigned int safeguarded_corrections = 25;
  /**
   * Redone macro steps: corrections with the closures frozen (from
   * safeguarded_corrections on) before the frozen pass's own Jacobian is
   * formed and Newton's corrections take over (HATICoupling::frozen_jacobian(),
   * doc/theory.md 9.6 item 8): H^-1 of the ramp (no contact changing) can be
   * far from it where a contact at the interface holds a velocity (a crane
   * wheel on its rail next to heavy girders: the corrections cycled, the
   * run stopped).
   */
  static constexpr unsigned int frozen_corrections_before_jacobian = 5;
  /** Redone macro steps: halvings of one correction (see above). */
  static constexpr unsigned int max_halvings = 8;
  /**
   * Redone macro steps: corrections with the ramp's H^-1 before the
   * secant (Broyden) ones (HATICoupling::broyden_step()); a macro step
   * that converges within them is computed as before the secant update.
   */
  static constexpr unsigned int plain_corrections = 3;
  /**
   * A response that moves a DoF of a nonlinear force law (a rope's, R1) is
   * superposed only while the change of the law's force it can cause is at
   * most this fraction of the law's force scale
   * (ForceLaw::relative_force_change()): the pass's forces of the law then
   * hold for the corrected micro steps to this fraction, the tolerance to
   * which a redone macro step meets the velocity continuity
   * (continuity_tolerance; doc/theory.md 10.5). The work of the pass's
   * forces on the corrected velocities is booked (add_nonlinear_work()).
   */
  static constexpr double nonlinear_force_tolerance = 1e-8;
  /** @} */

  /**
   * The explicit response to the unit ramps, its reach and contacts
   * within reach, for the explicit subdomain @p system, micro step @p dt
   * (s), @p m micro steps per macro step and the interface @p interface
   * (H^-1 for each response). The arguments must outlive this object.
   */
  RampSuperposition(const DiscreteSystem &system,
                    const double dt,
                    const unsigned int m,
                    const RayleighDamping &damping,
                    const MaxwellBranches &branches,
                    const InterfaceProblem &interface);

  /**
   * The explicit response to the unit ramps `(j/m) e_l` from rest, for one
   * active set of the contacts within reach (none: the open response),
   * with what the superposition needs: the state columns, the interface
   * increments, the load work, the velocities on the reach and the
   * quadratic form of its dissipation (damped), the impulse and gap of each
   * contact within reach after every micro step and its normal velocity
   * `L V_{j-1/2}` before it, and the inverse of the interface matrix
   * `H = C_E V_ramp + gamma DT C_I M_eff^-1 C_I^T` (G3').
   */
  struct Response
  {
    std::vector<SparseColumns> state;
    SparseColumns increment_sum, increment_weighted, H_E;
    std::vector<std::vector<Vector<double>>> load_work;
    // per micro step, sparse: the response spreads at the wave speed and
    // stays within the connected part of the subdomain
    /**
     * The velocities V_{j-1/2} on the reach, j = 1 .. m + 1, and the
     * quadratic form of the ramp's own dissipation,
     * `Q = sum_j V_j^T M (D_{j-1} + D_j)` (ramp_dissipation()).
     */
    std::vector<SparseColumns> velocity_on_reach;
    DenseColumns dissipation_quadratic;
    /**
     * With frequency-range damping (A8): the memory variables q_l after the
     * m micro steps, one set of columns per branch (superposed with the
     * state), and the ramp's branch forces `d_j = dt M^-1 K S_j` on the
     * reach, j = 1 .. m (the cross terms of ramp_dissipation()).
     */
    std::vector<SparseColumns> memory, damping_on_reach;
    // (rows j * n_contacts + c: contact c of the reach after micro step j,
    // its normal velocity before it)
    SparseColumns impulse, gap, normal_velocity;
    /**
     * With friction within reach (A9): the tangential impulses after micro
     * step j and the tangential velocities `T V_{j-1/2}` before it, rows
     * `2 (j n_contacts + c) + t` (tangent t of contact c of the reach). The
     * frictional contacts of the pushing set stick in the response (their
     * tangent rows are equalities, FrictionalContacts::solve()).
     */
    SparseColumns tangential_impulse, tangential_velocity;
    /** H^-1 (inverted once, one product per solve). */
    DenseColumns H_inverse;
    /**
     * Whether the response moves a DoF of a nonlinear force law
     * (ForceLaw::nonlinear_dofs(), e.g. a rope's, R1): the law's forces of
     * the pass change with the correction, so superpose() checks that they
     * change by at most nonlinear_force_tolerance, from the response's
     * displacements on those DoFs after every micro step (rows
     * `(j - 1) n_nonlinear + i`), or the micro steps are redone.
     */
    bool moves_nonlinear_law = false;
    /**
     * With moves_nonlinear_law: the velocities `V_{j-1/2}` on those DoFs
     * before micro step j (rows as nonlinear_displacement), for the work of
     * the pass's forces on the corrected velocities.
     */
    SparseColumns nonlinear_displacement, nonlinear_velocity;
  };

  /** Whether contacts are within reach of the ramp response. */
  bool contacts_in_reach() const { return !reach_contacts.empty(); }
  /**
   * Whether the pass must keep its start to redo the micro steps: contacts
   * or nonlinear force laws (e.g. ropes, R1) within reach of the ramp response.
   */
  bool nonlinear_in_reach() const
  {
    return contacts_in_reach() || open_ramp.moves_nonlinear_law;
  }
  /**
   * Whether a contact with friction (A9) lies within reach: its response is
   * linear in the multiplier only while it sticks (or stays open), which
   * response_for_pass() and superpose() check.
   */
  bool friction_in_reach() const { return reach_friction; }
  /** Whether the pass records the damping on the reach (damped). */
  bool records_damping() const { return !reach_dofs.empty(); }
  /** Active sets of the contacts within reach whose response was computed. */
  unsigned long ramp_patterns() const { return n_patterns; }

  /**
   * @name The pass (G2), recorded by HATICoupling::micro_steps()
   */
  /** @{ */
  /**
   * Before micro step 1: the contact state of the contacts within reach of
   * @p integrator if @p contacts (then record_damping_force() with j = 0 if
   * damped).
   */
  void start_pass(const CDLagrange &integrator, const bool contacts);
  /** Before micro step @p j: V_{j-1/2} on the reach. */
  void record_velocity(const unsigned int j, const Vector<double> &velocity);
  /** Where micro step @p j writes `S V_{j-1/2}` (n_dofs() or reach entries). */
  double *stiffness_velocity_buffer(const unsigned int j);
  /** After the free velocity of micro step @p j: `S V_{j-1/2}` on the reach. */
  void record_stiffness_velocity(const unsigned int j);
  /** After micro step @p j: the load weights of its step. */
  void record_load_weights(const unsigned int j, const CDLagrange::CouplingView &view);
  /**
   * After micro step @p j (before the first, from start_pass(): j = 0): the
   * forces the nonlinear laws applied (ForceLaw::applied_force()).
   */
  void record_law_forces(const unsigned int j, const CDLagrange &integrator);
  /** After micro step @p j (before the first: j = 0): d_j on the reach. */
  void record_damping_force(const unsigned int j, const Vector<double> &d);
  /**
   * After micro step @p j: the contacts within reach from @p sample, and
   * with friction (A9) their tangential velocities at @p V (`V_{j+1/2}`).
   */
  void record_contacts(const unsigned int j,
                       const ContactSample &sample,
                       const Vector<double> &V);
  /** @} */

  /**
   * The response for the pass: with contacts within reach, the response of
   * their pushing set if it stayed the same over the pass (computed on
   * first use and cached), else the open response and @p same_active_set
   * false (the micro steps are to be redone). A response that moves a rope
   * (R1) is not superposed either: @p same_active_set false. Nor is one
   * whose frictional contacts (A9) of the pushing set did not stick at
   * every micro step of the pass: then the response of the set is returned
   * (its H^-1 corrects the redone micro steps) with @p same_active_set false.
   */
  const Response &response_for_pass(bool &same_active_set);

  /**
   * Check that the pass plus the ramp response `r lambda` keeps the active
   * set of the pass (impulses of active contacts >= 0, gaps of inactive
   * ones > 0 at every micro step) and, with friction (A9), that the
   * sticking contacts' tangential impulses stay within their Coulomb cones
   * `|lambda_t| <= mu lambda_n` (to lcp_check_tolerance of the largest
   * impulse); if so add it to the state of
   * @p integrator, its works, @p increments and the @p n_samples recorded
   * contact @p samples of the pass and return true.
   */
  bool superpose(const Response &r,
                 const Vector<double> &lambda,
                 CDLagrange &integrator,
                 InterfaceIncrements &increments,
                 std::vector<ContactSample> &samples,
                 const unsigned int n_samples);

private:
  /**
   * Compute @p r for the active set @p pattern of the contacts within reach
   * (empty: all open), the contacts of the pattern taken as bilateral
   * (CDLagrange::CouplingView::prescribe_active_set()).
   */
  void
  compute_ramp(const std::vector<bool> &pattern, Response &r, const bool with_damping);
  /** The velocities on the reach and the quadratic form Q of @p r (damped). */
  void store_dissipation(const std::vector<FullMatrix<double>> &velocity_reach,
                         const std::vector<FullMatrix<double>> &damping_reach,
                         Response &r) const;
  /**
   * The tangential velocities `T V` of the frictional contacts within reach
   * at @p V into column @p l of @p rows (row 2 c + t, compute_ramp()).
   */
  void record_tangential(const Vector<double> &V,
                         FullMatrix<double> &rows,
                         const unsigned int l) const;
  /** The ramp response of @p pattern, computed on first use and cached. */
  const Response &ramp_for(const std::vector<bool> &pattern);
  /** The reach, the contacts within it and the damping records (set-up). */
  void find_reach();
  /**
   * Friction within reach (A9) in superpose(): false if a sticking contact's
   * total tangential impulse leaves its Coulomb cone at a micro step;
   * otherwise its impulses, the friction work and the samples corrected.
   */
  bool superpose_friction(const Response &r,
                          const Vector<double> &lambda,
                          CDLagrange &integrator,
                          std::vector<ContactSample> &samples,
                          const unsigned int n_samples,
                          const double impulse_tolerance);
  /**
   * Nonlinear force laws in superpose() (@p r moves their DoFs): whether the
   * correction `r lambda` changes each law's force by at most
   * nonlinear_force_tolerance of its scale (ForceLaw::relative_force_change()
   * of the largest displacement it adds to those DoFs at a micro step).
   */
  bool nonlinear_laws_hold(const Response &r,
                           const Vector<double> &lambda,
                           const CDLagrange &integrator);
  /**
   * The work the correction `r lambda` adds to each nonlinear law: its
   * pass's forces on the velocities the correction adds to its DoFs, the
   * trapezoid of ForceLaw::step() (ForceLaw::add_superposed_work()).
   */
  void add_nonlinear_work(const Response &r,
                          const Vector<double> &lambda,
                          CDLagrange &integrator);
  /** The contacts of superpose(): false if the active set does not hold. */
  bool superpose_contacts(const Response &r,
                          const Vector<double> &lambda,
                          CDLagrange &integrator,
                          std::vector<ContactSample> &samples,
                          const unsigned int n_samples);
  /** The dissipated energy of the ramp part @p r Lambda after the pass (G3', A7). */
  double ramp_dissipation(const Response &r, const Vector<double> &lambda) const;
  /** @p reach = @p source on reach_dofs. */
  void gather_reach(const Vector<double> &source, Vector<double> &reach) const;

  const DiscreteSystem &system;
  const double dt;
  const unsigned int m;
  const InterfaceProblem &interface;
  const bool damped;
  /** Frequency-range damping (A8): the memory variables are part of the state. */
  const bool with_memory;
  /** The explicit integrator of the ramp responses (from rest, no loads). */
  std::unique_ptr<CDLagrange> ramp_integrator;
  Response open_ramp;
  std::map<std::vector<bool>, Response> pattern_ramps;
  unsigned long n_patterns = 0;

  /** The DoFs of the nonlinear force laws (ForceLaw::nonlinear_dofs()). */
  std::vector<types::global_dof_index> nonlinear_dofs;
  /** The indices of those laws among the integrator's force_laws(). */
  std::vector<unsigned int> nonlinear_laws;
  /** Where each of those laws' DoFs start in nonlinear_dofs (one more entry). */
  std::vector<unsigned int> nonlinear_first;
  /** The forces those laws applied in the pass, row `j n_nonlinear + i` (N). */
  std::vector<double> pass_law_force;
  /** Work vector of nonlinear_laws_hold(). */
  Vector<double> ramp_nonlinear;
  // contacts within reach of the ramp response (indices)
  std::vector<unsigned int> reach_contacts;
  bool reach_friction = false;
  /** Whether each contact within reach has friction (A9). */
  std::vector<bool> reach_frictional;
  // with friction: the pass's tangential impulses after micro step j and
  // tangential velocities T V_{j-1/2} before it (row 2 (j nrc + c) + t),
  // whether each contact stuck in micro step j (row (j - 1) nrc + c), the
  // ramp's part and the totals of superpose_friction()
  std::vector<double> pass_tangential, pass_tangential_velocity;
  std::vector<bool> pass_stick;
  Vector<double> ramp_tangential, ramp_tangential_velocity;
  std::vector<double> total_tangential, total_tangential_velocity;
  // the pass over the contacts within reach: impulses, gaps, normal
  // velocities and active flags per micro step (row-major, j x contact)
  std::vector<double> pass_impulse, pass_gap, pass_normal;
  std::vector<double> total_impulse, total_gap, total_normal;
  std::vector<bool> pass_active, pattern;
  // the ramp's part of the contact quantities of all micro steps (superpose())
  Vector<double> ramp_impulse, ramp_gap, ramp_normal;
  // the pass's trapezoidal load weights, load s at micro step j: s m + j - 1
  std::vector<double> pass_load_weight;

  // With damping (A7) the dissipated energy is bilinear in the explicit
  // state: its part from the ramp response needs, on the DoFs the ramp
  // reaches, the ramp's velocities V_{j-1/2} per micro step (|R| x n_G) and
  // the velocities, S V and damping forces of the first pass
  // (ramp_dissipation()).
  std::vector<unsigned int> reach_dofs;
  /** reach_dofs is every explicit DoF in order (contacts within reach). */
  bool reach_is_all = false;
  /** Lumped mass on the reach (kg). */
  Vector<double> reach_mass;
  std::vector<Vector<double>> pass_velocity_reach, pass_damping_reach;
  /** S V_{j-1/2} of the pass on the reach (S = dt M^-1 K, A7), per micro step. */
  std::vector<Vector<double>> pass_stiffness_reach;
  /** S V of a micro step on every explicit DoF (reach not all DoFs). */
  Vector<double> stiffness_velocity_full;
  /** Each interface row C_E,l as (reach index, coefficient) pairs. */
  std::vector<std::vector<std::pair<unsigned int, double>>> interface_reach_rows;
  /** Work vectors of ramp_dissipation(). */
  mutable Vector<double> dissipation_p, dissipation_p_prev, dissipation_c, dissipation_g,
      dissipation_q;
};

// the pass record runs every micro step: inline
inline void RampSuperposition::record_velocity(const unsigned int j,
                                               const Vector<double> &velocity)
{
  gather_reach(velocity, pass_velocity_reach[j]);
}

inline double *RampSuperposition::stiffness_velocity_buffer(const unsigned int j)
{
  return reach_is_all ? pass_stiffness_reach[j].data() : stiffness_velocity_full.data();
}

inline void RampSuperposition::record_stiffness_velocity(const unsigned int j)
{
  if (!reach_is_all)
    for (unsigned int r = 0; r < reach_dofs.size(); ++r)
      pass_stiffness_reach[j][r] = stiffness_velocity_full[reach_dofs[r]];
}

inline void RampSuperposition::record_load_weights(const unsigned int j,
                                                   const CDLagrange::CouplingView &view)
{
  const unsigned int n_loads = system.time_dependent_loads.size();
  for (unsigned int s = 0; s < n_loads; ++s)
    pass_load_weight[s * m + j - 1] = view.load_step_weight(s);
}

inline void RampSuperposition::record_damping_force(const unsigned int j,
                                                    const Vector<double> &d)
{
  gather_reach(d, pass_damping_reach[j]);
}

inline void RampSuperposition::record_contacts(const unsigned int j,
                                               const ContactSample &sample,
                                               const Vector<double> &V)
{
  const unsigned int nrc = reach_contacts.size();
  for (unsigned int c = 0; c < nrc; ++c)
  {
    const unsigned int k = reach_contacts[c];
    pass_impulse[j * nrc + c] = sample.impulses[k];
    pass_gap[j * nrc + c] = sample.gaps[k];
    pass_normal[(j + 1) * nrc + c] = sample.normal_velocities[k];
    if (reach_frictional[c])
    {
      const auto &tangents = system.contacts[k].tangents;
      for (unsigned int t = 0; t < tangents.size(); ++t)
      {
        pass_tangential[2 * (j * nrc + c) + t] = sample.tangential_impulses[2 * k + t];
        pass_tangential_velocity[2 * ((j + 1) * nrc + c) + t] = tangents[t].apply(V);
      }
      pass_stick[(j - 1) * nrc + c] = sample.friction_states[k] == FrictionState::stick;
    }
  }
}

inline void RampSuperposition::gather_reach(const Vector<double> &source,
                                            Vector<double> &reach) const
{
  if (reach_is_all)
    std::copy(source.begin(), source.begin() + reach.size(), reach.begin());
  else
    for (unsigned int r = 0; r < reach_dofs.size(); ++r)
      reach[r] = source[reach_dofs[r]];
}
} // namespace hati

#endif

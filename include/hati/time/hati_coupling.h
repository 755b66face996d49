#ifndef hati_time_hati_coupling_h
#define hati_time_hati_coupling_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <hati/contact/sparse_rows.h>
#include <hati/model/decomposition.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/energies.h>
#include <hati/time/newmark.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/** The `Time integration/HATI` subsection. */
struct HATIParameters
{
  /** Declare "Time step ratio" and "Coupling method" (the caller enters the subsection).
   */
  static void declare_parameters(ParameterHandler &prm);
  /** Read them; throws a one-line error for a ratio of 0. */
  void parse_parameters(ParameterHandler &prm);

  /** m = DT / dt (-), integer >= 1. */
  unsigned int time_step_ratio = 1;
  /**
   * "macro-linear": (G3'), continuity at the macro-step ends with the
   * multiplier linear in time over the macro step (the stable variant).
   */
  std::string coupling_method = "macro-linear";
};

/**
 * Columns of a sparse matrix (the explicit response to a unit interface
 * ramp, G3'): only the entries the response reaches are stored.
 */
class SparseColumns
{
public:
  /** Append the column @p v (its nonzero entries). */
  void add_column(const Vector<double> &v);
  /** The nonzero entries of @p matrix, column by column. */
  explicit SparseColumns(const FullMatrix<double> &matrix);
  SparseColumns() = default;
  /** y += sum_k column_k x_k. */
  void add_multiply(Vector<double> &y, const Vector<double> &x) const;
  /** y = sum_k column_k x_k (@p y keeps its size). */
  void vmult(Vector<double> &y, const Vector<double> &x) const
  {
    y = 0.;
    add_multiply(y, x);
  }
  /** g_k += column_k . c for every column k (@p c: as many entries as rows). */
  void Tvmult_add(Vector<double> &g, const double *c) const;
  /** Rows with an entry in any column. */
  std::vector<unsigned int> rows() const;

private:
  std::vector<std::size_t> start{0};
  std::vector<unsigned int> row;
  std::vector<double> value;
};

/**
 * A small dense matrix stored column by column, the product taking four
 * columns per pass over the result (the coupling's dense operators: the
 * link columns M_eff^-1 C_I^T, H_I and H^-1 of G3'-G4, applied once or
 * twice per macro step).
 */
class DenseColumns
{
public:
  /** An @p m x @p n matrix of zeros. */
  void reinit(const unsigned int m, const unsigned int n)
  {
    n_rows = m;
    n_columns = n;
    value.assign(std::size_t(m) * n, 0.);
  }
  bool empty() const { return value.empty(); }
  double &operator()(const unsigned int i, const unsigned int j)
  {
    return value[std::size_t(j) * n_rows + i];
  }
  double operator()(const unsigned int i, const unsigned int j) const
  {
    return value[std::size_t(j) * n_rows + i];
  }
  /** y = A x (@p y keeps its size, m entries). */
  void vmult(Vector<double> &y, const Vector<double> &x) const;

private:
  unsigned int n_rows = 0, n_columns = 0;
  std::vector<double> value;
};

/**
 * The heterogeneous asynchronous time integrator (paper (4)-(10),
 * Gravouil-Combescure; doc/theory.md section 9): the explicit subdomain
 * integrated by CD-Lagrange with the micro step dt, the implicit one by
 * Newmark with the macro step DT = m dt, glued at the interface DoFs by
 * Lagrange multipliers Lambda (interface forces, acting as `C_E^T Lambda`
 * on the explicit side and `C_I^T Lambda` on the implicit side, with
 * `C_E = +1`, `C_I = -1` on the interface DoF pairs).
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
 */
class HATICoupling
{
public:
  /**
   * @param decomposition the two subdomains and the interface; it must
   *        outlive the coupling.
   * @param n_global_dofs number of DoFs of the whole model (outputs).
   * @param dt micro step (s), checked against the explicit dt_crit.
   */
  HATICoupling(const Decomposition &decomposition,
               const unsigned int n_global_dofs,
               const double dt,
               const double safety_factor,
               const HATIParameters &parameters,
               const NewmarkParameters &newmark_parameters,
               const RayleighDamping &damping);

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

  /** Displacement of the whole model (global numbering; interface: explicit copy). */
  const Vector<double> &displacement() const;
  /** Velocity of the whole model (explicit part at the half step, as CD-Lagrange). */
  const Vector<double> &velocity() const;

  /** Contact gaps, normal velocities, impulses, active flags (explicit subdomain). */
  const std::vector<double> &gaps() const { return explicit_integrator.gaps(); }
  std::vector<double> normal_velocities() const
  {
    return explicit_integrator.normal_velocities();
  }
  const std::vector<double> &impulses() const { return explicit_integrator.impulses(); }
  const std::vector<bool> &active() const { return explicit_integrator.active(); }

  /** Energies of both subdomains and the interface work (G5). */
  Energies energies() const;

  /**
   * @name The state of the macro-step map, for the stability test:
   * [U_E, dt V_E, U_I, DT V_I, DT^2 A_I, Lambda_n] (scaled so that every
   * block has the units of a displacement, the multipliers in N).
   */
  /** @{ */
  unsigned int state_size() const;
  void get_state(Vector<double> &x) const;
  void set_state(const Vector<double> &x);
  /** @} */

  /** Largest |C_E V_E + C_I V_I| at a macro-step end so far (m/s). */
  double interface_velocity_jump() const { return max_jump; }
  /** Macro steps whose micro steps were redone because of contacts. */
  unsigned long redone_macro_steps() const { return n_redone; }
  /** Largest number of interface corrections in one macro step. */
  unsigned int interface_iterations() const { return max_iterations; }
  /** Active sets of the contacts within reach whose ramp response was computed. */
  unsigned long ramp_patterns() const { return n_patterns; }

  /** Wall time of the explicit micro steps, the implicit steps, the interface (s). */
  double explicit_seconds() const { return seconds[0]; }
  double implicit_seconds() const { return seconds[1]; }
  double interface_seconds() const { return seconds[2]; }
  /** Set-up: factorisation, ramp response, interface matrix (s). */
  double setup_seconds() const { return setup; }

  const Newmark &implicit_part() const { return implicit; }
  unsigned int n_interface_dofs() const { return rows_E.size(); }

  /** The contact state of the explicit subdomain after one micro step. */
  struct ContactSample
  {
    double time = 0.;
    std::vector<double> gaps, normal_velocities, impulses;
    std::vector<bool> active;
  };

  /**
   * Called after every micro step with the contact state of the explicit
   * subdomain (contact statistics and contacts.csv at the micro-step
   * resolution); for redone macro steps, with the final pass only.
   */
  std::function<void(const ContactSample &)> after_micro_step;

private:
  /**
   * The m micro steps from the current explicit state with
   * `Lambda_j = (1 - j/m) Lambda_n + (j/m) lambda_end`: the pass with the
   * guess `lambda_end = Lambda_n` (@p pass: record what the superposition
   * needs), or a redo with the full multiplier.
   */
  void micro_steps(const Vector<double> &lambda_end, const bool pass);
  /** Lambda_{n+m} - Lambda_n of the current macro step (N). */
  Vector<double> delta_lambda;
  /** The explicit response to unit ramps, the interface matrix (set-up). */
  void precompute_ramp_response();
  /** Lambda_0 from the acceleration continuity at t = 0. */
  void initial_multiplier();

  const Decomposition &decomposition;
  const unsigned int m;
  const RayleighDamping damping;
  CDLagrange explicit_integrator;
  Newmark implicit;
  const double gamma;
  std::vector<SparseRow> rows_E, rows_I;
  /** The explicit DoF of each interface pair (rows_E: +1 on it), for the micro steps. */
  std::vector<unsigned int> dofs_E;

  Vector<double> lambda_n, lambda_m;

  /**
   * The explicit response to the unit ramps `(j/m) e_l` from rest, for one
   * active set of the contacts within reach (none: the open response),
   * with what the superposition needs: the state columns, the interface
   * increments, the load work, the velocities on the reach and the
   * quadratic form of its dissipation (damped), the impulse and gap of each contact
   * within reach after every micro step and its normal velocity `L V_{j-1/2}` before it,
   * and the inverse of the interface matrix `H = C_E V_ramp + gamma DT C_I M_eff^-1
   * C_I^T` (G3').
   */
  struct RampResponse
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
    // (rows j * n_contacts + c: contact c of the reach after micro step j,
    // its normal velocity before it)
    SparseColumns impulse, gap, normal_velocity;
    /** H^-1 (inverted once, one product per solve). */
    DenseColumns H_inverse;
  };
  /**
   * Compute @p r for the active set @p pattern of the contacts within reach
   * (empty: all open), the contacts of the pattern taken as bilateral
   * (CDLagrange::prescribe_active_set()).
   */
  void compute_ramp(const std::vector<bool> &pattern,
                    RampResponse &r,
                    const bool with_damping);
  /** The ramp response of @p pattern, computed on first use and cached. */
  const RampResponse &ramp_for(const std::vector<bool> &pattern);
  /**
   * Check that the pass plus the ramp response `r Lambda` keeps the active
   * set of the pass (impulses of active contacts >= 0, gaps of inactive
   * ones > 0 at every micro step); if so add it to the explicit state, its
   * works and the recorded contact samples and return true.
   */
  bool superpose(const RampResponse &r, const Vector<double> &lambda);

  // (G3') the implicit part of the interface matrix, the ramp responses
  DenseColumns H_I;
  RampResponse open_ramp;
  std::map<std::vector<bool>, RampResponse> pattern_ramps;
  std::unique_ptr<CDLagrange> ramp_integrator;
  unsigned long n_patterns = 0;
  // the pass over the contacts within reach: impulses, gaps, normal
  // velocities and active flags per micro step (row-major, j x contact)
  std::vector<double> pass_impulse, pass_gap, pass_normal;
  std::vector<double> total_impulse, total_gap, total_normal;
  std::vector<bool> pass_active, pattern;
  // contacts within reach of the ramp response (indices)
  std::vector<unsigned int> reach_contacts;
  bool contacts_in_reach = false;
  // per macro step with contacts in reach: whether one was active, and the
  // contact state of every micro step (replayed to after_micro_step)
  bool record_contacts = false;
  // (a pool: its first n_recorded entries, reused without allocation)
  std::vector<ContactSample> contact_record;
  unsigned int n_recorded = 0;
  ContactSample sample;
  /** Fill @p sample from the explicit integrator. */
  void take_sample(ContactSample &sample) const;

  // the pass's trapezoidal load weights, load s at micro step j: s m + j - 1
  std::vector<double> pass_load_weight;
  // per macro step: C_E V integer velocity at j = m, interface increments
  Vector<double> v_end, increment_sum, increment_weighted;
  // work vectors of step() and superpose() (no allocation per macro step)
  Vector<double> free_jump, implicit_guess, u_old, solve_work;
  // the ramp's part of the contact quantities of all micro steps (superpose())
  Vector<double> ramp_impulse, ramp_gap, ramp_normal;

  double interface_work = 0.;
  double max_jump = 0.;
  unsigned long n_redone = 0;
  unsigned int max_iterations = 0;
  double seconds[3] = {0., 0., 0.};
  double setup = 0.;
  Vector<double> link_force;
  /**
   * The columns M_eff^-1 C_I^T (n_I x n_G, column by column), kept when
   * they fit in 2e7 entries (160 MB): the link (G4) is then a product
   * instead of a solve.
   */
  DenseColumns link_columns;
  Vector<double> link_acceleration;

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
  /** @p reach = @p source on reach_dofs. */
  void gather_reach(const Vector<double> &source, Vector<double> &reach) const;
  std::vector<Vector<double>> pass_velocity_reach, pass_damping_reach;
  /** S V_{j-1/2} of the pass on the reach (S = dt M^-1 K, A7), per micro step. */
  std::vector<Vector<double>> pass_stiffness_reach;
  /** S V of a micro step on every explicit DoF (reach not all DoFs). */
  Vector<double> stiffness_velocity_full;
  /** Reach index of the explicit DoF of each interface pair. */
  std::vector<unsigned int> interface_reach_index;
  /** Work vectors of ramp_dissipation(). */
  mutable Vector<double> dissipation_p, dissipation_p_prev, dissipation_c, dissipation_g,
      dissipation_q;

  /** The dissipated energy of the ramp part @p r Lambda after the pass (G3', A7). */
  double ramp_dissipation(const RampResponse &r, const Vector<double> &lambda) const;
  mutable Vector<double> global_U, global_V;
  CDLagrange::Snapshot snapshot;
};
} // namespace hati

#endif

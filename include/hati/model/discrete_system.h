#ifndef hati_model_discrete_system_h
#define hati_model_discrete_system_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <hati/contact/sparse_rows.h>
#include <hati/model/rope.h>

#include <any>
#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * One unilateral contact: a row of the contact operator `L` (the gradient
 * of the normal gap), the gap at zero displacement and the restitution
 * coefficient of Newton's impact law (algorithms.md A4-A5). The gap is
 * `g(U) = initial_gap + sum_i coefficients[i] * U[dofs[i]]`; the impulse
 * `lambda >= 0` acts on the structure as `L^T lambda`.
 */
struct ContactRow : SparseRow
{
  std::string name;
  double initial_gap = 0.;
  double restitution = 0.;
  /**
   * A bilateral row (a two-sided contact without clearance, e.g. a braked
   * wheel): always active, its impulse of either sign (A5 as an equality).
   */
  bool bilateral = false;
  /**
   * Coulomb friction coefficient `mu` (-, A9, doc/theory.md A9); 0: a
   * frictionless contact (the A5 LCP, tangents empty).
   */
  double friction = 0.;
  /**
   * Rows of the tangential relative velocity `u_t = T_k V` (A9): the
   * tangent directions of the contact plane in which friction acts (two,
   * or one when the node rolls freely along an axis of the plane), with the
   * same DoFs as the normal row plus the other translations of its nodes.
   * The tangential impulse acts on the structure as `T_k^T lambda_t`.
   * Empty for a frictionless contact.
   */
  std::vector<SparseRow> tangents;
  /** Whether the contact has friction (mu > 0 and a tangent row). */
  bool frictional() const { return friction > 0. && !tangents.empty(); }
  /**
   * An equality of a tie or a rigid link (B1, doc/theory.md 11.2) enforced
   * by the explicit scheme: bilateral, gap 0, restitution 0, so that
   * `L V = 0` after every step. Not a contact: contacts.csv, the contact
   * statistics, the contact counts and the static contact forces leave it
   * out. The model appends these rows after its contacts.
   */
  bool constraint = false;
};

/** The number of rows of @p contacts that are contacts (not constraint rows). */
unsigned int n_contacts(const std::vector<ContactRow> &contacts);

/**
 * Gaps up to this (m) count as closed in the active set of CD-Lagrange (A4,
 * doc/theory.md 1.2). A contact at rest keeps a normal velocity of round-off
 * size after its impulse (1e-18 m/s on the crane's wheels), and its gap,
 * integrated from it, drifts by some 1e-22 m: with `g <= 0` such a contact
 * opened for one step and its body fell into the support (a 0.04 m/s
 * chatter of a crane wheel resting on its rail). 1e-12 m is far below any
 * gap a structure resolves and far above that drift.
 */
constexpr double closed_gap_tolerance = 1e-12;

/**
 * Whether a contact with the initial gap @p gap (m) touches at the start of
 * a run: within closed_gap_tolerance, as the integrators take it (A4), so
 * the round-off gap of a static state (8.7e-19 m) is not an impact.
 */
constexpr bool initially_touching(const double gap)
{
  return gap <= closed_gap_tolerance;
}

/** Whether a contact of @p contacts has friction (ContactRow::frictional()). */
bool has_friction(const std::vector<ContactRow> &contacts);

/**
 * A named point whose displacement and velocity components are written to
 * `history.csv`. `labels[i]` is the component name ("x", "y" or "z") of
 * `dofs[i]`.
 */
/**
 * A spring that holds the structure to the ground and whose force is a
 * load on the building (a crane's runway springs, doc/user_guide.md "The
 * crane on its runway"): `sign k u` with u the component @p component of
 * the monitor point @p monitor. The outputs give its largest and smallest
 * force (ReactionPeaks), as `<group>.<name>.<direction>`.
 */
struct ReactionSpring
{
  std::string group, name, direction, monitor;
  unsigned int component = 0;
  /** N/m; the force is sign x stiffness x u (N). */
  double stiffness = 0., sign = 1.;
};

struct MonitorPoint
{
  std::string name;
  std::vector<std::string> labels;
  std::vector<types::global_dof_index> dofs;
  /**
   * For a point whose DoFs are eliminated (a beam node tied to a solid face,
   * the slave of a rigid link): component i is `rows[i] . U` over free DoFs
   * (value()). Empty: component i is `U[dofs[i]]`.
   */
  std::vector<SparseRow> rows;

  /** Component @p i of the point for the DoF vector @p U. */
  double value(const unsigned int i, const Vector<double> &U) const
  {
    if (rows.empty())
      return U[dofs[i]];
    double v = 0.;
    for (unsigned int k = 0; k < rows[i].dofs.size(); ++k)
      v += rows[i].coefficients[k] * U[rows[i].dofs[k]];
    return v;
  }
};

/**
 * A time-dependent part of the external force:
 * `F_ext(t) += amplitude(t) * shape`.
 */
struct TimeDependentLoad
{
  Vector<double> shape;
  std::function<double(double)> amplitude;
  /**
   * For the load of a base acceleration along global direction d
   * (0, 1, 2), shape = -mass_influence[d]: an integrator with a lumped mass
   * uses -M_lumped influence[d] instead, so that a rigid motion stays
   * exact. -1 for other loads.
   */
  int acceleration_direction = -1;
};

/**
 * What one subdomain is once a model has built it (doc/architecture.md):
 * mass, stiffness, external forces, constraints, contacts, monitors and the
 * initial state. Integrators only ever see this class, never a mesh.
 *
 * The stiffness matrix refers to the sparsity pattern stored here, so a
 * DiscreteSystem is neither copied nor moved.
 */
class DiscreteSystem
{
public:
  DiscreteSystem() = default;
  DiscreteSystem(const DiscreteSystem &) = delete;
  DiscreteSystem &operator=(const DiscreteSystem &) = delete;

  /** Set every size to @p n and zero all vectors. */
  void reinit(const unsigned int n);

  /** Number of degrees of freedom. */
  unsigned int n_dofs() const { return lumped_mass.size(); }

  /** Whether a stiffness matrix was assembled (false for a rigid mass). */
  bool has_stiffness() const { return stiffness_pattern.n_rows() > 0; }

  /**
   * Mean number of entries per row of the stiffness pattern (-), 0 without
   * one: about 10-40 for frames, 80 and more for 3D continua, whose direct
   * factors fill in (the choice of `Linear solver = auto`).
   */
  double stiffness_row_length() const
  {
    return has_stiffness() ? double(stiffness_pattern.n_nonzero_elements()) /
                                 stiffness_pattern.n_rows()
                           : 0.;
  }

  /** Whether a consistent mass matrix was assembled (implicit integrator). */
  bool has_consistent_mass() const { return !consistent_mass.empty(); }

  /** External force at time @p t: constant part plus time-dependent ones. */
  void external_force(const double t, Vector<double> &f) const;

  /**
   * Upper bound of the highest circular frequency of the explicit system
   * (rad/s), `omega_max^2 >= lambda_max(M^-1 K)`. Models set
   * `omega_max_bound` from an element-by-element bound; when they do not,
   * this returns the Gershgorin bound of `M^-1 K`.
   */
  double highest_frequency_bound() const;

  /** Lumped (diagonal) mass, kg (or kg m^2 for rotations). */
  Vector<double> lumped_mass;
  /**
   * Flags of the DoFs held fixed (supports, lateral constraints, and the
   * slave DoFs of ties, whose values the model restores for output); they
   * have zero velocity and the integrators do not move them. The matrices
   * are condensed: rows and columns of fixed DoFs hold only a diagonal
   * entry.
   */
  std::vector<bool> fixed;

  SparsityPattern stiffness_pattern;
  /** Stiffness K (N/m); empty for a rigid point mass. */
  SparseMatrix<double> stiffness;

  /**
   * Consistent mass (kg, kg m^2), on the sparsity pattern of the stiffness;
   * empty when the model provides only the lumped mass. Used by the
   * implicit integrator and the static and modal analyses (the lumped mass
   * stands in when it is empty).
   */
  SparseMatrix<double> consistent_mass;

  /**
   * A viscous damping matrix of the system's own (N s/m), on the sparsity
   * pattern of the stiffness; empty when it has none. Newmark adds it to the
   * damping `C` of (N2) besides Rayleigh's `a0 M + a1 K`: the Craig-Bampton
   * reduced part with `Model/Decomposition/Reduction modal damping ratio`
   * (doc/theory.md 12.3), whose run then gives the reduced part no other
   * damping.
   */
  SparseMatrix<double> damping_matrix;

  /** Whether the system has a damping matrix of its own (damping_matrix). */
  bool has_damping_matrix() const { return !damping_matrix.empty(); }

  /**
   * Influence vectors of a rigid translation along global x, y, z (one per
   * direction, 1 on the translational DoFs of that direction, 0 elsewhere
   * and on fixed DoFs): base excitation `F = -M r a_g` and modal
   * participation factors. Empty vectors where the model has no such DoFs.
   */
  std::array<Vector<double>, 3> influence;

  /**
   * `M r_d` per direction (N per m/s^2) for a rigid translation of the whole
   * model *including its supports*: the loads of gravity and of a base
   * acceleration and the modal participation use it. It keeps the inertia
   * coupled to the supports that `M influence[d]` loses when the matrices are
   * condensed; zero on fixed DoFs. Models fill it; when they do not,
   * fill_default_mass_influence() uses `M influence[d]`.
   */
  std::array<Vector<double>, 3> mass_influence;

  /**
   * Base excitation on part of the model only (`Loading/Excited members`,
   * doc/theory.md section 4 with `M` restricted to the excited members): `M_S
   * r_d` (consistent, N per m/s^2) of the excited elements and point masses.
   * Empty vectors: the whole model is excited (mass_influence).
   */
  std::array<Vector<double>, 3> excited_mass_influence;

  /**
   * Lumped mass (kg) of the excited part only, for the integrators with a
   * lumped mass (they load `-M_lumped,S r_d a_g`); empty: lumped_mass.
   */
  Vector<double> excited_lumped_mass;

  /** Fill the empty mass_influence vectors with `M influence[d]`. */
  void fill_default_mass_influence();

  /**
   * Gravity with the lumped mass minus gravity with the consistent mass,
   * `g (M_lumped r - M r)` (N): what CD-Lagrange adds to constant_force so
   * that a rigid motion (free flight) is exact, and what a static state
   * for it must carry.
   */
  Vector<double> lumped_gravity_correction() const;

  /**
   * Gravity (m/s^2) included in constant_force as `sum_d g_d
   * mass_influence[d]`; an integrator with a lumped mass swaps that part for
   * `M_lumped influence[d] g_d` (free fall exact). Zero if the model puts no
   * gravity there that way.
   */
  Tensor<1, 3> gravity;

  /** Constant external force (N), e.g. gravity `M g`. */
  Vector<double> constant_force;
  std::vector<TimeDependentLoad> time_dependent_loads;

  std::vector<ContactRow> contacts;
  /**
   * Ropes (R1, doc/theory.md 10): nonlinear, tension-only forces that
   * CD-Lagrange applies step by step; the static and modal analyses use
   * their tangent. Not part of `stiffness` (its pattern holds their
   * couplings).
   */
  std::vector<Rope> ropes;
  /**
   * The data of force laws that have no member here, under the name of the
   * law's registration (force_law_registry(), doc/architecture.md "Force
   * laws"): the law's factory reads it, the integrators never do. A new law
   * needs no change of this class. The decomposition into HATI's subdomains
   * cannot renumber it and refuses a system that has some.
   */
  std::map<std::string, std::any> law_data;
  std::vector<MonitorPoint> monitors;
  /** The springs whose forces are reported as reactions (none by default). */
  std::vector<ReactionSpring> reaction_springs;

  Vector<double> initial_displacement;
  Vector<double> initial_velocity;
  /**
   * Time of the initial state (s): 0, or the time of the state a run
   * restarts from (Analysis/Initial state = file). The integrators count
   * their time from it (`t = start_time + n dt`) and evaluate the loads at
   * it, so that a restarted record goes on where it stopped.
   */
  double start_time = 0.;
  /**
   * The forces (N, on the DoFs) that the closed contacts carry in a static
   * initial state, `sum_k L_k^T lambda_k` with the tangent rows of sticking
   * friction: CD-Lagrange adds them to `G_0` (A7, doc/theory.md 1.1) so that
   * a structure that starts at rest on its contacts has `V_{1/2} = V_0`
   * (no contact DoF moving into its support at the first half step). Empty:
   * none (a start that is not static, or no contact closed).
   */
  Vector<double> initial_contact_reaction;

  /** Element-by-element bound of omega_max (rad/s), negative if unset. */
  double omega_max_bound = -1.;

  /**
   * One-line warnings of the model's set-up (e.g. linear hexahedra, which
   * lock in bending): Problem prints them and summary.json lists them.
   */
  std::vector<std::string> warnings;

  /**
   * Why lumped_mass is not the model's lumped mass, e.g. ties and rigid
   * links eliminated as constraints (a diagonal mass cannot carry them):
   * the explicit integrator (CD-Lagrange, HATI's explicit part) and Newmark
   * with `Mass = lumped` refuse to run with this one-line reason. Empty: the
   * lumped mass holds.
   */
  std::string lumped_mass_refusal;
};

/**
 * Throw a one-line error if the stiffness, a mass or the constant force of
 * @p system has an entry that is not finite (an overflow from material
 * constants or coordinates too large).
 */
void check_finite(const DiscreteSystem &system);

/**
 * Decouple the fixed DoFs of a matrix on the stiffness pattern: their rows
 * and columns keep only a positive diagonal entry (1 where it was not
 * positive). The DiscreteSystem matrices are condensed already; this makes
 * it hold whatever a model put there, before a factorisation.
 */
void decouple_fixed_dofs(SparseMatrix<double> &matrix, const std::vector<bool> &fixed);

/**
 * Largest eigenvalue of the element problem `K_e x = omega^2 M_e x` with a
 * diagonal (lumped) element mass @p element_mass. Its maximum over the
 * elements bounds `omega_max^2` of the assembled system from above
 * (element-by-element bound, algorithms.md section 1).
 */
double element_omega_squared(const FullMatrix<double> &element_stiffness,
                             const std::vector<double> &element_mass);
} // namespace hati

#endif

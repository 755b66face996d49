#ifndef hati_time_newmark_h
#define hati_time_newmark_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <hati/linear_algebra/direct_solver.h>
#include <hati/model/discrete_system.h>
#include <hati/time/energies.h>
#include <hati/time/maxwell_memory.h>
#include <hati/time/rayleigh_damping.h>

#include <array>
#include <memory>
#include <string>

namespace hati
{
using namespace dealii;

/**
 * Size (DoFs) from which Newmark stores a fully dense system (a reduced
 * part) as dense rows and multiplies through BLAS: below it, the rows'
 * own loop (the small models' results stay bitwise those of the sparse path).
 */
constexpr unsigned int dense_rows_from = 64;

/**
 * Parameters of the implicit Newmark integrator (algorithms.md section 2,
 * N1-N3). The defaults are the average acceleration scheme (trapezoidal rule,
 * `beta = 1/4`, `gamma = 1/2`): unconditionally stable, second order, no
 * numerical dissipation.
 */
struct NewmarkParameters
{
  /**
   * Declare "Beta", "Gamma", "Linear solver" and "Solver tolerance" in the
   * subsection @p prm currently is in (the caller enters it).
   */
  static void declare_parameters(ParameterHandler &prm);

  /**
   * Read the entries declared by declare_parameters() from the current
   * subsection. Throws if `gamma < 1/2` (the scheme would amplify the
   * solution: negative numerical damping).
   */
  void parse_parameters(ParameterHandler &prm);

  /**
   * Throws, naming `Time integration/Newmark/Beta`, unless `2 beta >= gamma`
   * (unconditional stability); called by the Problem for the methods that
   * step with Newmark (Newmark, and HATI for its implicit subdomain) before
   * any model is built.
   */
  void check_unconditional_stability() const;

  /** Newmark beta (-), weight of A_{n+1} in U_{n+1} (N1, N3). */
  double beta = 0.25;
  /** Newmark gamma (-), weight of A_{n+1} in V_{n+1} (N1, N3); >= 1/2. */
  double gamma = 0.5;
  /**
   * "KLU" / "MUMPS": the effective matrix of N2 is factorised once with
   * Amesos_Klu / Amesos_Mumps; "auto" (and "direct", its former name): KLU
   * below 20,000 DoFs, MUMPS at and above, and from 2,000 DoFs for 3D
   * continua (resolve_linear_solver());
   * "iterative": CG preconditioned by ML algebraic multigrid.
   */
  std::string linear_solver = "auto";
  /** Relative residual of the iterative solver, ||r|| <= tol ||b|| (-). */
  double solver_tolerance = 1e-10;
  /** "consistent" (the model's consistent mass, if it has one) or "lumped". */
  std::string mass = "consistent";
};

/**
 * Implicit Newmark integrator of `M A + C V + K U = F_ext(t)` for a linear
 * DiscreteSystem (algorithms.md section 2):
 *
 * - (N1) predictors `U* = U_n + DT V_n + DT^2 (1/2 - beta) A_n`,
 *   `V* = V_n + DT (1 - gamma) A_n`;
 * - (N2) `M_eff A_{n+1} = F_{n+1} - C V* - K U*`,
 *   `M_eff = M + gamma DT C + beta DT^2 K`, `C = a0 M + a1 K`;
 * - (N3) correctors `U_{n+1} = U* + beta DT^2 A_{n+1}`,
 *   `V_{n+1} = V* + gamma DT A_{n+1}`.
 *
 * With frequency-range damping (N4) the internal force is `K (U + S)`,
 * `S_{n+1} = sum_l alpha_l e_l q_l,n + beta_s (U_{n+1} - U_n)` (the memory
 * update with the average velocity `(U_{n+1} - U_n) / DT`, MaxwellMemory),
 * so `M_eff = M + beta DT^2 (1 + beta_s) K` and the right-hand side of (N2)
 * is `F_{n+1} - K ((1 + beta_s) U* - beta_s U_n + sum_l alpha_l e_l q_l,n)`.
 *
 * M is the consistent mass of the system when it has one, else the lumped
 * diagonal. M_eff is assembled once as a Trilinos matrix and factorised once
 * (Amesos_Klu or Amesos_Mumps) or handed to CG + ML AMG. Fixed DoFs stay at zero: their
 * rows of M_eff are decoupled and their right-hand sides are set to zero.
 *
 * The integrator only sees the DiscreteSystem (no model type, no mesh).
 */
class Newmark
{
public:
  /**
   * Assemble and factorise M_eff (N2) and compute the initial acceleration
   * from the system's initial displacement and velocity (set_initial_state()).
   *
   * @param system the discrete system; it must outlive the integrator.
   * @param DT time step (s), > 0.
   * @param parameters beta, gamma (-) and the linear solver.
   * @param damping Rayleigh coefficients a0 (1/s) and a1 (s).
   * @param branches Maxwell branches of frequency-range damping (N4; none by
   * default, not combined with Rayleigh damping).
   *
   * Throws ExcMessage if the factorisation fails (a singular M_eff: a model
   * without mass and without enough supports).
   */
  Newmark(const DiscreteSystem &system,
          const double DT,
          const NewmarkParameters &parameters,
          const RayleighDamping &damping,
          const MaxwellBranches &branches = MaxwellBranches());

  ~Newmark();
  Newmark(const Newmark &) = delete;
  Newmark &operator=(const Newmark &) = delete;

  /**
   * Restart from displacement @p U0 (m) and velocity @p V0 (m/s) at the
   * current time t: the initial acceleration solves
   * `M A_0 = F_ext(t) - C V_0 - K U_0` (algorithms.md section 2), fixed DoFs
   * are zeroed, and the accumulated external work and dissipated energy are
   * reset to zero, as are the memory variables of frequency-range damping. Free DoFs with
   * zero lumped mass get A_0 = 0.
   */
  void set_initial_state(const Vector<double> &U0, const Vector<double> &V0);

  /**
   * One step t_n -> t_{n+1}: predictors (N1), solve (N2), correctors (N3);
   * free_step() then finish_step().
   */
  void step();

  /**
   * @name Phases of a step, for the coupling (G1, G4): free_step(), then
   * any add_link(), then finish_step().
   */
  /** @{ */
  /**
   * (N1)-(N3) without interface force: the free state at t_{n+1}
   * (new_displacement(), new_velocity(), new_acceleration()).
   */
  void free_step();

  /**
   * (G4) the link correction of a force @p force (N) acting at t_{n+1}:
   * `A_link = M_eff^-1 force`, `A += A_link`, `V += gamma DT A_link`,
   * `U += beta DT^2 A_link` on the new state. The work of that force is
   * the coupling's (interface_work), not external_work.
   */
  void add_link(const Vector<double> &force);

  /**
   * (G4) the link correction of a known acceleration @p a_link (m/s^2),
   * e.g. `M_eff^-1 C_I^T Lambda` from precomputed columns: `A += a_link`,
   * `V += gamma DT a_link`, `U += beta DT^2 a_link`.
   */
  void add_link_acceleration(const Vector<double> &a_link);

  /** The new state becomes U_{n+1}, V_{n+1}, A_{n+1}; energies are booked. */
  void finish_step();

  /** The state at t_{n+1} being built between free_step() and finish_step(). */
  const Vector<double> &new_displacement() const { return U_star; }
  const Vector<double> &new_velocity() const { return V_star; }
  /** @} */

  /**
   * The state vectors {U_n, V_n, A_n} between two steps, for the coupling
   * (it reads and sets the state of the macro-step map).
   */
  std::array<Vector<double> *, 3> linear_state() { return {{&U, &V, &A}}; }

  /**
   * Solve `M x = b` with the mass of the integrator (consistent or lumped;
   * rows of fixed DoFs give x = 0): initial accelerations.
   */
  void solve_with_mass(Vector<double> &x, const Vector<double> &b) const;

  /** Current time t_n (s). */
  double time() const { return t; }
  /** Number of steps done since construction. */
  unsigned long step_number() const { return n_steps; }
  /** Time step DT (s). */
  double time_step() const { return dt; }

  /** U_n (m). */
  const Vector<double> &displacement() const { return U; }
  /** V_n (m/s). */
  const Vector<double> &velocity() const { return V; }
  /** A_n (m/s^2). */
  const Vector<double> &acceleration() const { return A; }

  /**
   * Energies at t_n (J): kinetic `1/2 V.M V`, internal `1/2 U.K U`,
   * external work accumulated with the trapezoidal rule
   * `1/2 (U_{n+1} - U_n).(F_n + F_{n+1})` and dissipated energy
   * `1/2 (U_{n+1} - U_n).C (V_n + V_{n+1})`; with frequency-range damping
   * the branches store `1/2 sum_l alpha_l q_l.K q_l` (damping_stored) and
   * have dissipated the work `1/2 (U_{n+1} - U_n).K (S_n + S_{n+1})` less
   * that (N4). For average acceleration
   * total() stays constant to round-off (proof in newmark.cc).
   */
  Energies energies() const;

  /** Wall time of the factorisation (or AMG set-up) of M_eff (s). */
  double factorization_time() const { return factorization_seconds; }

  /**
   * The solver of M_eff, resolved for this system's number of DoFs
   * (resolve_linear_solver()): "KLU", "MUMPS" or "iterative".
   */
  const std::string &linear_solver() const { return solver_name; }

  /**
   * Solve `M_eff x = b` (the matrix of N2) with the existing factorisation
   * (or CG + AMG, @p x being the initial guess), for the explicit/implicit
   * coupling. @p b is a force (N), @p x an acceleration (m/s^2). Rows of
   * fixed DoFs are decoupled diagonal rows: give b = 0 there to get x = 0.
   * Throws if the solution is not finite or CG does not converge.
   */
  void solve_with_effective_matrix(Vector<double> &x, const Vector<double> &b) const;

  /** Rayleigh coefficients a0 (1/s) and a1 (s) in use. */
  double mass_damping_coefficient() const { return a0; }
  double stiffness_damping_coefficient() const { return a1; }
  /** The memory variables of frequency-range damping (N4; inactive without). */
  const MaxwellMemory &memory() const { return branches; }
  /**
   * Set the memory variables q_l (m) of frequency-range damping (N4)
   * between two steps, keeping the branch work: the coupling's macro-step
   * map (HATICoupling::set_state()).
   */
  void set_memory(const std::vector<Vector<double>> &q);

private:
  /** dst = M src with the consistent or the lumped mass. */
  void mass_vmult(Vector<double> &dst, const Vector<double> &src) const;
  /** dst = K src (zero without stiffness). */
  void stiffness_vmult(Vector<double> &dst, const Vector<double> &src) const;
  /** dst = C src = a0 M src + a1 K src; dst = 0 without damping. */
  void damping_vmult(Vector<double> &dst, const Vector<double> &src) const;
  /** Zero the entries of fixed DoFs. */
  void zero_fixed(Vector<double> &x) const;
  /** Whether C != 0: Rayleigh's a0, a1 or the system's own damping matrix. */
  bool viscous_damping() const
  {
    return a0 != 0. || a1 != 0. || system.has_damping_matrix();
  }
  /**
   * Copy K and C = a0 M + a1 K row by row onto one pattern (CSR), so that
   * the right-hand side `F - K U* - C V*` of (N2) is one serial pass over
   * the rows (a deal.II product goes through the task scheduler, which
   * costs more than the product on a small subdomain).
   */
  void build_row_operators();
  /** dst = A src for the operator with @p values on the rows' pattern. */
  void row_vmult(const std::vector<double> &values,
                 Vector<double> &dst,
                 const Vector<double> &src) const;

  const DiscreteSystem &system;
  const double dt;
  const double beta, gamma;
  const double a0, a1;
  /** resolve_linear_solver() of the parameters, and the Amesos package of
   * the factorisations (direct_solver_package()). */
  const std::string solver_name, package;
  const bool direct;
  const double tolerance;
  const bool use_consistent_mass;

  double t = 0.;
  unsigned long n_steps = 0;

  /** M_eff and its factorisation or preconditioner (newmark.cc). */
  struct EffectiveSolver;
  std::unique_ptr<EffectiveSolver> solver;
  /** The consistent mass with fixed DoFs decoupled, factorised on first use. */
  mutable std::unique_ptr<DirectSolver> mass_solver;

  double factorization_seconds = 0.;

  // K and C on one pattern, row by row (build_row_operators())
  /**
   * Whether every row holds every column (a reduced part's dense matrices,
   * from dense_rows_from DoFs): the row operators are then row-major dense
   * matrices and their products BLAS dgemv (build_row_operators()).
   */
  bool dense_rows = false;
  std::vector<std::size_t> row_start;
  std::vector<unsigned int> row_column;
  std::vector<double> row_stiffness, row_damping;

  Vector<double> U, V, A;
  Vector<double> F;  // F_ext(t_n)
  Vector<double> CV; // C V_n (kept for the dissipated energy)
  /** Memory variables of frequency-range damping (N4). */
  MaxwellMemory branches;
  /** N4: K S_n, kept for the branch work; `W` the displacement K acts on in (N2). */
  Vector<double> KS, KS_new, W;
  // work vectors
  mutable Vector<double> U_star, V_star, A_new, rhs, tmp, F_new, CV_new;

  double external_work = 0.;
  double dissipated = 0.;
};
} // namespace hati

#endif

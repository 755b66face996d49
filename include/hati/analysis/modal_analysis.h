#ifndef hati_analysis_modal_analysis_h
#define hati_analysis_modal_analysis_h

#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/** The lowest vibration modes of a DiscreteSystem (compute_modes()). */
struct ModalResult
{
  /** Natural frequencies f_k = omega_k / (2 pi) (Hz), ascending. */
  std::vector<double> frequencies;
  /** Mode shapes phi_k, mass-normalised: phi_k.M phi_k = 1 (zero on fixed DoFs). */
  std::vector<Vector<double>> modes;
  /** Participation factors Gamma_kd = phi_k.M r_d (kg^(1/2)), d = x, y, z. */
  std::vector<std::array<double, 3>> participation;
  /** Effective modal masses Gamma_kd^2 (kg). */
  std::vector<std::array<double, 3>> effective_mass;
  /** Total mass per direction r_d.M r_d (kg); sum_k Gamma_kd^2 over all modes. */
  std::array<double, 3> total_mass{{0., 0., 0.}};
  /** Closed contact rows (zero initial gap, with a free DoF), held bilaterally. */
  unsigned int n_closed_contacts = 0;
  /** Independent constraints among them = DoFs eliminated (-). */
  unsigned int n_constraints = 0;
};

/**
 * The @p n_modes lowest modes of the generalized eigenproblem
 * `K phi = omega^2 M phi` (doc/theory.md 7.1; free DoFs; M the consistent
 * mass if the system has one, else the lumped diagonal). Rigid-body modes,
 * if the model has any, come out with frequency 0.
 *
 * With @p close_contacts, every contact row with a zero initial gap (the
 * one-sided contacts that touch, both rows of a two-sided contact without
 * clearance) is a bilateral constraint `L_k U = 0` (doc/theory.md 7.3, as in
 * the static analysis); contacts with a positive gap stay open. The
 * constraints are eliminated, `U = T q` with one slave DoF per independent
 * row: the eigenproblem `T^T K T q = omega^2 T^T M T q` is solved and the
 * modes are returned as `phi = T q` (they satisfy `L_k phi = 0`).
 *
 * Uses ARPACK (shift-invert Lanczos, one Amesos_Klu or Amesos_Mumps
 * factorisation of `K - sigma M`, direct_solver_package()) when its constraint `2 n_modes
 * + 1 < ncv <= n_free` can be met, dense LAPACK (dsygv) on the free DoFs otherwise. Every
 * returned pair satisfies `||K phi - omega^2 M phi|| <= 1e-6 (||K phi|| + omega^2 ||M
 * phi||)` or an exception is thrown.
 *
 * @param system the discrete system (stiffness, mass, fixed DoFs, influence).
 * @param n_modes number of modes wanted (-), at most the number of free DoFs
 *        (less the eliminated ones).
 * @param close_contacts hold the zero-gap contacts closed (true) or ignore
 *        every contact (false).
 * @param rope_state the displacement (m) at which the ropes' tangent
 *        `k e e^T + (T / l)(I - e e^T)` (R1, doc/theory.md 10.4) is added to
 *        K, normally the static state (null: U = 0); no effect without ropes.
 * @param linear_solver the value of `Time integration/Newmark/Linear
 *        solver` (auto, KLU, MUMPS, direct or iterative), which chooses the
 *        factorisation of the shift-invert (direct_solver_package(); with
 *        iterative, that of auto).
 * @param held rows held at zero, `L U = 0`, besides the fixed DoFs (null:
 *        none), eliminated as the closed contacts are: the boundary rows of
 *        the fixed-interface modes of a Craig-Bampton reduction (C1,
 *        doc/theory.md 12.1).
 */
ModalResult compute_modes(const DiscreteSystem &system,
                          const unsigned int n_modes,
                          const bool close_contacts = true,
                          const Vector<double> *rope_state = nullptr,
                          const std::string &linear_solver = "auto",
                          const std::vector<SparseRow> *held = nullptr);

/**
 * `M r_d` per direction d (kg, N per m/s^2; empty where the model has no
 * influence vector), with the inertia coupled to the supports where the
 * system provides it (DiscreteSystem::mass_influence), zero on fixed DoFs,
 * and the total masses `r_d.M r_d` (kg) in @p total_mass: what the
 * participation factors `Gamma_kd = phi_k.M r_d` use (doc/theory.md 7.1).
 */
std::array<Vector<double>, 3> influence_masses(const DiscreteSystem &system,
                                               const SparseMatrix<double> &M,
                                               std::array<double, 3> &total_mass);

/** One eigenpair of ModalProblem::modes_near(). */
struct Eigenpair
{
  /** The eigenvalue lambda = omega^2 (1/s^2). */
  double lambda = 0.;
  /**
   * The mode phi on the system's DoFs, mass-normalised (phi.M phi = 1), zero
   * on fixed DoFs, the eliminated rows distributed back, its largest entry
   * positive.
   */
  Vector<double> phi;
  /**
   * M phi in the eigenproblem's space (zero on fixed DoFs and on the
   * eliminated ones): `psi.Mphi = psi^T M phi` for every mode psi of the
   * same ModalProblem.
   */
  Vector<double> Mphi;
};

/**
 * The eigenproblem of compute_modes() set up once (K, M, the closed contacts
 * and held rows eliminated), then solved for the modes nearest any shift:
 * spectrum slicing (doc/theory.md 12.1), one shift-invert Lanczos run of
 * moderate size per slice instead of one large run, whose orthogonalisation
 * costs O(n ncv^2) per restart. compute_modes() is modes_near() at
 * lowest_shift().
 */
class ModalProblem
{
public:
  /**
   * Assemble and condense the eigenproblem; the parameters are those of
   * compute_modes().
   */
  ModalProblem(const DiscreteSystem &system,
               const bool close_contacts = true,
               const Vector<double> *rope_state = nullptr,
               const std::string &linear_solver = "auto",
               const std::vector<SparseRow> *held = nullptr);
  ~ModalProblem();

  /** Free DoFs less the eliminated ones: the number of eigenpairs (-). */
  unsigned int n_free() const;
  /** Closed contact rows (ModalResult::n_closed_contacts). */
  unsigned int n_closed_contacts() const;
  /** Independent constraints among them (ModalResult::n_constraints). */
  unsigned int n_constraints() const;
  /** The mass matrix M of the eigenproblem on the system's DoFs (zero on fixed DoFs). */
  const SparseMatrix<double> &mass() const;
  /**
   * The stiffness K of the eigenproblem on the system's DoFs, the ropes'
   * tangent included, before the elimination (fixed rows decoupled).
   */
  const SparseMatrix<double> &stiffness() const;

  /**
   * The number of eigenvalues below @p lambda (1/s^2, > 0) of the
   * eigenproblem solved: the negative pivots of the `L D L^T` factorisation
   * of `K - lambda M` (MUMPS, SymmetricMumps::negative_pivots(); Sylvester's
   * law of inertia, doc/theory.md 14.5), fixed and eliminated DoFs left out.
   * Throws if the factorisation fails (lambda on an eigenvalue).
   */
  unsigned int count_below(const double lambda) const;

  /**
   * A load @p f (N) on the system's DoFs brought into the eigenproblem's
   * space: `f <- T^T f`, zero on fixed and eliminated DoFs (the space of
   * Eigenpair::Mphi).
   */
  void condense_load(Vector<double> &f) const;

  /**
   * The static solution `U = T (T^T K T)^-1 f` (m) of a load @p f already
   * condensed (condense_load()): the closed contacts and held rows hold,
   * the eliminated DoFs distributed back. One factorisation of the condensed
   * stiffness, kept for the next calls. Throws, naming it, if the condensed
   * stiffness is singular (a mechanism).
   */
  Vector<double> solve_static(const Vector<double> &f) const;

  /**
   * The shift of compute_modes() (1/s^2): tiny and negative, so that `K -
   * sigma M` is positive definite and modes_near() gives the lowest modes.
   */
  double lowest_shift() const;

  /**
   * Whether modes_near() runs ARPACK for @p n_modes modes with @p n_deflated
   * modes deflated (its constraint `2 n_modes + 1 < ncv <= n_free() -
   * n_deflated`); otherwise it solves the dense problem.
   */
  bool lanczos_applies(const unsigned int n_modes,
                       const unsigned int n_deflated = 0) const;

  /**
   * The @p n_modes eigenpairs whose eigenvalues are nearest @p shift, but
   * for the @p deflated modes, ascending, each checked as compute_modes()
   * checks its modes (or an exception is thrown).
   *
   * A shift inside the spectrum makes `K - sigma M` indefinite: the LU
   * factorisation (KLU or MUMPS, with pivoting) handles it; should it fail
   * (the shift on an eigenvalue), the shift is nudged upwards by 1e-6
   * relative, at most twice. The factorisation is kept for the next call
   * with the same shift.
   *
   * @param shift sigma (1/s^2).
   * @param n_modes number of eigenpairs (-), at most n_free().
   * @param deflated modes found before by modes_near() (M-orthonormal)
   *        that the shift-invert operator is deflated of: ARPACK then finds
   *        the eigenpairs nearest the shift among the others. ARPACK only
   *        (lanczos_applies()).
   */
  std::vector<Eigenpair>
  modes_near(const double shift,
             const unsigned int n_modes,
             const std::vector<const Eigenpair *> &deflated = {}) const;

private:
  struct Data;
  std::unique_ptr<Data> data;
};
} // namespace hati

#endif

#ifndef hati_linear_algebra_direct_solver_h
#define hati_linear_algebra_direct_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>

namespace hati
{
using namespace dealii;

/**
 * Number of DoFs (-) from which `Linear solver = auto` (and `direct`)
 * factorises with MUMPS instead of KLU.
 */
constexpr unsigned int mumps_from_n_dofs = 20000;

/**
 * A system whose stiffness rows hold at least mumps_from_row_length entries
 * on average (3D continua: about 80 for linear hexahedra, 200 and more for
 * quadratic ones; frames 10-40) is factorised with MUMPS by `auto` from
 * mumps_from_n_dofs_continua DoFs: KLU's factors of a 3D mesh fill in (a
 * box girder of 8,166 DoFs: static 1.60 s with KLU, 0.66 s with MUMPS; the
 * 3D crane's 18,918: 17.0 s against 2.4 s).
 */
constexpr double mumps_from_row_length = 60.;
constexpr unsigned int mumps_from_n_dofs_continua = 2000;

/**
 * The solver that a value of `Time integration/Newmark/Linear solver`
 * selects for a system of @p n_dofs DoFs: "KLU" (Amesos_Klu), "MUMPS"
 * (Amesos_Mumps) or "iterative" (CG + ML AMG). `auto` and `direct` (its
 * name before issue #25) give KLU below mumps_from_n_dofs DoFs and MUMPS
 * at and above, and MUMPS from mumps_from_n_dofs_continua DoFs where the
 * stiffness rows are as long as a 3D continuum's (@p row_length at least
 * mumps_from_row_length); `KLU`, `MUMPS` and `iterative` give themselves.
 *
 * @param linear_solver the entry's value: auto, KLU, MUMPS, direct or iterative.
 * @param n_dofs number of DoFs of the system solved (-).
 * @param row_length mean entries per stiffness row
 *        (DiscreteSystem::stiffness_row_length(), -; 0: not known).
 *
 * Throws a one-line ExcMessage naming the entry for any other value.
 */
std::string resolve_linear_solver(const std::string &linear_solver,
                                  const unsigned int n_dofs,
                                  const double row_length = 0.);

/**
 * The Amesos package, "Amesos_Klu" or "Amesos_Mumps", of the matrices of a
 * system of @p n_dofs DoFs that are factorised: resolve_linear_solver()'s
 * choice, and with `iterative` that of `auto`, for the matrices that are
 * factorised whatever the solver (the consistent mass of the initial
 * acceleration, the static problem with closed contacts, the shifted
 * stiffness of the modal analysis).
 *
 * @param linear_solver the entry's value: auto, KLU, MUMPS, direct or iterative.
 * @param n_dofs number of DoFs of the system solved (-).
 * @param row_length mean entries per stiffness row (-; 0: not known).
 */
std::string direct_solver_package(const std::string &linear_solver,
                                  const unsigned int n_dofs,
                                  const double row_length = 0.);

/**
 * A sparse matrix factorised once with a Trilinos Amesos package
 * (Amesos_Klu or Amesos_Mumps, direct_solver_package()), then any number of
 * forward/backward substitutions: the effective matrix of Newmark (N2) and
 * the columns `M_eff^-1 C_I^T` of the coupling (G3'), the mass of the
 * initial acceleration, the stiffness of the static analysis and the
 * shifted stiffness of the modal analysis all go through it.
 */
class DirectSolver
{
public:
  /**
   * Not copyable: it owns its factorisation (a unique pointer).
   *
   * @param package the Amesos package: "Amesos_Klu" or "Amesos_Mumps"
   *        (throws ExcMessage for any other).
   */
  explicit DirectSolver(const std::string &package);
  ~DirectSolver();

  /**
   * Copy @p matrix to Trilinos and factorise it. Throws ExcMessage with
   * @p failure_message if the factorisation fails (a zero pivot: a singular
   * matrix).
   */
  void factorize(const SparseMatrix<double> &matrix, const std::string &failure_message);

  /**
   * Factorise @p matrix as factorize() does, unless it differs from the
   * matrix of the last factorize_or_update() that factorised (same
   * pattern) only in at most @p max_rank rows and columns: then keep that
   * factorisation and solve with a low-rank correction (LowRankUpdate,
   * Woodbury). Returns whether it factorised.
   */
  bool factorize_or_update(const SparseMatrix<double> &matrix,
                           const std::string &failure_message,
                           unsigned int max_rank = 48);

  /** x = A^-1 b; @p x and @p b may be the same vector. */
  void solve(Vector<double> &x, const Vector<double> &b) const;

  /**
   * Solve in place for @p n_rhs right-hand sides at once: @p columns holds
   * them one after another (column-major, the matrix's size each) and gets
   * the solutions. With MUMPS on a symmetric matrix one substitution pass
   * serves them all (BLAS 3 on the factor's blocks); otherwise one solve()
   * each.
   */
  void solve_many(double *columns, unsigned int n_rhs) const;
  /** Whether factorize() succeeded. */
  bool initialized() const;

  /** Wall time of the last factorize() (s). */
  double factorization_time() const { return seconds; }

  /** The Amesos package: "Amesos_Klu" or "Amesos_Mumps". */
  const std::string &package() const { return amesos_package; }

private:
  /** Solve in place with the factorisation only (no LowRankUpdate). */
  void solve_factorised(double *columns, unsigned int n_rhs) const;

  struct Data;
  std::unique_ptr<Data> data;
  std::string amesos_package;
  std::string failure;
  double seconds = 0.;
  /** The size of the factorised matrix. */
  std::size_t size = 0;
};
} // namespace hati

#endif

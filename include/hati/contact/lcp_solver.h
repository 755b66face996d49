#ifndef hati_contact_lcp_solver_h
#define hati_contact_lcp_solver_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Solve the linear complementarity problem of the velocity-level impact law
 * (algorithms.md A5):
 *
 *   w = W lambda + q,   0 <= w  _|_  lambda >= 0,
 *
 * with W the (symmetric, positive semi-definite) Delassus operator
 * `L M^-1 L^T` of a cluster of coupled contacts.
 *
 * - one contact: the closed form `lambda = max(0, -q / W)`;
 * - up to 12 contacts: exact enumeration of the active sets (the first
 *   complementary solution found, smallest active sets first);
 * - more: projected Gauss-Seidel to a relative tolerance of 1e-12,
 *   which converges for a symmetric positive definite W; an exception
 *   is thrown when it does not converge.
 *
 * Rows flagged in @p bilateral (empty: none) are equalities: always in the
 * active set, `w = 0`, their lambda of either sign.
 *
 * Returns lambda (impulses, N s).
 */
Vector<double> solve_lcp(const FullMatrix<double> &W,
                         const Vector<double> &q,
                         const std::vector<bool> &bilateral = {});

/**
 * The same into @p lambda (resized to the size of @p q): no allocation
 * once the clusters of every size up to 12 have been seen (the time step's
 * hot path).
 */
void solve_lcp(const FullMatrix<double> &W,
               const Vector<double> &q,
               const std::vector<bool> &bilateral,
               Vector<double> &lambda);

/**
 * The elimination of the rows B of a symmetric Delassus matrix W in favour
 * of the rows C (A9, doc/theory.md A9 "Links in a frictional cluster"):
 * with `W = [W_BB W_BC; W_CB W_CC]`, `X = W_BB^-1 W_BC` and the Schur
 * complement `S = W_CC - W_BC^T X`, so that `W_BB r_B + W_BC r_C = -q_B`
 * gives `r_B = -W_BB^-1 q_B - X r_C`. Shared by the frictionless clusters'
 * equalities (BilateralElimination) and the frictional clusters' links
 * (CondensedLinks).
 */
struct SchurElimination
{
  /** W_BC, W_BB^-1, X = W_BB^-1 W_BC and S = W_CC - W_BC^T X. */
  FullMatrix<double> Wbc, Wbb_inverse, X, S;
};

/**
 * @p e for the rows @p b and @p c of @p W: W_BB^-1 by Cholesky (LAPACK);
 * false, with only Wbc set, where W_BB is singular to round-off
 * (`W_BB^-1 W_BB = I` to 1e-9 n_B fails: dependent equalities).
 */
bool eliminate_rows(const FullMatrix<double> &W,
                    const std::vector<unsigned int> &b,
                    const std::vector<unsigned int> &c,
                    SchurElimination &e);

/** X and S of @p e from its Wbc and Wbb_inverse (rows @p c of @p W). */
void complete_elimination(const FullMatrix<double> &W,
                          const std::vector<unsigned int> &c,
                          SchurElimination &e);

/**
 * A cluster's equalities eliminated once (A5 with bilateral rows: ties,
 * rigid links): with B the bilateral rows and U the unilateral ones,
 *
 *   lambda_B = -W_BB^-1 (q_B + W_BU lambda_U),
 *   w_U = S lambda_U + q_S,  S = W_UU - W_UB W_BB^-1 W_BU,
 *                            q_S = q_U - W_UB W_BB^-1 q_B,
 *
 * and the LCP of the few unilateral rows alone. Formed on the first solve
 * with a W and kept while W is (the caller resets @p formed when W
 * changes). A cluster of the rails' ties with a trolley wheel on them
 * (dozens of equalities, one contact) took projected Gauss-Seidel hundreds
 * of sweeps a step.
 */
struct BilateralElimination
{
  bool formed = false;
  /** W_BB invertible to round-off: false keeps the plain solve. */
  bool invertible = false;
  std::vector<unsigned int> b, u;
  /** W_BU, W_BB^-1, X = W_BB^-1 W_BU and the Schur complement S. */
  SchurElimination schur;
  /** Work vectors of a solve: q_B, y = W_BB^-1 q_B, q_S, lambda_U. */
  Vector<double> q_b, y, q_s, lambda_u;
};

/**
 * solve_lcp() for a cluster with equalities through @p elimination where
 * the cluster is larger than the enumeration's 12 rows (there the plain
 * solve, bitwise): the equalities exactly instead of by projected
 * Gauss-Seidel, the unilateral rows' LCP by enumeration up to 12 of them.
 */
void solve_lcp(const FullMatrix<double> &W,
               const Vector<double> &q,
               const std::vector<bool> &bilateral,
               Vector<double> &lambda,
               BilateralElimination &elimination);

/**
 * The impulses of a prescribed active set, every row an equality:
 * `W lambda = -q` (W inverted by Gauss-Jordan), into @p lambda (resized to
 * the size of @p q). Used where a step must repeat a known active set (the
 * coupling's prescribed passes, A5, A9). Where W is singular (dependent
 * rows: a flange's lateral contact along a sticking wheel's tangent), the
 * minimum-norm solution (minimum_norm_solution()).
 */
/**
 * The minimum-norm solution of `W lambda = -q` for a symmetric positive
 * semi-definite @p W (by its singular value decomposition), into @p lambda.
 */
void minimum_norm_solution(const FullMatrix<double> &W,
                           const Vector<double> &q,
                           Vector<double> &lambda);

/**
 * `W lambda = -q` as equalities (a prescribed active set, the coupling's
 * ramp responses, G3'): by the Gauss-Jordan inverse of @p W, or, where that
 * is not finite (dependent rows), the minimum-norm solution. The inverse is
 * kept in @p W_inverse: computed when @p inverted is false (then set true),
 * reused otherwise (the caller resets @p inverted when W changes).
 */
void solve_equalities(const FullMatrix<double> &W,
                      FullMatrix<double> &W_inverse,
                      bool &inverted,
                      const Vector<double> &q,
                      Vector<double> &lambda);
} // namespace hati

#endif

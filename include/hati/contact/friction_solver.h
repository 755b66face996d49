#ifndef hati_contact_friction_solver_h
#define hati_contact_friction_solver_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace hati
{
using namespace dealii;

/** What a contact does in a step with friction (A9): open, sticking or sliding. */
enum class FrictionState : unsigned char
{
  open,
  stick,
  slip
};

/** The stopping rule of the nonsmooth Gauss-Seidel iteration (A9). */
struct FrictionSolverControl
{
  /**
   * Relative tolerance (-): a sweep converged when the sum over the
   * contacts of `|r_k - r_k,previous|` is at most this times the sum of
   * `|r_k|` (doc/theory.md A9).
   */
  double tolerance = 1e-10;
  /** Largest number of sweeps; a cluster that needs more is counted unconverged. */
  unsigned int max_sweeps = 1000;
};

/** How the solution of one cluster went. */
struct FrictionSolverResult
{
  /** Gauss-Seidel sweeps done (1 for a single contact). */
  unsigned int sweeps = 0;
  /**
   * False if the sweeps reached FrictionSolverControl::max_sweeps, or if a
   * local problem had no exact solution (the impulse is then the sticking
   * impulse projected on the cone).
   */
  bool converged = true;
};

/** What solve_local_coulomb() found: the state, and whether it is exact. */
struct LocalCoulombSolution
{
  FrictionState state = FrictionState::open;
  bool exact = true;
};

/**
 * The exact solution of the local problem of one contact (A9, doc/theory.md
 * A9): relative velocity `u = W r + q` with `W` its @p size x @p size
 * Delassus block (row-major in @p W, size 1 + number of tangents, at most
 * 3), row 0 the normal, the rest tangential; impulse @p r (N s) with
 * `0 <= u_n _|_ r_n >= 0` (for a @p bilateral row `u_n = 0`, r_n of either
 * sign) and Coulomb's law `||r_t|| <= mu |r_n|`, sticking `u_t = 0` or
 * sliding `r_t = -mu |r_n| u_t / ||u_t||`. Tried in that order: open
 * (`q_n >= 0`), sticking (`W r = -q` inside the cone), sliding (one tangent:
 * both directions in closed form; two: the sliding direction from Newton's
 * method on its angle, started from the fixed point `s = u_t / ||u_t||`,
 * which is exact at once for an isotropic block, then a scan of the angle
 * with bisection if Newton fails). Returns the state and whether the
 * solution is exact: when none was found, the sticking impulse projected on
 * the cone is returned in @p r, `exact` false.
 */
LocalCoulombSolution solve_local_coulomb(const double *W,
                                         const unsigned int size,
                                         const double *q,
                                         const double mu,
                                         const bool bilateral,
                                         double *r);

/**
 * The data of one cluster of contacts with friction (A9): the rows of
 * contact k are `first[k] .. first[k+1] - 1` of the Delassus matrix @p W
 * and of the free relative velocity @p q (normal first, then its tangents);
 * @p mu and @p bilateral per contact. References: the cluster owns nothing.
 */
struct FrictionalCluster
{
  const FullMatrix<double> &W;
  const Vector<double> &q;
  const std::vector<unsigned int> &first;
  const std::vector<double> &mu;
  const std::vector<bool> &bilateral;
};

/**
 * Nonsmooth Gauss-Seidel over the contacts of a @p cluster (A9). Each
 * sweep solves every contact's local problem exactly
 * (solve_local_coulomb()) with the impulses of the others as they are. The
 * impulses start from zero. A cluster of several blocks first tries the
 * all-sticking solution (every block's contact closed and sticking, its
 * flange partners open: one Cholesky solve), taken when it satisfies the
 * complementarity and Coulomb's law (one sweep counted). @p r receives the
 * impulses (N s, per row) and @p state the state of each contact.
 */
FrictionSolverResult solve_frictional_cluster(const FrictionalCluster &cluster,
                                              Vector<double> &r,
                                              std::vector<FrictionState> &state,
                                              const FrictionSolverControl &control = {});
} // namespace hati

#endif

#ifndef hati_contact_condensed_cluster_h
#define hati_contact_condensed_cluster_h

#include <hati/contact/friction_solver.h>
#include <hati/contact/lcp_solver.h>

namespace hati
{
/**
 * What solve_condensed_frictional_cluster() derives from the cluster's W, mu
 * and bilateral flags alone: the condensed rows B and the kept ones C (and
 * their contacts), `X = W_BB^-1`, `T = X W_BC`, the condensed Delassus
 * matrix `S = W_CC - W_CB T` and the condensed cluster's layout. A caller
 * that keeps a cluster's W from step to step keeps this with it, passed as
 * @p links below (`valid`: derived for that W; set it false when W
 * changes; nullptr: derived at every call).
 */
struct CondensedLinks
{
  bool valid = false;
  std::vector<unsigned int> rows_B, rows_C, kept, condensed;
  /** W_BB^-1, T = W_BB^-1 W_BC (its X) and S (eliminate_rows()). */
  SchurElimination schur;
  std::vector<unsigned int> first_S;
  std::vector<double> mu_S;
  std::vector<bool> bilateral_S;
};

/**
 * solve_frictional_cluster() with the cluster's frictionless bilateral rows
 * (rigid links, ties: equalities `u_b = 0` with an impulse of either sign)
 * condensed out first (A9, doc/theory.md A9 "Links in a frictional
 * cluster"). With `W = [W_BB W_BC; W_CB W_CC]` (B: those rows, C: the
 * contacts' rows), `r_B = -W_BB^-1 (q_B + W_BC r_C)` and the contacts solve
 *
 *   `u_C = (W_CC - W_CB W_BB^-1 W_BC) r_C + (q_C - W_CB W_BB^-1 q_B)`
 *
 * with their sign conditions and Coulomb's law, the same problem with the
 * equalities eliminated exactly. Gauss-Seidel on the whole cluster converged
 * slowly there: a wheel whose contact point is joined to its axis by rigid
 * links (true heights) took 29 sweeps on average, 276 at most, and the
 * friction solves cost about 30 s per second of earthquake on the braked
 * crane; condensed, a wheel is one local problem, exact in one sweep. A
 * singular `W_BB` (dependent links) takes its pseudo-inverse: the velocities
 * are those of any solution. Clusters without such rows, or with nothing
 * else, go to solve_frictional_cluster() as they are, and so does a
 * cluster whose condensed problem did not converge (a local problem
 * without an exact solution). The states of the
 * condensed rows are `slip` where their impulse is nonzero (as the
 * sweeps' local solution of a bilateral row), `open` otherwise.
 */
FrictionSolverResult
solve_condensed_frictional_cluster(const FrictionalCluster &cluster,
                                   Vector<double> &r,
                                   std::vector<FrictionState> &state,
                                   const FrictionSolverControl &control = {},
                                   CondensedLinks *links = nullptr);

} // namespace hati

#endif

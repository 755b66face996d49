#ifndef hati_analysis_settled_friction_h
#define hati_analysis_settled_friction_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/linear_algebra/direct_solver.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The settled static state of the sticking tangents (A9, doc/theory.md
 * 6.2): the brakes act on the structure as it stands under its static
 * load, so the sticking contacts carry only the tangential forces that
 * its mechanisms along them need, not the self-stress that holding every
 * tangent at zero slip would lock in (a braked trolley on a girder whose
 * top flange shortens as it bends).
 *
 * @p x solves the static saddle problem `A x = b` (`A = [K L^T; L 0]`, its
 * factorisation @p solver, @p n the DoFs, the multiplier of held row r at
 * `x[n + r]`), with the rows @p tangent_rows (indices of held rows)
 * sticking at zero slip. With `S = (A^-1)` on those rows (symmetric; its
 * null space the mechanisms the tangents hold, their participations), the
 * tangents' multipliers are split into their projection on the null space
 * (the forces the mechanisms need, kept) and the rest (self-stress), which
 * the slips `delta = -S^+ (rest)` relieve: `b` on the tangent rows gets
 * `delta` and `x` becomes `A^-1 b`. One back-substitution pass for all the tangent rows
 * (DirectSolver::solve_many()), one more for their refinement.
 */
void settle_sticking_tangents(const DirectSolver &solver,
                              const SparseMatrix<double> &A,
                              const unsigned int n,
                              const std::vector<unsigned int> &tangent_rows,
                              Vector<double> &x,
                              Vector<double> &b);
} // namespace hati

#endif

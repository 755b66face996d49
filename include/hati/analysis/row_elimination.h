#ifndef hati_analysis_row_elimination_h
#define hati_analysis_row_elimination_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>

#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Linear constraint rows `L_k U = 0` as a linear map `U = T q`
 * (doc/theory.md 7.3): Gaussian elimination row by row with partial
 * pivoting: the row, with the earlier slaves substituted, loses its largest
 * entry's DoF (the slave), which is then a combination of the remaining
 * DoFs; rows that vanish after the substitution (an opposite row of a
 * two-sided contact, dependent rows) are redundant. Fixed DoFs are zero and
 * drop out of the rows.
 *
 * Inhomogeneous rows `L_k U = g_k` (the boundary coordinates of a
 * Craig-Bampton reduction, doc/theory.md 12.1): give the row an entry -1 at
 * a virtual DoF `n + k` past the system's `n` DoFs and a pivot limit of
 * `n`; the virtual DoFs are never slaves, condense() leaves them out and
 * distribute() reads their values from a vector of `n` plus their number.
 */
struct RowElimination
{
  /** Per slave DoF: the masters and coefficients, `U_s = sum_j c_j U_j`. */
  std::map<unsigned int, std::vector<std::pair<unsigned int, double>>> slaves;
  /** Closed rows, independent ones and redundant ones. */
  unsigned int n_closed = 0, n_redundant = 0;

  RowElimination() = default;

  /**
   * The closed contacts of @p system: every zero-gap contact row with a
   * free DoF, and the tangent rows of the closed frictional ones (they
   * stick, A9).
   */
  explicit RowElimination(const DiscreteSystem &system);

  /**
   * Eliminate the constraint `row U = 0` (see the struct); @p count: a
   * contact row (n_closed, n_redundant), not a tangent row of friction;
   * DoFs at or past @p pivot_limit are never chosen as slaves.
   */
  void
  eliminate(const std::vector<bool> &fixed,
            const SparseRow &row,
            const bool count,
            const unsigned int pivot_limit = std::numeric_limits<unsigned int>::max());

  /**
   * `T^T A T` on the full numbering: rows and columns of slaves keep only
   * their diagonal entry @p slave_diagonal[s] (so that they act as fixed
   * DoFs), other entries collect the contributions of the slaves. An empty
   * @p pattern is built, a built one reused.
   */
  void condense(const SparseMatrix<double> &A,
                const std::vector<double> &slave_diagonal,
                SparsityPattern &pattern,
                SparseMatrix<double> &result) const;

  /** Back-substitution `U = T q`: the slaves from their masters. */
  void distribute(Vector<double> &phi) const;

  /** `y <- T^T y` on the real DoFs: the slaves' entries moved to their masters. */
  void transpose_apply(Vector<double> &y) const;
};
} // namespace hati

#endif

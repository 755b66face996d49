#ifndef hati_linear_algebra_low_rank_update_h
#define hati_linear_algebra_low_rank_update_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <functional>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Solves with a matrix `A = A_0 + P D P^T` that differs from a factorised
 * one, `A_0`, only on a few rows and columns S (`P`: the unit columns of S,
 * `D` the s x s difference there) through the Woodbury identity:
 * `A^-1 b = y - W (I + D C)^-1 D y_S` with `y = A_0^-1 b`, `W = A_0^-1 P`
 * (s back-substitutions once) and `C = P^T W`. The static state with
 * ropes (doc/theory.md 10.3) iterates Newton on the rope forces, whose
 * tangent changes only the rope ends' DoFs: one factorisation for every
 * iteration instead of one each.
 */
class LowRankUpdate
{
public:
  /** Keep a copy of @p A_0, the matrix just factorised (no update yet). */
  void set_base(const SparseMatrix<double> &A_0);

  /**
   * The rows where @p A differs from the base (ascending), if @p A has the
   * base's pattern and differs in at most @p limit rows; false otherwise.
   */
  bool differing_rows(const SparseMatrix<double> &A,
                      unsigned int limit,
                      std::vector<unsigned int> &rows) const;

  /**
   * Set up the update to @p A on the rows @p rows (differing_rows());
   * @p base_solve_many solves `A_0 X = B` in place for column-major blocks
   * (the base's factorisation). Returns false if `I + D C` is singular
   * (then `A` itself is).
   */
  bool update(const SparseMatrix<double> &A,
              const std::vector<unsigned int> &rows,
              const std::function<void(double *, unsigned int)> &base_solve_many);

  /** Drop the update: solves are the base's again. */
  void clear() { dofs.clear(); }

  /** Whether an update is set up (correct() changes solutions). */
  bool active() const { return !dofs.empty(); }

  /** x = A^-1 b from @p x = A_0^-1 b, in place (a vector of the matrix's size). */
  void correct(double *x) const;

private:
  SparsityPattern pattern;
  SparseMatrix<double> base;
  std::vector<unsigned int> dofs;
  std::vector<double> W;
  FullMatrix<double> D;
  LAPACKFullMatrix<double> capacitance;
};

} // namespace hati

#endif

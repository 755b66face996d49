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
 * A sparse matrix factorised once with Trilinos' Amesos_Klu, then any
 * number of forward/backward substitutions: the effective matrix of Newmark
 * (N2) and the columns `M_eff^-1 C_I^T` of the coupling (G3'), the mass of
 * the initial acceleration, the stiffness of the static analysis and the
 * shifted stiffness of the modal analysis all go through it.
 */
class DirectSolver
{
public:
  /** Not copyable: it owns its factorisation (a unique pointer). */
  DirectSolver();
  ~DirectSolver();

  /**
   * Copy @p matrix to Trilinos and factorise it. Throws ExcMessage with
   * @p failure_message if Amesos_Klu finds a zero pivot (a singular matrix).
   */
  void factorize(const SparseMatrix<double> &matrix, const std::string &failure_message);

  /** x = A^-1 b; @p x and @p b may be the same vector. */
  void solve(Vector<double> &x, const Vector<double> &b) const;

  /** Whether factorize() succeeded. */
  bool initialized() const;

  /** Wall time of the last factorize() (s). */
  double factorization_time() const { return seconds; }

private:
  struct Data;
  std::unique_ptr<Data> data;
  std::string failure;
  double seconds = 0.;
};
} // namespace hati

#endif

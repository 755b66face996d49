#ifndef hati_linear_algebra_symmetric_mumps_h
#define hati_linear_algebra_symmetric_mumps_h

#include <deal.II/lac/sparse_matrix.h>

#include <memory>
#include <vector>

namespace hati
{
using namespace dealii;

/** Relative mismatch of `a_ij` and `a_ji` that is_symmetric() accepts (-). */
constexpr double symmetry_tolerance = 1e-12;

/**
 * Whether @p matrix is symmetric: every pair of entries `a_ij`, `a_ji`
 * agrees to symmetry_tolerance of the largest entry of rows i and j (an
 * entry missing from the pattern counts as zero). The matrices that hati factorises (the
 * Newmark effective matrix of N2, the static saddle matrix, the shifted stiffness of the
 * modal analysis, the condensed stiffness of C1) are symmetric; this checks
 * it before the symmetric factorisation of SymmetricMumps.
 */
bool is_symmetric(const SparseMatrix<double> &matrix);

/**
 * A symmetric (possibly indefinite) sparse matrix factorised `L D L^T` by
 * MUMPS directly (`sym = 2`, on `MPI_COMM_SELF`), then any number of
 * forward/backward substitutions, one or many right-hand sides at once.
 *
 * Why not through Amesos: Trilinos 13.2's Amesos_Mumps always asks MUMPS
 * for an unsymmetric `L U` (its `MDS.sym = 0`, Amesos bug 2331), twice the
 * factorisation's work and memory of `L D L^T`, twice the factor that every
 * substitution reads; and it solves a multi-vector one column at a time.
 * Only the upper triangle of the matrix is handed over (MUMPS sums the two
 * triangles' entries otherwise).
 */
class SymmetricMumps
{
public:
  SymmetricMumps();
  ~SymmetricMumps();
  SymmetricMumps(const SymmetricMumps &) = delete;
  SymmetricMumps &operator=(const SymmetricMumps &) = delete;

  /**
   * Analyse and factorise @p matrix (symmetric: is_symmetric()). Returns
   * false if MUMPS fails (a singular matrix: a zero pivot), true otherwise.
   */
  bool factorize(const SparseMatrix<double> &matrix);

  /**
   * Solve in place: @p columns holds @p n_rhs right-hand sides of the
   * matrix's size one after another (column-major) and gets the solutions.
   * Returns false if MUMPS reports an error.
   */
  bool solve(double *columns, unsigned int n_rhs) const;

  /** The size of the factorised matrix. */
  unsigned int size() const { return n; }

  /** MUMPS's INFOG(1) and INFOG(2) of the last call (0: no error). */
  int error() const { return infog[0]; }
  long error_detail() const { return infog[1]; }

  /**
   * Whether MUMPS's INFOG(1) @p error says memory, not the matrix: an
   * allocation that failed (-7, -13, -19) or a workspace still too small
   * after factorize() doubled it four times (-8, -9, -11, -14, -15, -17,
   * -20).
   */
  static bool memory_error(const int error);

  /**
   * The number of negative pivots of the last factorisation (MUMPS's
   * INFOG(12) for a symmetric matrix): by Sylvester's law of inertia the
   * number of negative eigenvalues of the matrix, so that for `K - sigma M`
   * (M positive semi-definite) it counts the eigenvalues of `K phi = lambda
   * M phi` below sigma (RS5, doc/theory.md 14.5).
   */
  long negative_pivots() const { return n_negative; }

private:
  struct Data;
  std::unique_ptr<Data> data;
  unsigned int n = 0;
  int infog[2] = {0, 0};
  long n_negative = 0;
};

} // namespace hati

#endif

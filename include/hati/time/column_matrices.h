#ifndef hati_time_column_matrices_h
#define hati_time_column_matrices_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Columns of a sparse matrix (the explicit response to a unit interface
 * ramp, G3'): only the entries the response reaches are stored.
 */
class SparseColumns
{
public:
  /** Append the column @p v (its nonzero entries). */
  void add_column(const Vector<double> &v);
  /** The nonzero entries of @p matrix, column by column. */
  explicit SparseColumns(const FullMatrix<double> &matrix);
  SparseColumns() = default;
  /** y += sum_k column_k x_k. */
  void add_multiply(Vector<double> &y, const Vector<double> &x) const;
  /** y = sum_k column_k x_k (@p y keeps its size). */
  void vmult(Vector<double> &y, const Vector<double> &x) const
  {
    y = 0.;
    add_multiply(y, x);
  }
  /** g_k += column_k . c for every column k (@p c: as many entries as rows). */
  void Tvmult_add(Vector<double> &g, const double *c) const;
  /** Rows with an entry in any column. */
  std::vector<unsigned int> rows() const;

private:
  std::vector<std::size_t> start{0};
  std::vector<unsigned int> row;
  std::vector<double> value;
};

/**
 * A small dense matrix stored column by column, the product taking four
 * columns per pass over the result (the coupling's dense operators: the
 * link columns M_eff^-1 C_I^T, H_I and H^-1 of G3'-G4, applied once or
 * twice per macro step).
 */
class DenseColumns
{
public:
  /** An @p m x @p n matrix of zeros. */
  void reinit(const unsigned int m, const unsigned int n)
  {
    n_rows = m;
    n_columns = n;
    value.assign(std::size_t(m) * n, 0.);
    drop_skip_lists();
  }
  /** Whether the matrix has no entries (never set up, or 0 rows or columns). */
  bool has_no_entries() const { return value.empty(); }
  /** A_ij = @p a (drops the lists of skip_zero_rows()). */
  void set(const unsigned int i, const unsigned int j, const double a)
  {
    drop_skip_lists();
    value[std::size_t(j) * n_rows + i] = a;
  }
  /** A_ij += @p a (drops the lists of skip_zero_rows()). */
  void add(const unsigned int i, const unsigned int j, const double a)
  {
    drop_skip_lists();
    value[std::size_t(j) * n_rows + i] += a;
  }
  double operator()(const unsigned int i, const unsigned int j) const
  {
    return value[std::size_t(j) * n_rows + i];
  }
  /** y = A x (@p y keeps its size, m entries). */
  void vmult(Vector<double> &y, const Vector<double> &x) const;
  /**
   * Once the entries are set: for each pass of vmult() (four columns, or
   * one of the last n mod 4), the ranges of rows where one of its columns
   * has a nonzero (zero gaps under 8 rows inside), so that the passes skip
   * the others (the link columns of an
   * implicit part in several pieces are zero off the piece of their
   * interface DoF). The results are bitwise those of the full passes: a
   * skipped row would add an exact zero. Setting an entry afterwards
   * drops the lists.
   */
  void skip_zero_rows();

private:
  void drop_skip_lists()
  {
    pass_start.clear();
    pass_range.clear();
  }
  unsigned int n_rows = 0, n_columns = 0;
  std::vector<double> value;
  // per pass of vmult(): the row ranges [begin, end) it visits,
  // [pass_start[p], pass_start[p + 1]) in pass_range; empty: every row
  std::vector<std::size_t> pass_start;
  std::vector<std::pair<unsigned int, unsigned int>> pass_range;
};
} // namespace hati

#endif

#ifndef hati_time_quadratic_form_h
#define hati_time_quadratic_form_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

namespace hati
{
using namespace dealii;

/**
 * Rows below which quadratic_form() sums serially: deal.II 9.4's
 * `SparseMatrix::matrix_norm_square()` goes through TBB's parallel reduction
 * whatever the size, which on the beam crane's 170 to 480 DoFs cost more
 * than the sum (about 5 % of the main example, in its energy rows).
 */
constexpr unsigned int serial_quadratic_form_rows = 20000;

/**
 * `x^T A x` for the energies (E1, A8) at output rows: below
 * serial_quadratic_form_rows rows one serial pass, row by row, summing
 * each row in storage order as one subrange of deal.II's does; above, deal.II's
 * `matrix_norm_square()` (parallel).
 */
inline double quadratic_form(const SparseMatrix<double> &A, const Vector<double> &x)
{
  if (A.m() >= serial_quadratic_form_rows)
    return A.matrix_norm_square(x);
  double sum = 0.;
  for (unsigned int row = 0; row < A.m(); ++row)
  {
    double s = 0.;
    for (auto it = A.begin(row); it != A.end(row); ++it)
      s += it->value() * x[it->column()];
    sum += x[row] * s;
  }
  return sum;
}
} // namespace hati

#endif

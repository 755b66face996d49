// DenseColumns (source/time/column_matrices.cc): the product y = A x of the
// coupling's dense operators (the link columns M_eff^-1 C_I^T of G4, H_I,
// H^-1 of G3'). References: the same product summed by hand in double
// precision (1e-15 of the largest |y|); and skip_zero_rows(), which only
// skips rows where a pass of four columns (or one of the last n mod 4)
// is zero, against the full passes bitwise (tolerance 0).
#include "test_tools.h"

#include <hati/time/column_matrices.h>

#include <algorithm>
#include <cmath>

namespace hati_unit_column_matrices
{

using namespace hati;
using namespace hati_test;

/** A deterministic value in [-1, 1] that is never zero. */
double value_of(const unsigned int i, const unsigned int j)
{
  const double v = std::sin(1.3 * i + 0.7 * j + 0.1);
  return std::abs(v) < 1e-3 ? 0.5 : v;
}

/**
 * An m x n matrix in two pieces, like the link columns of an implicit part
 * in two parts: columns below @p split act on the rows below @p row_split
 * only, the others on the rows from it.
 */
DenseColumns two_pieces(const unsigned int m,
                        const unsigned int n,
                        const unsigned int row_split,
                        const unsigned int split)
{
  DenseColumns A;
  A.reinit(m, n);
  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < m; ++i)
      if ((j < split) == (i < row_split))
        A.set(i, j, value_of(i, j));
  return A;
}

HATI_UNIT_TEST(column_matrices)
{
  const unsigned int m = 37, n = 11; // two passes of four columns and three single ones
  Vector<double> x(n);
  for (unsigned int j = 0; j < n; ++j)
    x[j] = value_of(j, 100) * (j + 1);

  for (const unsigned int split : {4u, 8u, 5u})
  {
    const std::string what = "split after column " + std::to_string(split) + ": ";
    DenseColumns A = two_pieces(m, n, 20, split);
    Vector<double> full(m), skipped(m);
    A.vmult(full, x);
    // the hand product
    double largest = 0., error = 0.;
    for (unsigned int i = 0; i < m; ++i)
    {
      double y = 0.;
      for (unsigned int j = 0; j < n; ++j)
        y += A(i, j) * x[j];
      largest = std::max(largest, std::abs(y));
      error = std::max(error, std::abs(y - full[i]));
    }
    check(what + "A x against the hand product", error, 0., 1e-15 * largest);
    // the passes over the nonzero rows only: bitwise the full product
    A.skip_zero_rows();
    A.vmult(skipped, x);
    double difference = 0.;
    for (unsigned int i = 0; i < m; ++i)
      difference = std::max(difference, std::abs(skipped[i] - full[i]));
    check(what + "skipping the zero rows changes no bit", difference, 0., 0.);
    // an entry set afterwards (row 0, last column: zero in both pieces'
    // layout) drops the lists: the product sees it
    A.set(0, n - 1, 2.);
    A.vmult(skipped, x);
    const double expected = full[0] + 2. * x[n - 1];
    check(what + "an entry set after skip_zero_rows() counts",
          skipped[0],
          expected,
          1e-14 * largest);
  }

  // a matrix without zeros keeps its full passes (nothing to skip)
  DenseColumns B;
  B.reinit(9, 6);
  for (unsigned int j = 0; j < 6; ++j)
    for (unsigned int i = 0; i < 9; ++i)
      B.set(i, j, value_of(i, j));
  Vector<double> y0(9), y1(9), x6(6);
  for (unsigned int j = 0; j < 6; ++j)
    x6[j] = 1. + j;
  B.vmult(y0, x6);
  B.skip_zero_rows();
  B.vmult(y1, x6);
  double difference = 0.;
  for (unsigned int i = 0; i < 9; ++i)
    difference = std::max(difference, std::abs(y1[i] - y0[i]));
  check("dense matrix: the same product after skip_zero_rows()", difference, 0., 0.);
  return finish();
}

} // namespace hati_unit_column_matrices

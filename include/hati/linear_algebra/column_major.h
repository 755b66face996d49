#ifndef hati_linear_algebra_column_major_h
#define hati_linear_algebra_column_major_h

#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/lapack_templates.h>

#include <cstddef>

// Products with dense column-major matrices stored in std::vector<double>
// (a reduction basis, deflated modes) through BLAS: one pass of the matrix
// through memory.

namespace hati
{
/**
 * `y = alpha op(A) x + beta y` for the column-major @p rows x @p columns
 * matrix @p A, op(A) = A or A^T (BLAS dgemv).
 */
inline void column_major_vmult(const bool transpose,
                               const std::size_t rows,
                               const std::size_t columns,
                               const double alpha,
                               const double *A,
                               const double *x,
                               const double beta,
                               double *y)
{
  const dealii::types::blas_int m = rows, n = columns, one = 1;
  dealii::gemv(transpose ? "T" : "N", &m, &n, &alpha, A, &m, x, &one, &beta, y, &one);
}

/**
 * `C = op(A) B` with op(A) = A (@p rows x @p inner) or A^T (A @p inner x
 * @p rows), B @p inner x @p columns, C @p rows x @p columns, all
 * column-major and contiguous (BLAS dgemm).
 */
inline void column_major_mmult(const bool transpose_a,
                               const std::size_t rows,
                               const std::size_t columns,
                               const std::size_t inner,
                               const double *A,
                               const double *B,
                               double *C)
{
  const dealii::types::blas_int m = rows, n = columns, k = inner;
  const dealii::types::blas_int lda = transpose_a ? k : m;
  const double alpha = 1., beta = 0.;
  dealii::gemm(
      transpose_a ? "T" : "N", "N", &m, &n, &k, &alpha, A, &lda, B, &k, &beta, C, &m);
}
} // namespace hati

#endif

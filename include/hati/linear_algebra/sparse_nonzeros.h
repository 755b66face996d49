#ifndef hati_linear_algebra_sparse_nonzeros_h
#define hati_linear_algebra_sparse_nonzeros_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

namespace hati
{
using namespace dealii;

/**
 * @p B (on @p pattern) = @p A without its zero entries (the diagonal is
 * kept). A consistent mass is stored on the stiffness pattern, whose
 * entries between different displacement components are all zero for a
 * solid (two thirds of them): a product with the copy reads a third of the
 * entries. Its products equal @p A's bitwise (the same nonzero terms, in
 * the same order).
 */
void copy_nonzeros(const SparseMatrix<double> &A,
                   SparsityPattern &pattern,
                   SparseMatrix<double> &B);

} // namespace hati

#endif

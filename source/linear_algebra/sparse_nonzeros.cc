#include <hati/linear_algebra/sparse_nonzeros.h>

#include <vector>

namespace hati
{
void copy_nonzeros(const SparseMatrix<double> &A,
                   SparsityPattern &pattern,
                   SparseMatrix<double> &B)
{
  const unsigned int m = A.m();
  std::vector<unsigned int> row_lengths(m, 0);
  for (unsigned int i = 0; i < m; ++i)
    for (auto it = A.begin(i); it != A.end(i); ++it)
      if (it->value() != 0. || it->column() == i)
        ++row_lengths[i];
  pattern.reinit(m, A.n(), row_lengths);
  for (unsigned int i = 0; i < m; ++i)
    for (auto it = A.begin(i); it != A.end(i); ++it)
      if (it->value() != 0. || it->column() == i)
        pattern.add(i, it->column());
  pattern.compress();
  B.reinit(pattern);
  for (unsigned int i = 0; i < m; ++i)
    for (auto it = A.begin(i); it != A.end(i); ++it)
      if (it->value() != 0.)
        B.set(i, it->column(), it->value());
}
} // namespace hati

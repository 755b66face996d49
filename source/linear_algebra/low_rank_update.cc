// Solves with a low-rank update of a factorised matrix (Woodbury identity).

#include <deal.II/lac/vector.h>

#include <hati/linear_algebra/low_rank_update.h>

#include <algorithm>

namespace hati
{
void LowRankUpdate::set_base(const SparseMatrix<double> &A_0)
{
  dofs.clear();
  base.clear();
  pattern.copy_from(A_0.get_sparsity_pattern());
  base.reinit(pattern);
  base.copy_from(A_0);
}

bool LowRankUpdate::differing_rows(const SparseMatrix<double> &A,
                                   const unsigned int limit,
                                   std::vector<unsigned int> &rows) const
{
  rows.clear();
  std::vector<unsigned int> columns;
  const SparsityPattern &p = A.get_sparsity_pattern();
  if (base.m() == 0 || p.n_rows() != pattern.n_rows() || p.n_cols() != pattern.n_cols() ||
      p.n_nonzero_elements() != pattern.n_nonzero_elements())
    return false;
  for (unsigned int i = 0; i < A.m(); ++i)
  {
    if (p.row_length(i) != pattern.row_length(i))
      return false;
    bool differs = false;
    for (auto a = A.begin(i), b = base.begin(i); a != A.end(i); ++a, ++b)
    {
      if (a->column() != b->column())
        return false;
      if (a->value() != b->value())
      {
        differs = true;
        columns.push_back(a->column());
      }
    }
    if (differs)
    {
      rows.push_back(i);
      if (rows.size() > limit)
        return false;
    }
  }
  // the rows and columns of the differing entries (the same for a symmetric update)
  rows.insert(rows.end(), columns.begin(), columns.end());
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows.size() <= limit;
}

bool LowRankUpdate::update(
    const SparseMatrix<double> &A,
    const std::vector<unsigned int> &rows,
    const std::function<void(double *, unsigned int)> &base_solve_many)
{
  const std::size_t N = A.m(), s = rows.size();
  dofs = rows;
  if (s == 0)
    return true;
  W.assign(N * s, 0.);
  for (std::size_t k = 0; k < s; ++k)
    W[k * N + dofs[k]] = 1.;
  base_solve_many(W.data(), s);
  // D = (A - A_0) on S x S (symmetric rows: the columns of S are its rows)
  D.reinit(s, s);
  for (std::size_t a = 0; a < s; ++a)
    for (std::size_t b = 0; b < s; ++b)
      D(a, b) = A.el(dofs[a], dofs[b]) - base.el(dofs[a], dofs[b]);
  // I + D C, C = P^T W
  capacitance.reinit(s, s);
  for (std::size_t a = 0; a < s; ++a)
    for (std::size_t b = 0; b < s; ++b)
    {
      double sum = a == b ? 1. : 0.;
      for (std::size_t c = 0; c < s; ++c)
        sum += D(a, c) * W[b * N + dofs[c]];
      capacitance(a, b) = sum;
    }
  try
  {
    capacitance.compute_lu_factorization();
  }
  catch (const std::exception &)
  {
    dofs.clear();
    return false;
  }
  return true;
}

void LowRankUpdate::correct(double *x) const
{
  const std::size_t N = base.m(), s = dofs.size();
  if (s == 0)
    return;
  // z = (I + D C)^-1 D y_S, x = y - W z
  Vector<double> z(s);
  for (std::size_t a = 0; a < s; ++a)
    for (std::size_t c = 0; c < s; ++c)
      z[a] += D(a, c) * x[dofs[c]];
  capacitance.solve(z);
  for (std::size_t k = 0; k < s; ++k)
    for (std::size_t i = 0; i < N; ++i)
      x[i] -= W[k * N + i] * z[k];
}
} // namespace hati

#ifndef hati_contact_sparse_rows_h
#define hati_contact_sparse_rows_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * One sparse row of a constraint operator acting on a DoF vector: a row
 * `L_k` of the contact operator (A4-A5) or a row of the signed Boolean
 * interface operators `C_E`, `C_I` of the coupling (G2-G4). Both kinds go
 * through the same three operations: `L_k x`, `x += s L_k^T lambda_k` and
 * the Delassus matrix `L M^-1 L^T` of a set of rows.
 */
struct SparseRow
{
  std::vector<types::global_dof_index> dofs;
  std::vector<double> coefficients;

  /** L_k . x for a vector x. */
  double apply(const Vector<double> &x) const
  {
    return apply(ArrayView<const double>(x.begin(), x.size()));
  }

  /** L_k . x for the values @p x of a vector (e.g. a column of a basis). */
  double apply(const ArrayView<const double> &x) const
  {
    double s = 0.;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      s += coefficients[i] * x[dofs[i]];
    return s;
  }

  /** x += lambda * diag(scale) L_k^T, e.g. a velocity jump M^-1 L^T lambda. */
  void
  add_transpose(const double lambda, const Vector<double> &scale, Vector<double> &x) const
  {
    for (unsigned int i = 0; i < dofs.size(); ++i)
      x[dofs[i]] += scale[dofs[i]] * coefficients[i] * lambda;
  }
};

namespace internal
{
/**
 * The positions of the entries of @p row sorted by (DoF, position): the
 * entries on one DoF are consecutive, in the order they have in the row.
 */
template <class Row> void sort_by_dof(const Row &row, std::vector<unsigned int> &order)
{
  order.resize(row.dofs.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(),
                   order.end(),
                   [&](const unsigned int i, const unsigned int j)
                   { return row.dofs[i] < row.dofs[j]; });
}
} // namespace internal

/**
 * The Delassus matrix `W = L M^-1 L^T` of the rows @p rows (A5), with
 * @p inverse_mass the diagonal of `M^-1` (0 on fixed DoFs): `W_ab` sums
 * `c_a c_b / m` over the DoFs the two rows share.
 *
 * The sum of each `W_ab` is the one of the double loop over the entries of
 * the two rows, `for i in a: for j in b: if dof_i == dof_j: w += c_i c_j /
 * m`: its terms are added in that order (i, then j), so the result does not
 * depend on how the matching entries are found. A row longer than
 * `short_row` entries (the bilateral rows of a tie, one entry per face DoF)
 * is looked up through its entries sorted by DoF (a binary search per entry
 * of the other row, the matches of one DoF in increasing position): the
 * cost of a pair is `len_a log len_b` instead of `len_a len_b`
 * (doc/theory.md 11.2). The short rows of point contacts keep the double
 * loop.
 */
template <class Row>
void delassus(const std::vector<const Row *> &rows,
              const Vector<double> &inverse_mass,
              FullMatrix<double> &W)
{
  constexpr unsigned int short_row = 8;
  const unsigned int m = rows.size();
  if (W.m() != m || W.n() != m)
    W.reinit(m, m);
  // order[b]: row b's positions sorted by DoF, for its long rows only
  // (work space reused from call to call: the contacts call this every step)
  thread_local std::vector<std::vector<unsigned int>> order;
  if (order.size() < m)
    order.resize(m);
  for (unsigned int b = 0; b < m; ++b)
  {
    order[b].clear();
    if (rows[b]->dofs.size() > short_row)
      internal::sort_by_dof(*rows[b], order[b]);
  }
  for (unsigned int a = 0; a < m; ++a)
    for (unsigned int b = 0; b < m; ++b)
    {
      const Row &ra = *rows[a], &rb = *rows[b];
      double w = 0.;
      if (order[b].empty())
      {
        for (unsigned int i = 0; i < ra.dofs.size(); ++i)
          for (unsigned int j = 0; j < rb.dofs.size(); ++j)
            if (ra.dofs[i] == rb.dofs[j])
              w += ra.coefficients[i] * rb.coefficients[j] * inverse_mass[ra.dofs[i]];
      }
      else
      {
        const std::vector<unsigned int> &ob = order[b];
        for (unsigned int i = 0; i < ra.dofs.size(); ++i)
        {
          const types::global_dof_index d = ra.dofs[i];
          auto p =
              std::lower_bound(ob.begin(),
                               ob.end(),
                               d,
                               [&](const unsigned int j, const types::global_dof_index e)
                               { return rb.dofs[j] < e; });
          // the entries of row b on DoF d, in increasing position j
          for (; p != ob.end() && rb.dofs[*p] == d; ++p)
            w += ra.coefficients[i] * rb.coefficients[*p] * inverse_mass[d];
        }
      }
      W(a, b) = w;
    }
}

/** The Delassus matrix of @p rows as a new matrix (see above). */
template <class Row>
FullMatrix<double> delassus(const std::vector<const Row *> &rows,
                            const Vector<double> &inverse_mass)
{
  FullMatrix<double> W;
  delassus(rows, inverse_mass, W);
  return W;
}
} // namespace hati

#endif

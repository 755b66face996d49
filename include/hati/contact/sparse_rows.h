#ifndef hati_contact_sparse_rows_h
#define hati_contact_sparse_rows_h

#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

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

/**
 * The Delassus matrix `W = L M^-1 L^T` of the rows @p rows (A5), with
 * @p inverse_mass the diagonal of `M^-1` (0 on fixed DoFs): `W_ab` sums
 * `c_a c_b / m` over the DoFs the two rows share.
 */
template <class Row>
void delassus(const std::vector<const Row *> &rows,
              const Vector<double> &inverse_mass,
              FullMatrix<double> &W)
{
  const unsigned int m = rows.size();
  if (W.m() != m || W.n() != m)
    W.reinit(m, m);
  for (unsigned int a = 0; a < m; ++a)
    for (unsigned int b = 0; b < m; ++b)
    {
      double w = 0.;
      for (unsigned int i = 0; i < rows[a]->dofs.size(); ++i)
        for (unsigned int j = 0; j < rows[b]->dofs.size(); ++j)
          if (rows[a]->dofs[i] == rows[b]->dofs[j])
            w += rows[a]->coefficients[i] * rows[b]->coefficients[j] *
                 inverse_mass[rows[a]->dofs[i]];
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

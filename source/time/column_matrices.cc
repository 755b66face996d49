#include <deal.II/base/exceptions.h>

#include <hati/time/column_matrices.h>

#include <algorithm>

namespace hati
{
void SparseColumns::add_column(const Vector<double> &v)
{
  for (unsigned int i = 0; i < v.size(); ++i)
    if (v[i] != 0.)
    {
      row.push_back(i);
      value.push_back(v[i]);
    }
  start.push_back(row.size());
}

SparseColumns::SparseColumns(const FullMatrix<double> &matrix)
{
  for (unsigned int k = 0; k < matrix.n(); ++k)
  {
    for (unsigned int i = 0; i < matrix.m(); ++i)
      if (matrix(i, k) != 0.)
      {
        row.push_back(i);
        value.push_back(matrix(i, k));
      }
    start.push_back(row.size());
  }
}

void SparseColumns::add_multiply(Vector<double> &y, const Vector<double> &x) const
{
  for (unsigned int k = 0; k + 1 < start.size(); ++k)
    if (x[k] != 0.)
      for (std::size_t e = start[k]; e < start[k + 1]; ++e)
        y[row[e]] += value[e] * x[k];
}

void DenseColumns::vmult(Vector<double> &y, const Vector<double> &x) const
{
  AssertDimension(y.size(), n_rows);
  AssertDimension(x.size(), n_columns);
  double *__restrict a = y.data();
  std::fill(a, a + n_rows, 0.);
  const double *const columns = value.data();
  const bool lists = !pass_start.empty();
  unsigned int l = 0, pass = 0;
  for (; l + 4 <= n_columns; l += 4, ++pass)
  {
    const double x0 = x[l], x1 = x[l + 1], x2 = x[l + 2], x3 = x[l + 3];
    const double *__restrict c0 = columns + std::size_t(l) * n_rows,
                             *__restrict c1 = c0 + n_rows, *__restrict c2 = c1 + n_rows,
                             *__restrict c3 = c2 + n_rows;
    if (lists)
      for (std::size_t e = pass_start[pass]; e < pass_start[pass + 1]; ++e)
      {
        const unsigned int i = pass_row[e];
        a[i] += c0[i] * x0 + c1[i] * x1 + c2[i] * x2 + c3[i] * x3;
      }
    else
      for (unsigned int i = 0; i < n_rows; ++i)
        a[i] += c0[i] * x0 + c1[i] * x1 + c2[i] * x2 + c3[i] * x3;
  }
  for (; l < n_columns; ++l, ++pass)
  {
    const double xl = x[l];
    const double *__restrict column = columns + std::size_t(l) * n_rows;
    if (lists)
      for (std::size_t e = pass_start[pass]; e < pass_start[pass + 1]; ++e)
        a[pass_row[e]] += column[pass_row[e]] * xl;
    else
      for (unsigned int i = 0; i < n_rows; ++i)
        a[i] += column[i] * xl;
  }
}

void DenseColumns::skip_zero_rows()
{
  pass_start.assign(1, 0);
  pass_row.clear();
  for (unsigned int l = 0; l < n_columns;)
  {
    const unsigned int width = l + 4 <= n_columns ? 4 : 1;
    for (unsigned int i = 0; i < n_rows; ++i)
      for (unsigned int c = l; c < l + width; ++c)
        if (value[std::size_t(c) * n_rows + i] != 0.)
        {
          pass_row.push_back(i);
          break;
        }
    pass_start.push_back(pass_row.size());
    l += width;
  }
  // the indexed passes pay off where they skip a quarter of the rows
  if (4 * pass_row.size() > 3 * std::size_t(n_rows) * (pass_start.size() - 1))
  {
    pass_start.clear();
    pass_row.clear();
  }
}

void SparseColumns::Tvmult_add(Vector<double> &g, const double *c) const
{
  for (unsigned int k = 0; k + 1 < start.size(); ++k)
  {
    double s = 0.;
    for (std::size_t e = start[k]; e < start[k + 1]; ++e)
      s += value[e] * c[row[e]];
    g[k] += s;
  }
}

std::vector<unsigned int> SparseColumns::rows() const
{
  std::vector<unsigned int> r(row);
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}
} // namespace hati

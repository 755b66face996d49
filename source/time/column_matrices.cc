#include <deal.II/base/exceptions.h>

#include <hati/base/cpu_clones.h>
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

HATI_AVX2_CLONES void DenseColumns::vmult(Vector<double> &y,
                                          const Vector<double> &x) const
{
  AssertDimension(y.size(), n_rows);
  AssertDimension(x.size(), n_columns);
  double *__restrict a = y.data();
  std::fill(a, a + n_rows, 0.);
  const double *const columns = value.data();
  // the row ranges of each pass (every row without skip_zero_rows())
  const bool ranges = !pass_start.empty();
  const std::pair<unsigned int, unsigned int> all_rows(0, n_rows);
  unsigned int l = 0, pass = 0;
  for (; l + 4 <= n_columns; l += 4, ++pass)
  {
    const double x0 = x[l], x1 = x[l + 1], x2 = x[l + 2], x3 = x[l + 3];
    const double *__restrict c0 = columns + std::size_t(l) * n_rows,
                             *__restrict c1 = c0 + n_rows, *__restrict c2 = c1 + n_rows,
                             *__restrict c3 = c2 + n_rows;
    const std::size_t n_ranges = ranges ? pass_start[pass + 1] - pass_start[pass] : 1;
    for (std::size_t r = 0; r < n_ranges; ++r)
    {
      const auto &[begin, end] = ranges ? pass_range[pass_start[pass] + r] : all_rows;
      for (unsigned int i = begin; i < end; ++i)
        a[i] += c0[i] * x0 + c1[i] * x1 + c2[i] * x2 + c3[i] * x3;
    }
  }
  for (; l < n_columns; ++l, ++pass)
  {
    const double xl = x[l];
    const double *__restrict column = columns + std::size_t(l) * n_rows;
    const std::size_t n_ranges = ranges ? pass_start[pass + 1] - pass_start[pass] : 1;
    for (std::size_t r = 0; r < n_ranges; ++r)
    {
      const auto &[begin, end] = ranges ? pass_range[pass_start[pass] + r] : all_rows;
      for (unsigned int i = begin; i < end; ++i)
        a[i] += column[i] * xl;
    }
  }
}

void DenseColumns::skip_zero_rows()
{
  // zero gaps shorter than this stay inside a range (they add exact zeros)
  const unsigned int shortest_gap = 8;
  pass_start.assign(1, 0);
  pass_range.clear();
  std::size_t visited = 0;
  for (unsigned int l = 0; l < n_columns;)
  {
    const unsigned int width = l + 4 <= n_columns ? 4 : 1;
    const std::size_t first = pass_range.size();
    for (unsigned int i = 0; i < n_rows; ++i)
    {
      bool nonzero = false;
      for (unsigned int c = l; c < l + width && !nonzero; ++c)
        nonzero = value[std::size_t(c) * n_rows + i] != 0.;
      if (!nonzero)
        continue;
      if (pass_range.size() > first && i < pass_range.back().second + shortest_gap)
        pass_range.back().second = i + 1;
      else
        pass_range.emplace_back(i, i + 1);
    }
    for (std::size_t r = first; r < pass_range.size(); ++r)
      visited += pass_range[r].second - pass_range[r].first;
    pass_start.push_back(pass_range.size());
    l += width;
  }
  // the ranges pay off where they skip a quarter of the rows
  if (4 * visited > 3 * std::size_t(n_rows) * (pass_start.size() - 1))
  {
    pass_start.clear();
    pass_range.clear();
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

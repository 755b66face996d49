// Elimination of linear constraint rows `L U = g` (doc/theory.md 7.3 and 12.1).

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hati/analysis/row_elimination.h>

#include <cmath>

namespace hati
{
RowElimination::RowElimination(const DiscreteSystem &system)
{
  for (const ContactRow &row : system.contacts)
  {
    if (row.initial_gap != 0.)
      continue; // open: a contact with a positive gap does not act on small vibrations
    eliminate(system.fixed, row, true);
    // a closed contact with friction sticks: it also holds its tangent
    // directions (A9, doc/theory.md A9), not a rolling axis
    if (row.frictional())
      for (const SparseRow &tangent : row.tangents)
        eliminate(system.fixed, tangent, false);
  }
}

void RowElimination::eliminate(const std::vector<bool> &fixed,
                               const SparseRow &row,
                               const bool count,
                               const unsigned int pivot_limit)
{
  {
    std::map<unsigned int, double> a;
    double scale = 0.;
    for (unsigned int j = 0; j < row.dofs.size(); ++j)
    {
      const unsigned int dof = row.dofs[j];
      const double c = row.coefficients[j];
      if ((dof < fixed.size() && fixed[dof]) || c == 0.)
        continue;
      scale = std::max(scale, std::abs(c));
      const auto slave = slaves.find(dof);
      if (slave == slaves.end())
        a[dof] += c;
      else
        for (const auto &[master, cm] : slave->second)
          a[master] += c * cm;
    }
    if (scale == 0.)
      return; // only fixed DoFs: nothing to hold
    n_closed += count ? 1 : 0;
    unsigned int pivot = numbers::invalid_unsigned_int;
    double largest = 0.;
    for (const auto &[dof, c] : a)
      if (dof < pivot_limit && std::abs(c) > 1e-12 * scale && std::abs(c) > largest)
      {
        largest = std::abs(c);
        pivot = dof;
      }
    if (pivot == numbers::invalid_unsigned_int)
    {
      n_redundant += count ? 1 : 0;
      return;
    }
    std::vector<std::pair<unsigned int, double>> expression;
    for (const auto &[dof, c] : a)
      if (dof != pivot && std::abs(c) > 1e-12 * scale)
        expression.emplace_back(dof, -c / a[pivot]);
    // earlier slaves that depend on the new slave
    for (auto &[s, terms] : slaves)
    {
      std::map<unsigned int, double> merged;
      bool depends = false;
      for (const auto &[master, c] : terms)
        if (master == pivot)
        {
          depends = true;
          for (const auto &[m, cm] : expression)
            merged[m] += c * cm;
        }
        else
          merged[master] += c;
      if (depends)
        terms.assign(merged.begin(), merged.end());
    }
    slaves[pivot] = expression;
  }
}

void RowElimination::condense(const SparseMatrix<double> &A,
                              const std::vector<double> &slave_diagonal,
                              SparsityPattern &pattern,
                              SparseMatrix<double> &result) const
{
  const unsigned int n = A.m();
  auto expansion = [&](const unsigned int i)
  {
    const auto s = slaves.find(i);
    return s == slaves.end() ? std::vector<std::pair<unsigned int, double>>{{i, 1.}}
                             : s->second;
  };
  if (pattern.n_rows() == 0)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
    {
      dsp.add(i, i);
      const auto ei = expansion(i);
      for (auto it = A.begin(i); it != A.end(i); ++it)
        for (const auto &[p, cp] : ei)
          for (const auto &[q, cq] : expansion(it->column()))
            if (p < n && q < n) // not the virtual DoFs of boundary values
              dsp.add(p, q);
    }
    pattern.copy_from(dsp);
  }
  result.reinit(pattern);
  for (unsigned int i = 0; i < n; ++i)
  {
    const auto ei = expansion(i);
    for (auto it = A.begin(i); it != A.end(i); ++it)
      if (it->value() != 0.)
        for (const auto &[p, cp] : ei)
          for (const auto &[q, cq] : expansion(it->column()))
            if (p < n && q < n)
              result.add(p, q, cp * it->value() * cq);
  }
  for (const auto &entry : slaves)
    result.set(entry.first, entry.first, slave_diagonal[entry.first]);
}

void RowElimination::distribute(Vector<double> &phi) const
{
  for (const auto &[s, terms] : slaves)
  {
    double value = 0.;
    for (const auto &[master, c] : terms)
      value += c * phi[master];
    phi[s] = value;
  }
}

void RowElimination::transpose_apply(Vector<double> &y) const
{
  for (const auto &[s, terms] : slaves)
  {
    for (const auto &[master, c] : terms)
      if (master < y.size())
        y[master] += c * y[s];
    y[s] = 0.;
  }
}
} // namespace hati

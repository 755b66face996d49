// The contacts a response-spectrum analysis holds and their multipliers
// (doc/theory.md 14.5, 14.6).

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/analysis/held_contacts.h>

#include <cmath>
#include <map>

namespace hati
{
/** The dot product of two sparse rows. */
double row_product(const SparseRow &a, const SparseRow &b)
{
  double s = 0.;
  for (unsigned int i = 0; i < a.dofs.size(); ++i)
    for (unsigned int j = 0; j < b.dofs.size(); ++j)
      if (a.dofs[i] == b.dofs[j])
        s += a.coefficients[i] * b.coefficients[j];
  return s;
}

HeldContacts::HeldContacts(const DiscreteSystem &system, const bool clearance_closed)
    : fixed(system.fixed)
{
  std::map<std::string, unsigned int> index;
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
  {
    const ContactRow &row = system.contacts[k];
    if (row.constraint)
      continue;
    const auto [it, added] = index.emplace(row.name, names.size());
    if (added)
    {
      names.push_back(row.name);
      members.emplace_back();
    }
    members[it->second].push_back(k);
  }
  two_sided.assign(names.size(), false);
  for (unsigned int c = 0; c < names.size(); ++c)
  {
    const std::vector<unsigned int> &m = members[c];
    const ContactRow &first = system.contacts[m[0]];
    // a two-sided contact: two opposite rows of one name
    if (m.size() == 2)
    {
      const ContactRow &second = system.contacts[m[1]];
      const double ab = row_product(first, second), aa = row_product(first, first),
                   bb = row_product(second, second);
      two_sided[c] = ab < 0. && std::abs(ab * ab - aa * bb) <= 1e-12 * aa * bb;
    }
    for (const unsigned int k : m)
    {
      const ContactRow &row = system.contacts[k];
      const bool closed = row.initial_gap == 0.;
      const bool clearance = two_sided[c] && row.initial_gap > 0.;
      if (closed || (clearance && clearance_closed))
      {
        add_row(row, c, row_product(row, first) >= 0. ? 1. : -1.);
        if (closed)
          ++n_closed;
        else
          ++n_clearance;
        if (clearance)
          held_clearance.push_back(row);
      }
      // a closed frictional contact sticks: its tangents are held too (A9)
      if (closed && row.frictional())
        for (const SparseRow &tangent : row.tangents)
          add_row(tangent, names.size(), 0.);
    }
  }
  // (L L^T)^+ on the free DoFs
  const unsigned int m = rows.size();
  if (m == 0)
    return;
  LAPACKFullMatrix<double> G(m, m);
  for (unsigned int i = 0; i < m; ++i)
    for (unsigned int j = i; j < m; ++j)
      G(i, j) = G(j, i) = row_product(rows[i], rows[j]);
  G.compute_inverse_svd(1e-10);
  pseudo_inverse.reinit(m, m);
  for (unsigned int i = 0; i < m; ++i)
    for (unsigned int j = 0; j < m; ++j)
      pseudo_inverse(i, j) = G(i, j);
}

void HeldContacts::forces(const Vector<double> &residual,
                          std::vector<double> &forces) const
{
  const unsigned int m = rows.size();
  std::vector<double> Lr(m, 0.);
  for (unsigned int i = 0; i < m; ++i)
    Lr[i] = rows[i].apply(residual);
  const std::size_t first = forces.size();
  forces.resize(first + names.size(), 0.);
  for (unsigned int i = 0; i < m; ++i)
    if (contact[i] < names.size())
    {
      double mu = 0.;
      for (unsigned int j = 0; j < m; ++j)
        mu += pseudo_inverse(i, j) * Lr[j];
      forces[first + contact[i]] += sign[i] * mu;
    }
}

void HeldContacts::add_row(const SparseRow &row, const std::size_t c, const double s)
{
  SparseRow free;
  for (unsigned int i = 0; i < row.dofs.size(); ++i)
    if (!fixed[row.dofs[i]] && row.coefficients[i] != 0.)
    {
      free.dofs.push_back(row.dofs[i]);
      free.coefficients.push_back(row.coefficients[i]);
    }
  rows.push_back(free);
  contact.push_back(c);
  sign.push_back(s);
}
} // namespace hati

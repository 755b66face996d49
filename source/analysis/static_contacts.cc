// The contact rows of a static solve (doc/theory.md 6): which are held
// closed, their forces, the sticking tangents of friction (A9).
#include <deal.II/base/exceptions.h>

#include <hati/analysis/static_contacts.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace hati
{
bool opposite_rows(const ContactRow &a, const ContactRow &b)
{
  if (a.dofs != b.dofs || a.initial_gap != b.initial_gap)
    return false;
  for (unsigned int j = 0; j < a.dofs.size(); ++j)
    if (a.coefficients[j] != -b.coefficients[j])
      return false;
  return true;
}

ClosedContacts::ClosedContacts(const DiscreteSystem &system)
    : opposite(system.contacts.size(), -1)
{
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
  {
    const ContactRow &c = system.contacts[k];
    bool free_dof = false;
    for (const auto dof : c.dofs)
      free_dof = free_dof || !system.fixed[dof];
    if (!free_dof)
      continue;
    // a row with a gap is held only as the second of a two-sided pair whose
    // first row (the same gap, the opposite normal) precedes it
    if (c.initial_gap != 0.)
    {
      for (unsigned int j = 0; j < k; ++j)
        if (opposite_rows(system.contacts[j], c))
        {
          centred.push_back(j);
          closed.push_back(j);
          opposite[k] = j;
          break;
        }
      continue;
    }
    for (const unsigned int j : closed)
      if (opposite_rows(system.contacts[j], c))
        opposite[k] = j;
    if (opposite[k] < 0)
      closed.push_back(k);
  }
}

bool ClosedContacts::is_centred(const unsigned int k) const
{
  return std::find(centred.begin(), centred.end(), k) != centred.end();
}

void ClosedContacts::release(const unsigned int k)
{
  closed.erase(std::remove(closed.begin(), closed.end(), k), closed.end());
  centred.erase(std::remove(centred.begin(), centred.end(), k), centred.end());
  released.push_back(k);
}

std::vector<unsigned int> PlayProbe::releasable(const ClosedContacts &contacts) const
{
  const unsigned int m = rows.size();
  double scale = 0.;
  for (unsigned int i = 0; i < m; ++i)
    scale = std::max(scale, std::abs(block[i * m + i]));
  // Gaussian elimination on the block, a row taken when its pivot (the
  // Schur complement of the rows taken before) is regular
  std::vector<double> a = block;
  std::vector<unsigned int> taken, result;
  for (unsigned int j = 0; j < m; ++j)
  {
    const double pivot = a[j * m + j];
    if (!(std::abs(pivot) > 1e-8 * scale))
      continue;
    taken.push_back(j);
    result.push_back(contacts.closed[rows[j]]);
    for (unsigned int i = j + 1; i < m; ++i)
    {
      const double f = a[i * m + j] / pivot;
      for (unsigned int k = j; k < m; ++k)
        a[i * m + k] -= f * a[j * m + k];
    }
  }
  return result;
}

std::string push_message(const DiscreteSystem &system, const PushedPair &p)
{
  std::ostringstream message;
  message << "static analysis: the static load pushes the two-sided contact '"
          << system.contacts[p.first].name << "' across its clearance (" << p.second
          << " N): there is no static state within the play (support it)";
  return message.str();
}

std::vector<double> closed_contact_forces(const DiscreteSystem &system,
                                          const ClosedContacts &contacts,
                                          const std::vector<double> &lambda,
                                          const Vector<double> &F,
                                          std::vector<PushedPair> *pushed)
{
  const std::vector<unsigned int> &closed = contacts.closed;
  const std::vector<int> &opposite = contacts.opposite;
  double largest = 0.;
  for (const double l : lambda)
    largest = std::max(largest, std::abs(l));
  std::vector<double> forces(system.contacts.size(), 0.);
  for (unsigned int r = 0; r < closed.size(); ++r)
    forces[closed[r]] = lambda[r];
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
    if (opposite[k] >= 0 && forces[opposite[k]] < 0.) // bilateral pair
    {
      forces[k] = -forces[opposite[k]];
      forces[opposite[k]] = 0.;
    }
  for (unsigned int r = 0; r < closed.size(); ++r)
  {
    const unsigned int k = closed[r];
    bool bilateral = system.contacts[k].bilateral; // and the centred pairs
    for (unsigned int j = 0; j < opposite.size(); ++j)
      bilateral = bilateral || opposite[j] == static_cast<int>(k);
    if (!bilateral && lambda[r] < -1e-9 * largest)
    {
      std::ostringstream message;
      message << "static analysis: the closed contact '" << system.contacts[k].name
              << "' is in tension (" << lambda[r]
              << " N): the structure would lift off there (give it a gap > 0 or a "
                 "support)";
      AssertThrow(false, ExcMessage(message.str()));
    }
  }
  // a two-sided contact with a clearance only stands in for the play: the
  // static load must not push the node to a side
  double load = 0.;
  for (unsigned int i = 0; i < F.size(); ++i)
    load = std::max(load, std::abs(F[i]));
  for (unsigned int r = 0; r < closed.size(); ++r)
    if (contacts.is_centred(closed[r]))
    {
      if (pushes(lambda[r], largest, load))
      {
        AssertThrow(pushed != nullptr,
                    ExcMessage(push_message(system, {closed[r], lambda[r]})));
        pushed->emplace_back(closed[r], lambda[r]);
      }
      forces[closed[r]] = 0.;
      for (unsigned int k = 0; k < opposite.size(); ++k)
        if (opposite[k] == static_cast<int>(closed[r]))
          forces[k] = 0.;
    }
  return forces;
}

bool parallel_rows(const SparseRow &a, const SparseRow &b, const std::vector<bool> &fixed)
{
  std::map<types::global_dof_index, double> ca, cb;
  for (unsigned int j = 0; j < a.dofs.size(); ++j)
    if (!fixed[a.dofs[j]] && a.coefficients[j] != 0.)
      ca[a.dofs[j]] += a.coefficients[j];
  for (unsigned int j = 0; j < b.dofs.size(); ++j)
    if (!fixed[b.dofs[j]] && b.coefficients[j] != 0.)
      cb[b.dofs[j]] += b.coefficients[j];
  if (ca.empty() || ca.size() != cb.size())
    return false;
  const double ratio = cb.begin()->second / ca.begin()->second;
  for (auto ia = ca.begin(), ib = cb.begin(); ia != ca.end(); ++ia, ++ib)
    if (ia->first != ib->first ||
        std::abs(ib->second - ratio * ia->second) > 1e-12 * std::abs(ib->second))
      return false;
  return true;
}

std::vector<std::array<unsigned int, 3>>
sticking_tangents(const DiscreteSystem &system,
                  const ClosedContacts &contacts,
                  std::vector<const SparseRow *> &held,
                  std::vector<double> &held_rhs)
{
  std::vector<std::array<unsigned int, 3>> sticking;
  for (unsigned int r = 0; r < contacts.closed.size(); ++r)
  {
    const ContactRow &c = system.contacts[contacts.closed[r]];
    if (!c.frictional() || contacts.is_centred(contacts.closed[r]))
      continue;
    const unsigned int first = held.size();
    for (const SparseRow &t : c.tangents)
    {
      bool free_dof = false;
      for (const auto dof : t.dofs)
        free_dof = free_dof || !system.fixed[dof];
      if (!free_dof)
        continue; // a tangent direction a support holds already
      bool parallel = false;
      for (const SparseRow *h : held)
        parallel = parallel || parallel_rows(*h, t, system.fixed);
      if (parallel)
        continue; // held already, e.g. by a wheel's centred flange pair
      held.push_back(&t);
      held_rhs.push_back(0.);
    }
    sticking.push_back({{r, first, static_cast<unsigned int>(held.size()) - first}});
  }
  return sticking;
}

void check_static_friction(const DiscreteSystem &system,
                           const ClosedContacts &contacts,
                           const std::vector<std::array<unsigned int, 3>> &sticking,
                           const std::vector<double> &lambda)
{
  double largest = 0.;
  for (const double l : lambda)
    largest = std::max(largest, std::abs(l));
  for (const auto &[r, first, count] : sticking)
  {
    const ContactRow &c = system.contacts[contacts.closed[r]];
    double t2 = 0.;
    for (unsigned int t = 0; t < count; ++t)
      t2 += lambda[first + t] * lambda[first + t];
    const double tangential = std::sqrt(t2), normal = std::abs(lambda[r]);
    if (tangential > c.friction * normal + 1e-12 * largest)
    {
      std::ostringstream message;
      message << "static analysis: the closed contact '" << c.name
              << "' does not stick: its tangential force " << tangential
              << " N exceeds mu times its normal force, " << c.friction << " x " << normal
              << " = " << c.friction * normal
              << " N (Coulomb friction, mu = " << c.friction
              << "): there is no static state on it (support it or raise mu)";
      AssertThrow(false, ExcMessage(message.str()));
    }
  }
}

} // namespace hati

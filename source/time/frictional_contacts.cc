#include <deal.II/base/exceptions.h>

#include <hati/contact/condensed_cluster.h>
#include <hati/contact/lcp_solver.h>
#include <hati/contact/sparse_rows.h>
#include <hati/time/frictional_contacts.h>

#include <algorithm>
#include <cmath>

namespace hati
{
FrictionalContacts::FrictionalContacts(const std::vector<ContactRow> &contacts)
    : contacts(contacts), with_friction(has_friction(contacts))
{
  tangential.assign(2 * contacts.size(), 0.);
  states.assign(contacts.size(), FrictionState::open);
  in_friction_cluster.assign(contacts.size(), 0);
  for (const auto &c : contacts)
    AssertThrow(c.tangents.size() <= 2,
                ExcMessage("contact '" + c.name + "' has more than two tangent rows"));
}

bool FrictionalContacts::frictional(const std::vector<unsigned int> &cluster) const
{
  for (const unsigned int k : cluster)
    if (contacts[k].frictional())
      return true;
  return false;
}

void FrictionalContacts::begin_step(const Vector<double> &v_after)
{
  // the first half of the work of the last step's impulses (doc/theory.md E1, A9)
  add_half_work(v_after);
  for (unsigned int k = 0; k < contacts.size(); ++k)
  {
    tangential[2 * k] = tangential[2 * k + 1] = 0.;
    states[k] = FrictionState::open;
    in_friction_cluster[k] = 0;
  }
}

void FrictionalContacts::end_step(const Vector<double> &v_before)
{
  add_half_work(v_before);
}

void FrictionalContacts::add_half_work(const Vector<double> &v)
{
  for (unsigned int k = 0; k < contacts.size(); ++k)
    for (unsigned int t = 0; t < contacts[k].tangents.size(); ++t)
      if (tangential[2 * k + t] != 0.)
        friction_work += 0.5 * contacts[k].tangents[t].apply(v) * tangential[2 * k + t];
}

void FrictionalContacts::solve(const std::vector<unsigned int> &cluster,
                               const Vector<double> &inverse_mass,
                               const Vector<double> &v_before,
                               const bool prescribed,
                               const std::vector<bool> *sliding,
                               Vector<double> &v,
                               std::vector<double> &lambda)
{
  // the rows of the cluster: per contact its normal, then its tangents
  rows.clear();
  first.clear();
  mu.clear();
  bilateral.clear();
  for (const unsigned int k : cluster)
  {
    const ContactRow &c = contacts[k];
    first.push_back(rows.size());
    rows.push_back(&c);
    // a prescribed sliding contact: its normal row alone (no tangential
    // impulse in the linear response)
    const bool slides = prescribed && sliding != nullptr && (*sliding)[k];
    if (c.frictional() && !slides)
      for (const auto &t : c.tangents)
        rows.push_back(&t);
    mu.push_back(c.frictional() && !slides ? c.friction : 0.);
    bilateral.push_back(c.bilateral);
  }
  first.push_back(rows.size());
  const unsigned int n = rows.size();
  // the work space of a cluster of n rows (deal.II's reinit() to another
  // size allocates: the crane's clusters alternate between sizes)
  if (work_space.size() <= n)
    work_space.resize(n + 1);
  Vector<double> &q = work_space[n].q, &r = work_space[n].r;
  // W = L M^-1 L^T, formed when the cluster's rows change
  if (cached_clusters.size() != contacts.size())
    cached_clusters.resize(contacts.size());
  CachedCluster &cached = cached_clusters[cluster[0]];
  if (cached.cluster != cluster || cached.mu != mu ||
      cached.inverse_mass != &inverse_mass)
  {
    cached.cluster = cluster;
    cached.mu = mu;
    cached.inverse_mass = &inverse_mass;
    delassus(rows, inverse_mass, cached.W);
    cached.links.valid = false;
    cached.inverted = false;
  }
  const FullMatrix<double> &W = cached.W;
  if (q.size() != n)
    q.reinit(n);
  for (unsigned int a = 0; a < cluster.size(); ++a)
  {
    const ContactRow &c = contacts[cluster[a]];
    // q = L V_free + e L V_{n+1/2} (normal), T V_free (tangents)
    q[first[a]] = c.apply(v) + c.restitution * c.apply(v_before);
    for (unsigned int i = first[a] + 1; i < first[a + 1]; ++i)
      q[i] = rows[i]->apply(v);
  }
  if (prescribed)
  {
    // every row an equality: W r = -q (the sticking response of the active set)
    solve_equalities(W, cached.W_inverse, cached.inverted, q, r);
    cluster_states.assign(cluster.size(), FrictionState::stick);
  }
  else
  {
    const FrictionSolverResult result = solve_condensed_frictional_cluster(
        {W, q, first, mu, bilateral}, r, cluster_states, control, &cached.links);
    sweeps_max = std::max(sweeps_max, result.sweeps);
    if (!result.converged)
      ++n_unconverged;
  }
  // V_{n+3/2} = V_free + M^-1 (L^T lambda_n + T^T lambda_t) (A5, A9)
  for (unsigned int a = 0; a < cluster.size(); ++a)
  {
    const unsigned int k = cluster[a];
    lambda[k] = r[first[a]];
    states[k] = cluster_states[a];
    in_friction_cluster[k] = 1;
    for (unsigned int i = first[a]; i < first[a + 1]; ++i)
    {
      if (i > first[a])
        tangential[2 * k + i - first[a] - 1] = r[i];
      rows[i]->add_transpose(r[i], inverse_mass, v);
    }
  }
}

double FrictionalContacts::tangential_impulse_norm(const unsigned int k) const
{
  return std::hypot(tangential[2 * k], tangential[2 * k + 1]);
}

FrictionState FrictionalContacts::state(const unsigned int k, const double impulse) const
{
  if (in_friction_cluster[k])
    return states[k];
  return impulse != 0. ? FrictionState::slip : FrictionState::open;
}

void FrictionalContacts::sample(const Vector<double> &V,
                                const std::vector<double> &impulses,
                                std::vector<double> &tangential_out,
                                std::vector<double> &slip,
                                std::vector<FrictionState> &states_out) const
{
  const unsigned int nc = contacts.size();
  tangential_out.resize(2 * nc);
  slip.resize(nc);
  states_out.resize(nc);
  for (unsigned int k = 0; k < nc; ++k)
  {
    tangential_out[2 * k] = tangential[2 * k];
    tangential_out[2 * k + 1] = tangential[2 * k + 1];
    states_out[k] = state(k, impulses[k]);
    double s2 = 0.;
    if (states_out[k] != FrictionState::open)
      for (const auto &t : contacts[k].tangents)
      {
        const double u = t.apply(V);
        s2 += u * u;
      }
    slip[k] = std::sqrt(s2);
  }
}

void FrictionalContacts::save(Record &record) const
{
  record.tangential = tangential;
  record.states = states;
  record.in_cluster = in_friction_cluster;
  record.work = friction_work;
}

void FrictionalContacts::restore(const Record &record)
{
  tangential = record.tangential;
  states = record.states;
  in_friction_cluster = record.in_cluster;
  friction_work = record.work;
}
} // namespace hati

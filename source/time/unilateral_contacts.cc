#include <deal.II/base/exceptions.h>

#include <hati/contact/lcp_solver.h>
#include <hati/output/contact_output.h>
#include <hati/time/unilateral_contacts.h>

#include <algorithm>

namespace hati
{
Registry<ForceLawFactory>::Entry UnilateralContacts::registration()
{
  return {"contacts",
          "the contact rows (A4-A6, A9) and the constraint rows of ties and rigid "
          "links (B1)",
          {},
          [](const DiscreteSystem &system) -> std::unique_ptr<ForceLaw>
          { return std::make_unique<UnilateralContacts>(system); }};
}

UnilateralContacts::UnilateralContacts(const DiscreteSystem &system)
    : system(system), contacts(system.contacts), frictional_contacts(system.contacts)
{
}

void UnilateralContacts::start_rows(const Vector<double> &U,
                                    const Vector<double> &dt_minv)
{
  // contacts: which contacts are coupled through a common free DoF
  const unsigned int nc = contacts.size();
  gap.resize(nc);
  lambda.assign(nc, 0.);
  is_active.assign(nc, false);
  coupled_with.resize(nc);
  for (unsigned int k = 0; k < nc; ++k)
  {
    const auto &c = contacts[k];
    double w = 0.;
    for (unsigned int a = 0; a < c.dofs.size(); ++a)
      w += c.coefficients[a] * c.coefficients[a] * dt_minv[c.dofs[a]];
    AssertThrow(w > 0.,
                ExcMessage("contact '" + c.name +
                           "' acts only on fixed or massless degrees of freedom"));
    gap[k] = c.initial_gap + c.apply(U);
  }
  was_closed.resize(nc);
  for (unsigned int k = 0; k < nc; ++k)
    was_closed[k] = gap[k] <= closed_gap_tolerance;
  // the DoFs a contact's impulse acts on: its row, and its tangent rows
  // with friction (A9)
  auto shares_dof = [&](const SparseRow &a, const SparseRow &b)
  {
    bool shared = false;
    for (const auto d : a.dofs)
      if (!system.fixed[d])
        for (const auto e : b.dofs)
          shared = shared || (d == e);
    return shared;
  };
  for (unsigned int k = 0; k < nc; ++k)
    for (unsigned int l = k + 1; l < nc; ++l)
    {
      bool shared = shares_dof(contacts[k], contacts[l]);
      if (frictional_contacts.any())
      {
        std::vector<const SparseRow *> rows_k{&contacts[k]}, rows_l{&contacts[l]};
        for (const auto &t : contacts[k].tangents)
          rows_k.push_back(&t);
        for (const auto &t : contacts[l].tangents)
          rows_l.push_back(&t);
        for (const auto *a : rows_k)
          for (const auto *b : rows_l)
            shared = shared || shares_dof(*a, *b);
      }
      if (shared)
      {
        coupled_with[k].push_back(l);
        coupled_with[l].push_back(k);
      }
    }
}

void UnilateralContacts::apply_impulses(const Vector<double> &U,
                                        const Vector<double> &v_before,
                                        const Vector<double> &minv,
                                        Vector<double> &v)
{
  const unsigned int nc = contacts.size();

  // contact work, first half: 1/2 (L V_{n+1/2}) lambda_n (doc/theory.md E1)
  for (unsigned int k = 0; k < nc; ++k)
    if (lambda[k] != 0.)
      contact_work += 0.5 * contacts[k].apply(v_before) * lambda[k];
  if (frictional_contacts.any())
    frictional_contacts.begin_step(v_before);

  // (A4) active set from the position-level gap (or the prescribed or frozen one),
  // round-off gaps closed (closed_gap_tolerance; held_gap_tolerance for a
  // contact in the previous step's set)
  active_list.clear();
  for (unsigned int k = 0; k < nc; ++k)
  {
    const auto &c = contacts[k];
    gap[k] = c.initial_gap + c.apply(U);
    const double tolerance = was_closed[k] ? held_gap_tolerance : closed_gap_tolerance;
    is_active[k] =
        c.bilateral ||
        (prescribed ? bool((*prescribed)[k])
         : frozen   ? bool((*frozen)[k])
                    : (gap[k] <= tolerance && !(switched_off && (*switched_off)[k])));
    was_closed[k] = is_active[k];
    lambda[k] = 0.;
    if (is_active[k])
      active_list.push_back(k);
  }
  if (active_list.empty())
    return;

  // (A5) clusters of coupled active contacts, each an LCP w = W lambda + q
  clustered.assign(nc, false);
  for (const unsigned int k0 : active_list)
  {
    if (clustered[k0])
      continue;
    cluster.assign(1, k0);
    clustered[k0] = true;
    for (unsigned int c = 0; c < cluster.size(); ++c)
      for (const unsigned int l : coupled_with[cluster[c]])
        if (is_active[l] && !clustered[l])
        {
          clustered[l] = true;
          cluster.push_back(l);
        }

    const unsigned int m = cluster.size();
    // (A9) a cluster with friction: nonsmooth Gauss-Seidel over its contacts
    if (frictional_contacts.any() && frictional_contacts.frictional(cluster))
    {
      frictional_contacts.solve(
          cluster, minv, v_before, prescribed != nullptr, prescribed_sliding, v, lambda);
      continue;
    }
    if (m == 1)
    {
      // a single contact: lambda = max(0, -q / W) (bilateral: -q / W)
      const auto &c = contacts[k0];
      const double q = c.apply(v) + c.restitution * c.apply(v_before);
      double w = 0.;
      for (unsigned int i = 0; i < c.dofs.size(); ++i)
        w += c.coefficients[i] * c.coefficients[i] * minv[c.dofs[i]];
      AssertThrow(w > 0.,
                  ExcMessage("contact LCP: a contact acts on degrees of freedom without "
                             "mass (fixed or massless); its Delassus entry is zero."));
      const double l = (prescribed || c.bilateral) ? -q / w : std::max(0., -q / w);
      lambda[k0] = l;
      if (l != 0.)
        c.add_transpose(l, minv, v);
      continue;
    }
    cluster_rows.resize(m);
    // work vectors per cluster size (no allocation once a size was seen)
    if (lcp_q.size() <= m)
    {
      lcp_q.resize(m + 1);
      lcp_lambda.resize(m + 1);
      lcp_bilateral.resize(m + 1);
    }
    Vector<double> &q = lcp_q[m];
    std::vector<bool> &bilateral = lcp_bilateral[m];
    if (q.size() != m)
    {
      q.reinit(m);
      bilateral.resize(m);
    }
    for (unsigned int a = 0; a < m; ++a)
    {
      cluster_rows[a] = &contacts[cluster[a]];
      bilateral[a] = cluster_rows[a]->bilateral;
      // q = L V_free + e L V_{n+1/2}
      q[a] = cluster_rows[a]->apply(v) +
             cluster_rows[a]->restitution * cluster_rows[a]->apply(v_before);
    }
    // the cluster's Delassus block, formed once per cluster (its rows are
    // constant): the last two clusters that began with this row are kept
    if (delassus_blocks.size() != nc)
      delassus_blocks.resize(nc);
    DelassusBlocks &slot = delassus_blocks[cluster[0]];
    DelassusBlock *block = nullptr;
    for (DelassusBlock &entry : slot.entries)
      if (entry.inverse_mass == &minv && entry.cluster == cluster)
        block = &entry;
    if (block == nullptr)
    {
      block = &slot.entries[slot.next];
      slot.next = (slot.next + 1) % slot.entries.size();
      block->cluster = cluster;
      block->inverse_mass = &minv;
      delassus(cluster_rows, minv, block->W);
      block->inverted = false;
      block->elimination.formed = false;
    }
    const FullMatrix<double> &W = block->W;
    Vector<double> &l = lcp_lambda[m];
    // W lambda = -q on the prescribed active set
    if (prescribed)
      solve_equalities(W, block->W_inverse, block->inverted, q, l);
    else
      solve_lcp(W, q, bilateral, l, block->elimination);

    // V_{n+3/2} = V_free + M^-1 L^T lambda  (A5); lambda is an impulse (A6)
    for (unsigned int a = 0; a < m; ++a)
    {
      const auto &c = contacts[cluster[a]];
      lambda[cluster[a]] = l[a];
      c.add_transpose(l[a], minv, v);
    }
  }

  // contact work, second half: 1/2 (L V_{n+1/2}) lambda_{n+1}
  for (const unsigned int k : active_list)
    if (lambda[k] != 0.)
      contact_work += 0.5 * contacts[k].apply(v_before) * lambda[k];
  if (frictional_contacts.any())
    frictional_contacts.end_step(v_before);
}

void UnilateralContacts::add_energies(Energies &e) const
{
  e.contact_work = contact_work;
  e.friction_dissipated = -frictional_contacts.work();
}

void UnilateralContacts::save(std::any &state) const
{
  // copied into the State a previous save left there (no allocation)
  State *s = std::any_cast<State>(&state);
  if (!s)
  {
    state = State();
    s = std::any_cast<State>(&state);
  }
  s->gap = gap;
  s->lambda = lambda;
  s->is_active = is_active;
  s->was_closed = was_closed;
  s->contact_work = contact_work;
  frictional_contacts.save(s->friction);
}

void UnilateralContacts::restore(const std::any &state)
{
  const State &s = std::any_cast<const State &>(state);
  gap = s.gap;
  lambda = s.lambda;
  is_active = s.is_active;
  was_closed = s.was_closed;
  contact_work = s.contact_work;
  frictional_contacts.restore(s.friction);
}
void UnilateralContacts::sample(const Vector<double> &V, LawSample &s) const
{
  s.gaps = gap;
  s.impulses = lambda;
  s.active = is_active;
  if (!s.every_step) // only the output rows and the coupling read them
  {
    s.normal_velocities.resize(contacts.size());
    for (unsigned int k = 0; k < contacts.size(); ++k)
      s.normal_velocities[k] = contacts[k].apply(V);
  }
  if (frictional_contacts.any())
    frictional_contacts.sample(
        V, s.impulses, s.tangential_impulses, s.slip_velocities, s.friction_states);
}

std::unique_ptr<LawOutput>
UnilateralContacts::make_output(const LawOutputContext &context) const
{
  // the constraint rows of ties and rigid links are not contacts
  if (n_contacts(context.system.contacts) == 0)
    return nullptr;
  return std::make_unique<ContactOutput>(context, frictional_contacts);
}
std::string UnilateralContacts::refusal_of(const std::vector<ContactRow> &contacts,
                                           const std::string &method)
{
  if (method == "Newmark" && !contacts.empty())
    return "Time integration/Method = Newmark: the model has contacts, which need the "
           "explicit CD-Lagrange integrator.";
  if (method == "event-driven")
    for (const auto &c : contacts)
    {
      if (c.frictional())
        return "Time integration/Method = event-driven: the contact '" + c.name +
               "' has Coulomb friction (mu > 0), which the event-driven reference does "
               "not handle; use CD-Lagrange";
      if (c.bilateral)
        return "Time integration/Method = event-driven: the contact '" + c.name +
               "' is two-sided without clearance (bilateral), which the event-driven "
               "reference does not handle; use CD-Lagrange";
    }
  return "";
}

std::string UnilateralContacts::refusal(const std::string &method) const
{
  // a system without rows: every method; with rows, those that resolve them
  if (method == "Newmark" || method == "event-driven")
    return refusal_of(contacts, method);
  return ForceLaw::refusal(method);
}
} // namespace hati

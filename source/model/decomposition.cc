#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hati/model/decomposition.h>
#include <hati/time/force_law.h>

#include <algorithm>

namespace hati
{
namespace
{
/** The refusal of a rope outside the explicit subdomain (R1). */
std::string rope_message(const std::string &name)
{
  return "Model/Decomposition: the rope '" + name +
         "' lies in the implicit subdomain; ropes need the explicit CD-Lagrange "
         "integrator: put its hook point in the Explicit region or the Explicit "
         "members";
}

/**
 * The rows @p links (whole numbering) split into their explicit and implicit
 * parts (G3'', doc/theory.md 11.3): a DoF of one subdomain only goes to that
 * side's row; a DoF of both (an interface DoF) to the explicit side if it is
 * the row's first (the slave of a link), to the implicit side otherwise.
 */
void add_link_rows(const std::vector<SparseRow> &links, Decomposition &decomposition)
{
  const auto &e = decomposition.parts[0].global_dofs,
             &i = decomposition.parts[1].global_dofs;
  for (const SparseRow &link : links)
  {
    SparseRow row_E, row_I;
    for (unsigned int k = 0; k < link.dofs.size(); ++k)
    {
      const auto in_E = std::lower_bound(e.begin(), e.end(), link.dofs[k]);
      const auto in_I = std::lower_bound(i.begin(), i.end(), link.dofs[k]);
      const bool E = in_E != e.end() && *in_E == link.dofs[k],
                 I = in_I != i.end() && *in_I == link.dofs[k];
      if (E && (k == 0 || !I))
      {
        row_E.dofs.push_back(in_E - e.begin());
        row_E.coefficients.push_back(link.coefficients[k]);
      }
      else if (I)
      {
        row_I.dofs.push_back(in_I - i.begin());
        row_I.coefficients.push_back(link.coefficients[k]);
      }
    }
    AssertThrow(!row_E.dofs.empty() && !row_I.dofs.empty(),
                ExcMessage("Model/Decomposition: a tie or rigid link across the "
                           "interface has no DoF on one side"));
    if (row_E.dofs.size() == 1)
      for (const SparseRow &other : decomposition.rows[0])
        AssertThrow(other.dofs.size() != 1 || other.dofs[0] != row_E.dofs[0],
                    ExcMessage("Model/Decomposition: a tied node joins members of both "
                               "subdomains: put all the members at a tied node on one "
                               "side"));
    decomposition.rows[0].push_back(row_E);
    decomposition.rows[1].push_back(row_I);
  }
}
} // namespace

void extract_subsystem(const DiscreteSystem &full,
                       const std::vector<types::global_dof_index> &dofs,
                       DiscreteSystem &sub)
{
  const unsigned int N = full.n_dofs(), n = dofs.size();
  std::vector<int> local(N, -1);
  for (unsigned int i = 0; i < n; ++i)
    local[dofs[i]] = i;
  sub.reinit(n);
  auto restrict = [&](const Vector<double> &x, Vector<double> &y)
  {
    if (x.size() != N)
      return;
    y.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      y[i] = x[dofs[i]];
  };
  restrict(full.lumped_mass, sub.lumped_mass);
  restrict(full.constant_force, sub.constant_force);
  restrict(full.initial_displacement, sub.initial_displacement);
  restrict(full.initial_velocity, sub.initial_velocity);
  for (unsigned int d = 0; d < 3; ++d)
  {
    restrict(full.influence[d], sub.influence[d]);
    restrict(full.mass_influence[d], sub.mass_influence[d]);
    restrict(full.excited_mass_influence[d], sub.excited_mass_influence[d]);
  }
  restrict(full.excited_lumped_mass, sub.excited_lumped_mass);
  sub.gravity = full.gravity;
  sub.start_time = full.start_time;
  sub.omega_max_bound = full.omega_max_bound;
  for (const auto &load : full.time_dependent_loads)
  {
    TimeDependentLoad l = load;
    restrict(load.shape, l.shape);
    sub.time_dependent_loads.push_back(l);
  }

  if (full.has_stiffness())
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
    {
      dsp.add(i, i);
      for (auto it = full.stiffness_pattern.begin(dofs[i]);
           it != full.stiffness_pattern.end(dofs[i]);
           ++it)
        if (local[it->column()] >= 0)
          dsp.add(i, local[it->column()]);
    }
    sub.stiffness_pattern.copy_from(dsp);
    sub.stiffness.reinit(sub.stiffness_pattern);
    if (full.has_consistent_mass())
      sub.consistent_mass.reinit(sub.stiffness_pattern);
    for (unsigned int i = 0; i < n; ++i)
    {
      for (auto it = full.stiffness.begin(dofs[i]); it != full.stiffness.end(dofs[i]);
           ++it)
        if (local[it->column()] >= 0 && it->value() != 0.)
          sub.stiffness.set(i, local[it->column()], it->value());
      if (full.has_consistent_mass())
        for (auto it = full.consistent_mass.begin(dofs[i]);
             it != full.consistent_mass.end(dofs[i]);
             ++it)
          if (local[it->column()] >= 0 && it->value() != 0.)
            sub.consistent_mass.set(i, local[it->column()], it->value());
    }
  }

  // contacts: every DoF of a row must be kept, or be a fixed one (zero
  // displacement: its coefficient is dropped)
  for (const auto &c : full.contacts)
  {
    ContactRow row = c;
    // the normal row and the tangent rows of friction (A9) alike
    auto renumber = [&](const SparseRow &from, SparseRow &to)
    {
      to.dofs.clear();
      to.coefficients.clear();
      for (unsigned int i = 0; i < from.dofs.size(); ++i)
      {
        AssertThrow(local[from.dofs[i]] >= 0 || full.fixed[from.dofs[i]],
                    ExcMessage("Model/Decomposition: the contact '" + c.name +
                               "' lies in the implicit subdomain; contacts need the "
                               "explicit CD-Lagrange integrator: put its node in the "
                               "Explicit region or the Explicit members"));
        if (local[from.dofs[i]] >= 0)
        {
          to.dofs.push_back(local[from.dofs[i]]);
          to.coefficients.push_back(from.coefficients[i]);
        }
      }
    };
    renumber(c, row);
    for (unsigned int t = 0; t < c.tangents.size(); ++t)
      renumber(c.tangents[t], row.tangents[t]);
    sub.contacts.push_back(row);
  }

  // ropes (R1): the same for their translations (a held DoF stays invalid)
  for (const auto &r : full.ropes)
  {
    Rope rope = r;
    for (auto *dofs : {&rope.hook_dofs, &rope.load_dofs})
      for (auto &dof : *dofs)
        if (dof != numbers::invalid_dof_index)
        {
          AssertThrow(local[dof] >= 0 || full.fixed[dof],
                      ExcMessage(rope_message(r.name)));
          dof = local[dof] >= 0 ? local[dof] : numbers::invalid_dof_index;
        }
    sub.ropes.push_back(rope);
  }

  // the data of the other force laws (DiscreteSystem::law_data): each law
  // renumbers its own (ForceLaw::part_data(); refused by a law that cannot)
  extract_law_data(full, local, sub);
}

void decompose(Model &model,
               const CommonModelParameters &common,
               const DecompositionParameters &parameters,
               Decomposition &decomposition)
{
  decomposition.cell_parts = model.cell_parts(parameters);
  const auto &cell_parts = decomposition.cell_parts;
  const auto n_explicit = std::count(cell_parts.begin(), cell_parts.end(), 0);
  AssertThrow(n_explicit > 0,
              ExcMessage("Model/Decomposition: the explicit subdomain is empty: no "
                         "cell centre lies in the Explicit region and no Explicit "
                         "members are given"));
  AssertThrow(n_explicit < static_cast<long>(cell_parts.size()),
              ExcMessage("Model/Decomposition: the implicit subdomain is empty: every "
                         "cell is in the Explicit region or the Explicit members (use "
                         "Method = CD-Lagrange for a fully explicit run)"));

  for (unsigned int p = 0; p < 2; ++p)
  {
    model.select_part(cell_parts, p);
    DiscreteSystem full;
    model.build(common, full);
    full.fill_default_mass_influence();
    // the free DoFs the part's cells touch: a mass or a stiffness entry
    auto &part = decomposition.parts[p];
    part.global_dofs.clear();
    for (unsigned int i = 0; i < full.n_dofs(); ++i)
    {
      if (full.fixed[i])
        continue;
      bool touched = full.lumped_mass[i] > 0.;
      if (!touched && full.has_stiffness())
        for (auto it = full.stiffness.begin(i); it != full.stiffness.end(i) && !touched;
             ++it)
          touched = it->value() != 0.;
      if (touched)
        part.global_dofs.push_back(i);
    }
    extract_subsystem(full, part.global_dofs, part.system);
    AssertThrow(p == 0 || part.system.contacts.empty(),
                ExcMessage("Model/Decomposition: the contact '" +
                           part.system.contacts[0].name +
                           "' lies in the implicit subdomain; contacts need the explicit "
                           "CD-Lagrange integrator: put its node in the Explicit region "
                           "or the Explicit members"));
    AssertThrow(p == 0 || part.system.ropes.empty(),
                ExcMessage(rope_message(part.system.ropes[0].name)));
    AssertThrow(
        p == 0 || part.system.law_data.empty(),
        ExcMessage("Model/Decomposition: the force law '" +
                   (part.system.law_data.empty() ? std::string()
                                                 : part.system.law_data.begin()->first) +
                   "' lies in the implicit subdomain; force laws need the "
                   "explicit CD-Lagrange integrator: put its nodes in the "
                   "Explicit region or the Explicit members"));
  }
  // the rows of the model's links across (G3''), in the whole numbering
  const std::vector<SparseRow> links = model.interface_rows();
  model.select_part(cell_parts, -1);

  auto &rows = decomposition.rows;
  rows[0].clear();
  rows[1].clear();
  const auto &e = decomposition.parts[0].global_dofs,
             &i = decomposition.parts[1].global_dofs;
  auto pair_row = [](const unsigned int dof, const double coefficient)
  {
    SparseRow row;
    row.dofs = {dof};
    row.coefficients = {coefficient};
    return row;
  };
  for (unsigned int a = 0, b = 0; a < e.size() && b < i.size();)
    if (e[a] < i[b])
      ++a;
    else if (i[b] < e[a])
      ++b;
    else
    {
      rows[0].push_back(pair_row(a++, 1.));
      rows[1].push_back(pair_row(b++, -1.));
    }
  add_link_rows(links, decomposition);
  AssertThrow(!rows[0].empty(),
              ExcMessage("Model/Decomposition: the explicit and implicit subdomains "
                         "share no node (no interface): the coupling needs them to "
                         "touch"));
}
} // namespace hati

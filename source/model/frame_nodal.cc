#include <deal.II/lac/full_matrix.h>

#include <hati/model/frame.h>
#include <hati/model/frame_solids.h>

#include <sstream>

namespace hati
{
namespace
{
} // namespace

// The items of a frame at its nodes: springs, point masses, nodal loads and
// monitors. A tied node or a rigid link's slave is a constrained DoF: its
// items act through the constraints on the DoFs it follows.

std::vector<double> Frame::add_springs(DiscreteSystem &system) const
{
  std::vector<double> spring(system.n_dofs(), 0.);
  for (const auto &s : frame.supports)
    for (unsigned int c = 0; c < 6; ++c)
      if (s.stiffness[c] > 0. && owns_node(node_cells.at(s.node)))
      {
        const auto i = node_dofs.at(s.node)[c];
        // on a tied node or a rigid link's slave: on the DoFs it follows
        add_to_diagonal(i, s.stiffness[c], system.stiffness);
        spring[i] += s.stiffness[c];
      }
  return spring;
}

void Frame::add_to_diagonal(const types::global_dof_index i,
                            const double value,
                            SparseMatrix<double> &matrix) const
{
  FullMatrix<double> local(1, 1);
  local(0, 0) = value;
  constraints.distribute_local_to_global(
      local, std::vector<types::global_dof_index>{i}, matrix);
}

void Frame::add_point_masses(const std::vector<bool> &excited,
                             const bool restricted,
                             DiscreteSystem &system) const
{
  for (const auto &p : frame.point_masses)
    for (unsigned int c = 0; c < 6; ++c)
    {
      if (!owns_node(node_cells.at(p.node)))
        break;
      const auto i = node_dofs.at(p.node)[c];
      if (held(i) && !constraints.is_constrained(i))
        continue; // a rotation of a rope-only node
      // through the constraints: the mass of a tied node or of a rigid
      // link's slave moves with the DoFs it follows (C^T m C)
      const double m = c < 3 ? p.mass : p.rotary_inertia[c - 3];
      const std::vector<types::global_dof_index> dof{i};
      Vector<double> mi(1);
      mi[0] = m;
      constraints.distribute_local_to_global(mi, dof, system.lumped_mass);
      add_to_diagonal(i, m, system.consistent_mass);
      if (c < 3)
        constraints.distribute_local_to_global(mi, dof, system.mass_influence[c]);
      if (restricted && node_excited(p.node, excited))
      {
        constraints.distribute_local_to_global(mi, dof, system.excited_lumped_mass);
        if (c < 3)
          constraints.distribute_local_to_global(
              mi, dof, system.excited_mass_influence[c]);
      }
    }
}

void Frame::add_loads(const CommonModelParameters &common, DiscreteSystem &system) const
{
  // rigid translations; gravity F = M r g (consistent mass, inertia coupled
  // to the supports included); nodal loads
  const unsigned int n = system.n_dofs();
  for (unsigned int d = 0; d < 3; ++d)
  {
    system.influence[d].reinit(n);
    for (const auto &vd : vertex_dofs)
      if (!system.fixed[vd[d]])
        system.influence[d][vd[d]] = 1.;
    for (types::global_dof_index i = n_mesh_dofs + d; i < n_beam_dofs; i += 6)
      system.influence[d][i] = 1.; // the translations of rope-only nodes
    system.constant_force.add(common.gravity[d], system.mass_influence[d]);
  }
  if (solids)
    solids->add_influence(system.fixed, system.influence);
  system.gravity = common.gravity;
  // through the constraints: a load on a tied node or on the slave of a
  // rigid link reaches the DoFs it follows (the transposed rows, virtual
  // work); one on a supported DoF is dropped
  for (const auto &[node, f] : frame.nodal_loads)
    if (owns_node(node_cells.at(node)))
    {
      const auto &dofs = node_dofs.at(node);
      constraints.distribute_local_to_global(
          Vector<double>(f.begin(), f.end()),
          std::vector<types::global_dof_index>(dofs.begin(), dofs.end()),
          system.constant_force);
    }
  for (unsigned int i = 0; i < n; ++i)
    if (system.fixed[i])
      system.constant_force[i] = 0.;
}

void Frame::add_monitors(DiscreteSystem &system) const
{
  // a tied node, the slave of a rigid link, a supported solid node: its
  // values from the free DoFs
  const auto add = [&](MonitorPoint &m)
  {
    bool eliminated = false;
    for (const auto dof : m.dofs)
    {
      const auto *entries = constraints.get_constraint_entries(dof);
      eliminated = eliminated || (entries != nullptr && !entries->empty());
    }
    if (eliminated)
      for (const auto dof : m.dofs)
      {
        SparseRow row;
        const auto *entries = constraints.get_constraint_entries(dof);
        if (entries == nullptr)
        {
          row.dofs.push_back(dof);
          row.coefficients.push_back(1.);
        }
        else
          for (const auto &[j, a] : *entries)
          {
            row.dofs.push_back(j);
            row.coefficients.push_back(a);
          }
        m.rows.push_back(row);
      }
    system.monitors.push_back(m);
  };
  for (const auto &node : frame.monitor_nodes)
  {
    MonitorPoint m;
    m.name = node;
    for (unsigned int c = 0; c < 6; ++c)
    {
      m.labels.push_back(dof_component_labels[c]);
      m.dofs.push_back(node_dofs.at(node)[c]);
    }
    add(m);
  }
  // the solid monitors: the translations of the nearest solid node
  if (solids)
    for (const auto &node : solids->monitor_nodes())
    {
      // a point outside its solid (a typo in a coordinate) is not refused
      // (a monitor at a surface may lie just off it) but said
      if (node.distance > node.cell_size)
      {
        std::ostringstream w;
        w << "Model/Frame/Monitor nodes: monitor '" << node.name << "' is "
          << node.distance << " m from its point, farther than its solid's largest cell ("
          << node.cell_size << " m): the point lies outside the solid";
        system.warnings.push_back(w.str());
      }
      MonitorPoint m;
      m.name = node.name;
      for (unsigned int c = 0; c < 3; ++c)
      {
        m.labels.push_back(dof_component_labels[c]);
        m.dofs.push_back(node.dofs[c]);
      }
      add(m);
    }
}
} // namespace hati

// The rows a frame adds to its system: contacts and the constraint rows of
// ties and rigid links (explicit scheme).
#include <hati/model/frame.h>
#include <hati/model/frame_solids.h>
#include <hati/model/solid_tie.h>
#include <hati/model/wheel_flange.h>

namespace hati
{
namespace
{
/**
 * @p row with each entry on a DoF that @p constraints eliminate (a tied
 * node, the slave of a rigid link) replaced by its constraint line over the
 * DoFs it follows (homogeneous lines; a support's empty line keeps the
 * entry, the fixed DoFs are skipped where the rows are used). Unchanged if
 * no entry is eliminated.
 */
void expand_through_constraints(SparseRow &row,
                                const AffineConstraints<double> &constraints)
{
  bool eliminated = false;
  for (const auto dof : row.dofs)
  {
    const auto *line = constraints.get_constraint_entries(dof);
    eliminated = eliminated || (line != nullptr && !line->empty());
  }
  if (!eliminated)
    return;
  SparseRow expanded;
  const auto add = [&expanded](const types::global_dof_index j, const double a)
  {
    for (unsigned int i = 0; i < expanded.dofs.size(); ++i)
      if (expanded.dofs[i] == j)
      {
        expanded.coefficients[i] += a;
        return;
      }
    expanded.dofs.push_back(j);
    expanded.coefficients.push_back(a);
  };
  for (unsigned int k = 0; k < row.dofs.size(); ++k)
  {
    const auto *line = constraints.get_constraint_entries(row.dofs[k]);
    if (line == nullptr || line->empty())
      add(row.dofs[k], row.coefficients[k]);
    else
      for (const auto &[j, a] : *line)
        add(j, row.coefficients[k] * a);
  }
  row.dofs = expanded.dofs;
  row.coefficients = expanded.coefficients;
}
} // namespace

void Frame::add_contacts(const CommonModelParameters &common,
                         DiscreteSystem &system) const
{
  // contacts (doc/theory.md 1.2): g = gap + n . (u_node - u_other), so L has
  // n on the node's translations and -n on the other node's (none for a rigid
  // plane); a two-sided contact is two such rows with normals n and -n and
  // gaps c / 2. A node-to-node contact belongs to the explicit subdomain if
  // either node touches an explicit cell.
  for (const auto &c : frame.contacts)
  {
    std::vector<unsigned int> contact_cells = node_cells.at(c.node);
    if (!c.other_node.empty())
      contact_cells.insert(contact_cells.end(),
                           node_cells.at(c.other_node).begin(),
                           node_cells.at(c.other_node).end());
    if (!owns_node(contact_cells))
      continue;
    // two-sided without clearance: one bilateral row; with a clearance: two
    // opposite rows
    const bool bilateral = c.two_sided && c.gap == 0.;
    for (const double side : c.two_sided && !bilateral ? std::vector<double>{1., -1.}
                                                       : std::vector<double>{1.})
    {
      ContactRow row;
      row.name = c.name;
      row.bilateral = bilateral;
      for (unsigned int d = 0; d < 3; ++d)
        if (c.normal[d] != 0.)
        {
          row.dofs.push_back(node_dofs.at(c.node)[d]);
          row.coefficients.push_back(side * c.normal[d]);
          if (!c.other_node.empty())
          {
            row.dofs.push_back(node_dofs.at(c.other_node)[d]);
            row.coefficients.push_back(-side * c.normal[d]);
          }
        }
      row.initial_gap = c.two_sided ? 0.5 * c.gap : c.gap;
      row.restitution = c.restitution >= 0. ? c.restitution : common.restitution;
      // Coulomb friction (A9): the rows of the tangential relative velocity
      // t . (u_node - u_other), the same for both sides of a clearance
      if (c.friction > 0.)
      {
        row.friction = c.friction;
        for (const auto &t : contact_tangent_directions(c.normal, c.rolls))
        {
          SparseRow tangent;
          for (unsigned int d = 0; d < 3; ++d)
            if (t[d] != 0.)
            {
              tangent.dofs.push_back(node_dofs.at(c.node)[d]);
              tangent.coefficients.push_back(t[d]);
              if (!c.other_node.empty())
              {
                tangent.dofs.push_back(node_dofs.at(c.other_node)[d]);
                tangent.coefficients.push_back(-t[d]);
              }
            }
          expand_through_constraints(tangent, constraints);
          row.tangents.push_back(tangent);
        }
      }
      // at a tied node or a link's slave eliminated here (static, modal,
      // Newmark, HATI's implicit part): on the DoFs it follows
      expand_through_constraints(row, constraints);
      system.contacts.push_back(row);
    }
  }
}

void Frame::add_flanges(DiscreteSystem &system) const
{
  // the flanges whose contacts the part built holds (both or neither: a
  // tread and a flange contact of one node are owned together), by the rows
  // add_contacts() gave them
  std::vector<WheelFlange> flanges;
  for (const auto &f : frame.flanges)
  {
    std::vector<unsigned int> tread, lateral;
    for (unsigned int k = 0; k < system.contacts.size(); ++k)
    {
      if (system.contacts[k].name == f.tread_contact)
        tread.push_back(k);
      if (system.contacts[k].name == f.flange_contact)
        lateral.push_back(k);
    }
    if (tread.empty() && lateral.empty())
      continue;
    AssertThrow(tread.size() == 1 && lateral.size() == 2, ExcInternalError());
    WheelFlange w;
    w.wheel = f.name;
    w.tread_row = tread[0];
    w.flange_rows = {{lateral[0], lateral[1]}};
    w.flange_depth = f.depth;
    // D2: the flange contact's total clearance plus half the rail head
    for (const auto &c : frame.contacts)
      if (c.name == f.flange_contact)
        w.derailment_offset = c.gap + 0.5 * f.rail_head_width;
    flanges.push_back(w);
  }
  if (!flanges.empty())
    system.law_data[wheel_flanges_key] = flanges;
}

void Frame::add_link_rows(DiscreteSystem &system) const
{
  // after the contacts: ties and rigid links as bilateral constraint rows of
  // the explicit scheme (doc/theory.md 11.2), and in a decomposed model the
  // rigid links between explicit nodes in the explicit part; eliminated or
  // across the interface otherwise
  for (unsigned int k = 0; k < links.size(); ++k)
    if (links_as_rows || (selected_part == 0 && k < link_sides.size() &&
                          link_sides[k] == LinkSide::explicit_rows))
      hati::add_link_rows(links[k], system.fixed, system.contacts);
}

void Frame::place_links(const int part)
{
  // the rigid links come first in links (add_link_constraints()), then the
  // ties, whose master is a solid face
  const auto &rigid = frame.solids.rigid_links;
  link_sides.assign(links.size(), LinkSide::eliminated);
  for (unsigned int k = 0; k < rigid.size(); ++k)
  {
    const auto &l = rigid[k];
    const bool m = part >= 0 && node_explicit(l.master),
               s = part >= 0 && node_explicit(l.slave);
    const bool swap = m && !s;
    const std::string &slave = swap ? l.master : l.slave,
                      &master = swap ? l.slave : l.master;
    links[k] = {l.name,
                node_dofs.at(slave),
                rigid_link_rows(
                    node_dofs.at(master), frame.nodes.at(master), frame.nodes.at(slave))};
    link_nodes[k] = slave;
    link_sides[k] = m && s ? LinkSide::explicit_rows
                           : (m || s ? LinkSide::interface : LinkSide::eliminated);
  }
  for (unsigned int k = rigid.size(); k < links.size(); ++k)
  {
    if (part < 0)
      continue;
    const auto &tie = frame.solids.ties[k - rigid.size()];
    const int solid = solid_part(tie.face.solid);
    AssertThrow(solid >= 0,
                ExcMessage("Model/Decomposition: the solid '" + tie.face.solid +
                           "' of the tie '" + tie.name +
                           "' lies in both subdomains: put the whole solid on one side "
                           "(its name in Explicit members, or all its cells in the "
                           "Explicit region)"));
    const bool n = node_explicit(link_nodes[k]), s = solid == 0;
    link_sides[k] = n && s ? LinkSide::explicit_rows
                           : (n || s ? LinkSide::interface : LinkSide::eliminated);
  }
}

int Frame::solid_part(const std::string &solid) const
{
  // the solid cells' parts follow the beam cells' (cell_centres())
  const std::vector<unsigned int> cell_solid = solids->cell_solids();
  const unsigned int first = triangulation.n_active_cells();
  int part = -2;
  for (unsigned int c = 0; c < cell_solid.size(); ++c)
    if (solids->solid_name(cell_solid[c]) == solid && first + c < parts.size())
      part = part == -2 || part == parts[first + c] ? parts[first + c] : -1;
  return part == -2 ? 1 : part;
}

std::vector<SparseRow> Frame::interface_rows() const
{
  // U_P - R u_master = 0 (G3''): a tie of an explicit node or a rigid link
  // (turned so that the explicit node is P): C_E one DoF per row; a tie of an
  // implicit node to an explicit solid: C_E the face's B1 row
  std::vector<SparseRow> rows;
  if (parts.empty())
    return rows;
  for (unsigned int k = 0; k < links.size(); ++k)
    if (k < link_sides.size() && link_sides[k] == LinkSide::interface)
      for (unsigned int c = 0; c < 6; ++c)
      {
        SparseRow row;
        row.dofs.push_back(links[k].slave[c]);
        row.coefficients.push_back(1.);
        auto add = [&row](const types::global_dof_index j, const double a)
        {
          for (unsigned int i = 1; i < row.dofs.size(); ++i)
            if (row.dofs[i] == j)
            {
              row.coefficients[i] += a;
              return;
            }
          row.dofs.push_back(j);
          row.coefficients.push_back(a);
        };
        for (const auto &[j, a] : links[k].rows[c])
          if (!constraints.is_constrained(j))
            add(j, -a);
          else if (const auto *line = constraints.get_constraint_entries(j))
            // a master DoF eliminated in the implicit part (a chain of
            // links): its line over free DoFs (closed; a support has none)
            for (const auto &[jj, aa] : *line)
              add(jj, -a * aa);
        rows.push_back(row);
      }
  return rows;
}
} // namespace hati

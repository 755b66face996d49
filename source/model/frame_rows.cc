// The rows a frame adds to its system: contacts and the constraint rows of
// ties and rigid links (explicit scheme).
#include <hati/model/frame.h>
#include <hati/model/solid_tie.h>

namespace hati
{
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
          row.tangents.push_back(tangent);
        }
      }
      system.contacts.push_back(row);
    }
  }
}

void Frame::add_link_rows(DiscreteSystem &system) const
{
  // after the contacts: ties and rigid links as bilateral constraint rows of
  // the explicit scheme (doc/theory.md 11.2); eliminated otherwise
  if (!links_as_rows)
    return;
  for (const auto &link : links)
    hati::add_link_rows(link, system.fixed, system.contacts);
}
} // namespace hati

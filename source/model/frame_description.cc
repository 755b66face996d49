#include <deal.II/base/exceptions.h>

#include <hati/base/names.h>
#include <hati/model/frame_description.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace hati
{
namespace
{
/** Throw "Model/Frame/<entry>: <what>" unless @p ok. */
void require(const bool ok, const std::string &entry, const std::string &what)
{
  AssertThrow(ok, ExcMessage("Model/Frame/" + entry + ": " + what));
}

/**
 * The name @p name, given by @p who in @p entry, is a key of @p known:
 * "<who> names <kind> '<name>', which is not in Model/Frame/<list>" otherwise.
 */
template <class Map>
void require_known(const Map &known,
                   const std::string &name,
                   const std::string &entry,
                   const std::string &who,
                   const std::string &kind,
                   const std::string &list)
{
  require(known.count(name),
          entry,
          who + " names " + kind + " '" + name + "', which is not in Model/Frame/" +
              list);
}

/** No name twice in @p names: "<kind> '<name>' is <twice>" otherwise. */
void require_unique(const std::vector<std::string> &names,
                    const std::string &entry,
                    const std::string &kind,
                    const std::string &twice)
{
  std::set<std::string> seen;
  for (const auto &n : names)
    require(seen.insert(n).second, entry, kind + " '" + n + "' is " + twice);
}

/**
 * Every name the description defines or refers to follows the rule of
 * check_name() (issue #19, finding 4): checked first, so that a name that
 * cannot be written is refused as such.
 */
void validate_names(const FrameDescription &d)
{
  const std::string frame = "Model/Frame/";
  for (const auto &n : d.node_order)
    check_name(n, frame + "Nodes", "node", NameKind::node);
  for (const auto &[name, m] : d.materials)
    check_name(name, frame + "Materials", "material");
  for (const auto &[name, s] : d.sections)
    check_name(name, frame + "Sections", "section");
  for (const auto &m : d.members)
  {
    check_name(m.name, frame + "Members", "member");
    for (const auto &n :
         m.path.empty() ? std::vector<std::string>{m.start, m.end} : m.path)
      check_name(n, frame + "Members", "node", NameKind::node);
  }
  for (const auto &p : d.point_masses)
    check_name(p.node, frame + "Point masses", "node", NameKind::node);
  for (const auto &s : d.supports)
    check_name(s.node, frame + "Supports", "node", NameKind::node);
  for (const auto &n : d.hinged_joints)
    check_name(n, frame + "Hinged joints", "node", NameKind::node);
  for (const auto &[node, load] : d.nodal_loads)
    check_name(node, frame + "Nodal loads", "node", NameKind::node);
  for (const auto &c : d.contacts)
  {
    check_name(c.name, frame + "Contacts", "contact");
    check_name(c.node, frame + "Contacts", "node", NameKind::node);
    if (!c.other_node.empty())
      check_name(c.other_node, frame + "Contacts", "node", NameKind::node);
  }
  for (const auto &r : d.ropes)
  {
    check_name(r.name, frame + "Ropes", "rope");
    check_name(r.node, frame + "Ropes", "node", NameKind::node);
    check_name(r.other_node, frame + "Ropes", "node", NameKind::node);
  }
  for (const auto &n : d.monitor_nodes)
    check_name(n, frame + "Monitor nodes", "monitor", NameKind::node);
  for (const auto &m : d.section_force_members)
    check_name(m, frame + "Section force members", "member");
}

/** The nodes, materials and sections on their own. */
void validate_parts(const FrameDescription &d)
{
  require_unique(d.node_order, "Nodes", "node", "defined twice");
  for (const auto &n : d.node_order)
    require(d.nodes.count(n), "Nodes", "node '" + n + "' has no position");
  require(d.node_order.size() == d.nodes.size(),
          "Nodes",
          "a node is missing from the order of the nodes");
  for (const auto &[name, m] : d.materials)
    require(m.E > 0. && m.G > 0. && m.rho > 0.,
            "Materials",
            "item '" + name + "' needs E > 0, -1 < nu < 0.5 and rho > 0");
  for (const auto &[name, s] : d.sections)
    require(s.A > 0. && s.Iy > 0. && s.Iz > 0. && s.J > 0.,
            "Sections",
            "item '" + name + "' needs A, Iy, Iz and J > 0");
}

/**
 * The members: names, the nodes, section and material they name, their
 * lengths; returns the nodes that are ends of a member or of a mesh element.
 */
std::set<std::string> validate_members(const FrameDescription &d)
{
  require(!d.members.empty(), "Members", "no member is defined");
  std::vector<std::string> names;
  for (const auto &m : d.members)
    names.push_back(m.name);
  require_unique(names, "Members", "member", "defined twice");
  std::set<std::string> used_nodes;
  for (const auto &m : d.members)
  {
    const std::string member = "member '" + m.name + "'";
    for (const auto &n :
         m.path.empty() ? std::vector<std::string>{m.start, m.end} : m.path)
    {
      require_known(d.nodes, n, "Members", member, "node", "Nodes");
      used_nodes.insert(n);
    }
    require_known(d.sections, m.section, "Members", member, "section", "Sections");
    require_known(d.materials, m.material, "Members", member, "material", "Materials");
    require(m.n_elements >= 1 && (m.path.empty() || m.path.size() == m.n_elements + 1),
            "Members",
            member + ": the number of elements does not match its nodes");
    const Point<3> &a = d.nodes.at(m.start), &b = d.nodes.at(m.end);
    require(a.distance(b) > 0.,
            "Members",
            member + " has zero length (both ends at the same point)");
    require(std::isfinite(a.square()) && std::isfinite(b.square()) &&
                std::isfinite(a.distance_square(b)),
            "Members",
            member + ": the coordinates of its nodes '" + m.start + "', '" + m.end +
                "' overflow (not finite when squared): node coordinates too large");
    for (unsigned int i = 0; i + 1 < m.path.size(); ++i)
      require(d.nodes.at(m.path[i]).distance(d.nodes.at(m.path[i + 1])) > 0.,
              "Mesh file",
              member + " has a zero-length element at node '" + m.path[i] + "'");
  }
  return used_nodes;
}

/**
 * The data at nodes: every node they name is a node of a member (@p used),
 * or for point masses, monitors and nodal loads a node only a rope holds
 * (@p held: @p used and those).
 */
void validate_nodal_data(const FrameDescription &d,
                         const std::set<std::string> &used,
                         const std::set<std::string> &held)
{
  auto check_node = [&](const std::string &n, const std::string &entry)
  {
    require(held.count(n),
            entry,
            "node '" + n + "' is not an end of any member in Model/Frame/Members");
  };
  auto check_member_node = [&](const std::string &n, const std::string &entry)
  {
    require(used.count(n),
            entry,
            "node '" + n + "' is not an end of any member in Model/Frame/Members" +
                (held.count(n) ? " (a node held only by a rope takes no support or "
                                 "hinge)"
                               : ""));
  };
  for (const auto &p : d.point_masses)
  {
    check_node(p.node, "Point masses");
    require(p.mass >= 0. && p.rotary_inertia[0] >= 0. && p.rotary_inertia[1] >= 0. &&
                p.rotary_inertia[2] >= 0.,
            "Point masses",
            "node '" + p.node +
                "': the mass (kg) and the rotary inertias (kg m^2) must be >= 0");
  }
  std::vector<std::string> supported;
  for (const auto &s : d.supports)
  {
    supported.push_back(s.node);
    for (const double k : s.stiffness)
      require(k == -1. || k == 0. || (k > 0. && std::isfinite(k)),
              "Supports",
              "node '" + s.node + "': a spring stiffness must be > 0");
  }
  require_unique(supported, "Supports", "node", "listed twice");
  for (const auto &s : d.supports)
    check_member_node(s.node, "Supports");
  for (const auto &n : d.hinged_joints)
    check_member_node(n, "Hinged joints");
  for (const auto &n : d.monitor_nodes)
    check_node(n, "Monitor nodes");
  for (const auto &l : d.nodal_loads)
    check_node(l.first, "Nodal loads");
}

/**
 * The ropes: unique names, the hook point a member node, the load a node
 * (of a member or held by the rope alone), two different nodes, the
 * stiffness and the rest length in range.
 */
void validate_ropes(const FrameDescription &d, const std::set<std::string> &used)
{
  std::vector<std::string> names;
  for (const auto &r : d.ropes)
    names.push_back(r.name);
  require_unique(names, "Ropes", "rope", "defined twice");
  for (const auto &r : d.ropes)
  {
    const std::string rope = "rope '" + r.name + "'";
    require(used.count(r.node),
            "Ropes",
            rope + ": its hook point '" + r.node +
                "' is not an end of any member in Model/Frame/Members");
    require_known(d.nodes, r.other_node, "Ropes", rope, "node", "Nodes");
    require(
        r.other_node != r.node, "Ropes", rope + " names the node '" + r.node + "' twice");
    require(r.stiffness > 0. && r.stiffness <= FrameDescription::max_rope_stiffness,
            "Ropes",
            rope + ": the stiffness must be > 0 and at most 1e12 N/m");
    const double distance = d.nodes.at(r.node).distance(d.nodes.at(r.other_node));
    require(distance > 0.,
            "Ropes",
            rope + ": its nodes '" + r.node + "' and '" + r.other_node +
                "' are at the same point");
    require(r.rest_length < 0. ? true
                               : (r.rest_length > 0. && std::isfinite(r.rest_length)),
            "Ropes",
            rope + ": the rest length must be > 0 (m)");
    // a load that only ropes hold has no mass of a member: it needs its own
    bool has_mass = used.count(r.other_node) > 0;
    for (const auto &p : d.point_masses)
      has_mass = has_mass || (p.node == r.other_node && p.mass > 0.);
    require(has_mass,
            "Ropes",
            rope + ": its load '" + r.other_node +
                "' is held only by ropes and has no mass: give it a point mass > 0 "
                "in Model/Frame/Point masses");
  }
}

/** The contacts: their nodes, normals, gaps and restitution coefficients. */
void validate_contacts(const FrameDescription &d, const std::set<std::string> &held)
{
  for (const auto &c : d.contacts)
  {
    const std::string contact = "contact '" + c.name + "'";
    require(c.other_node != c.node,
            "Contacts",
            contact + " names the node '" + c.node + "' twice");
    for (const auto &n : {c.node, c.other_node})
      require(n.empty() || held.count(n),
              "Contacts",
              "node '" + n + "' is not an end of any member in Model/Frame/Members");
    require(c.normal.norm() > 0., "Contacts", contact + " has a zero normal");
    require(c.gap >= 0.,
            "Contacts",
            contact + ": the " + (c.two_sided ? "clearance" : "gap") +
                " must be >= 0 (m)");
    require(c.restitution <= 1.,
            "Contacts",
            contact + ": the restitution coefficient must be in [0, 1]");
    require(std::isfinite(c.friction) && c.friction >= 0.,
            "Contacts",
            contact + ": the friction coefficient mu must be a finite number >= 0");
    require(c.rolls < 0 || !contact_tangent_directions(c.normal, c.rolls).empty(),
            "Contacts",
            contact + ": the rolling axis (rolls=) lies along the contact normal; it "
                      "must lie in the contact plane");
  }
}

/**
 * The flanges: each names a one-sided tread contact and a two-sided flange
 * contact with a clearance of the same node, a depth > 0 and a rail head
 * width >= 0.
 */
void validate_flanges(const FrameDescription &d)
{
  std::set<std::string> names;
  for (const auto &f : d.flanges)
  {
    const std::string flange = "flange '" + f.name + "'";
    require(names.insert(f.name).second, "Flanges", flange + " is given twice");
    const auto find = [&](const std::string &contact)
    {
      for (const auto &c : d.contacts)
        if (c.name == contact)
          return &c;
      return static_cast<const FrameDescription::NodeContact *>(nullptr);
    };
    const auto *tread = find(f.tread_contact), *lateral = find(f.flange_contact);
    require(tread != nullptr,
            "Flanges",
            flange + ": no contact named '" + f.tread_contact +
                "' in Model/Frame/Contacts (the tread contact)");
    require(lateral != nullptr,
            "Flanges",
            flange + ": no contact named '" + f.flange_contact +
                "' in Model/Frame/Contacts (the flange contact)");
    require(!tread->two_sided,
            "Flanges",
            flange + ": the tread contact '" + f.tread_contact +
                "' must be one-sided (its gap is the uplift)");
    require(lateral->two_sided && lateral->gap > 0.,
            "Flanges",
            flange + ": the flange contact '" + f.flange_contact +
                "' must be two-sided with a clearance > 0");
    require(tread->node == lateral->node,
            "Flanges",
            flange + ": the tread and flange contacts act on different nodes ('" +
                tread->node + "', '" + lateral->node + "'): give one wheel's");
    require(std::isfinite(f.depth) && f.depth > 0.,
            "Flanges",
            flange + ": the flange depth must be > 0 (m)");
    require(std::isfinite(f.rail_head_width) && f.rail_head_width >= 0.,
            "Flanges",
            flange + ": the rail head width must be >= 0 (m)");
  }
}
} // namespace

std::vector<Tensor<1, 3>> contact_tangent_directions(const Tensor<1, 3> &normal,
                                                     const int rolls)
{
  const Tensor<1, 3> n = normal / normal.norm();
  if (rolls >= 0)
  {
    Tensor<1, 3> axis;
    axis[rolls] = 1.;
    const Tensor<1, 3> t = cross_product_3d(n, axis);
    if (t.norm() < 1e-12)
      return {};
    return {t / t.norm()};
  }
  unsigned int least = 0;
  for (unsigned int d = 1; d < 3; ++d)
    if (std::abs(n[d]) < std::abs(n[least]))
      least = d;
  Tensor<1, 3> t1;
  t1[least] = 1.;
  t1 -= (t1 * n) * n;
  t1 /= t1.norm();
  return {t1, cross_product_3d(n, t1)};
}

void FrameDescription::add_node(const std::string &name, const Point<3> &x)
{
  nodes[name] = x;
  node_order.push_back(name);
}

std::vector<std::string> FrameDescription::rope_only_nodes() const
{
  std::set<std::string> member_nodes;
  for (const auto &m : members)
    for (const auto &n :
         m.path.empty() ? std::vector<std::string>{m.start, m.end} : m.path)
      member_nodes.insert(n);
  std::vector<std::string> r;
  for (const auto &rope : ropes)
    if (!member_nodes.count(rope.other_node) &&
        std::find(r.begin(), r.end(), rope.other_node) == r.end())
      r.push_back(rope.other_node);
  return r;
}

namespace
{
/**
 * Solids, ties, solid supports, rigid links, cuts and solid monitors:
 * names, materials, the solids and nodes they name; a tied or slave node is a member node
 * that no support fixes, tied or slaved once.
 */
void validate_solids(const FrameDescription &d, const std::set<std::string> &used_nodes)
{
  const auto &S = d.solids;
  std::map<std::string, const SolidDescription::Solid *> solids;
  for (const auto &s : S.solids)
  {
    check_name(s.name, "Model/Frame/Solids", "solid");
    require(solids.emplace(s.name, &s).second,
            "Solids",
            "solid '" + s.name + "' is defined twice");
    require_known(d.materials,
                  s.material,
                  "Solids",
                  "solid '" + s.name + "'",
                  "material",
                  "Materials");
  }
  std::set<std::string> fixed, bound, tie_names, link_names;
  for (const auto &s : d.supports)
    for (const double k : s.stiffness)
      if (k == 0.)
        fixed.insert(s.node);
  for (const auto &t : S.ties)
  {
    check_name(t.name, "Model/Frame/Ties", "tie");
    require(
        tie_names.insert(t.name).second, "Ties", "tie '" + t.name + "' is defined twice");
    require_known(used_nodes, t.node, "Ties", "tie '" + t.name + "'", "node", "Members");
    require_known(
        solids, t.face.solid, "Ties", "tie '" + t.name + "'", "solid", "Solids");
    require(!fixed.count(t.node),
            "Ties",
            "tie '" + t.name + "': node '" + t.node +
                "' is already supported (Model/Frame/Supports): a tied node follows its "
                "face");
    require(bound.insert(t.node).second,
            "Ties",
            "tie '" + t.name + "': node '" + t.node + "' is tied twice");
  }
  for (const auto &f : S.supports)
    require_known(solids, f.solid, "Solid supports", "a support", "solid", "Solids");
  std::set<std::string> cut_names,
      monitor_names(d.monitor_nodes.begin(), d.monitor_nodes.end());
  for (const auto &c : S.cuts)
  {
    check_name(c.name, "Model/Frame/Solid cuts", "cut");
    require_known(
        solids, c.solid, "Solid cuts", "cut '" + c.name + "'", "solid", "Solids");
    require(cut_names.insert(c.name).second,
            "Solid cuts",
            "cut '" + c.name + "' is defined twice");
  }
  for (const auto &m : S.monitors)
  {
    check_name(m.name, "Model/Frame/Monitor nodes", "monitor", NameKind::node);
    require_known(
        solids, m.solid, "Monitor nodes", "monitor '" + m.name + "'", "solid", "Solids");
    require(monitor_names.insert(m.name).second,
            "Monitor nodes",
            "monitor '" + m.name + "' is listed twice");
  }
  for (const auto &l : S.rigid_links)
  {
    check_name(l.name, "Model/Frame/Rigid links", "rigid link");
    const std::string who = "rigid link '" + l.name + "'";
    require(link_names.insert(l.name).second, "Rigid links", who + " is defined twice");
    require_known(used_nodes, l.master, "Rigid links", who, "node", "Members");
    require_known(used_nodes, l.slave, "Rigid links", who, "node", "Members");
    require(l.master != l.slave, "Rigid links", who + ": master and slave are one node");
    require(!fixed.count(l.slave),
            "Rigid links",
            who + ": slave node '" + l.slave + "' is supported (Model/Frame/Supports)");
    require(bound.insert(l.slave).second,
            "Rigid links",
            who + ": node '" + l.slave + "' is already tied or the slave of a link");
  }
  // a chain of links is resolved; a closed one (each node the slave of the
  // next) has no master and would not end
  std::map<std::string, std::string> master_of;
  for (const auto &l : S.rigid_links)
    master_of[l.slave] = l.master;
  for (const auto &l : S.rigid_links)
  {
    std::string chain = "'" + l.slave + "'", n = l.master;
    for (std::size_t k = 0; k <= master_of.size() && n != l.slave; ++k)
    {
      chain += " -> '" + n + "'";
      const auto up = master_of.find(n);
      if (up == master_of.end())
        break;
      n = up->second;
    }
    require(n != l.slave,
            "Rigid links",
            "rigid link '" + l.name + "': its slave follows itself through the links (" +
                chain + " -> '" + l.slave + "'): a closed chain has no master");
  }
}
} // namespace

void FrameDescription::validate() const
{
  validate_names(*this);
  validate_parts(*this);
  const std::set<std::string> used_nodes = validate_members(*this);
  validate_ropes(*this, used_nodes);
  std::set<std::string> held = used_nodes;
  for (const auto &n : rope_only_nodes())
    held.insert(n);
  validate_nodal_data(*this, used_nodes, held);
  validate_contacts(*this, held);
  validate_flanges(*this);
  validate_solids(*this, used_nodes);
  std::set<std::string> member_names;
  for (const auto &m : members)
    member_names.insert(m.name);
  for (const auto &m : section_force_members)
    require(
        member_names.count(m), "Section force members", "no member named '" + m + "'");
  for (const auto &c : solids.cuts)
    require(!member_names.count(c.name),
            "Solid cuts",
            "cut '" + c.name +
                "' has the name of a member (section_forces.csv names both by it)");
}
} // namespace hati

#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>

#include <hati/model/frame.h>
#include <hati/model/gmsh_frame_reader.h>
#include <hati/model/memory_estimate.h>

#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace hati
{
namespace
{
const char *const component_labels[6] = {"x", "y", "z", "rx", "ry", "rz"};

/** Largest number of elements of one member (-). */
constexpr double max_elements_per_member = 1e7;

/** One item "name: v1, v2, ..." of a list entry. */
struct Item
{
  std::string name;
  std::vector<std::string> values;
};

/** Split `name: v, v; name: v, v` into items; @p entry names the parameter in errors. */
std::vector<Item> parse_items(const std::string &text, const std::string &entry)
{
  std::vector<Item> items;
  for (const std::string &raw : Utilities::split_string_list(text, ';'))
  {
    const std::string item = Utilities::trim(raw);
    if (item.empty())
      continue;
    const auto colon = item.find(':');
    AssertThrow(colon != std::string::npos && colon > 0,
                ExcMessage("Model/Frame/" + entry + ": item '" + item +
                           "' is not of the form 'name: values'"));
    Item it;
    it.name = Utilities::trim(item.substr(0, colon));
    for (const std::string &v : Utilities::split_string_list(item.substr(colon + 1), ','))
      it.values.push_back(Utilities::trim(v));
    if (it.values.size() == 1 && it.values[0].empty())
      it.values.clear();
    items.push_back(it);
  }
  return items;
}

/** Whether @p value is a finite number (a node named like a number is read as one). */
bool is_number(const std::string &value)
{
  char *end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  return !value.empty() && end != nullptr && *end == '\0' && std::isfinite(x);
}

double to_number(const std::string &value, const std::string &entry, const Item &item)
{
  char *end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  AssertThrow(!value.empty() && end != nullptr && *end == '\0' && std::isfinite(x),
              ExcMessage("Model/Frame/" + entry + ": item '" + item.name + "': '" +
                         value + "' is not a number"));
  return x;
}

void expect_values(const Item &item,
                   const std::string &entry,
                   const std::vector<unsigned int> &counts,
                   const std::string &expected)
{
  for (const unsigned int c : counts)
    if (item.values.size() == c)
      return;
  AssertThrow(false,
              ExcMessage("Model/Frame/" + entry + ": item '" + item.name + "' has " +
                         std::to_string(item.values.size()) + " values, expected " +
                         expected));
}
} // namespace

void Frame::Parameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Nodes",
                    "",
                    Patterns::Anything(),
                    "Named nodes, 'name: x, y, z; ...' (m, global axes).");
  prm.declare_entry(
      "Materials",
      "steel: 2.1e11, 0.3, 7850",
      Patterns::Anything(),
      "Named materials, 'name: E, nu, rho; ...' with Young's modulus E (Pa), "
      "Poisson's ratio nu (-, G = E / (2 (1 + nu))) and density rho (kg/m^3).");
  prm.declare_entry(
      "Sections",
      "",
      Patterns::Anything(),
      "Named cross-sections, 'name: kind, values; ...' with kind 'rectangle, b, h' "
      "(solid, width b along local y, height h along local z, m), 'box, b, h, t_web, "
      "t_flange' (thin-walled closed box, m) or 'general, A, Iy, Iz, J, Asy, Asz' (m^2, "
      "m^4, m^4, m^4, m^2, m^2; Iy = int z^2 dA for bending about local y; shear areas "
      "Asy, Asz, 0 for no shear deformation).");
  prm.declare_entry(
      "Members",
      "",
      Patterns::Anything(),
      "Named members, 'name: start node, end node, section, material, number of "
      "elements[, yx, yy, yz]; ...'. Local x runs from the start to the end node; the "
      "optional vector (global axes) fixes the section's local y axis (its part "
      "orthogonal to the member); default: global Y, or global X for members parallel "
      "to Y.");
  prm.declare_entry(
      "Mesh file",
      "",
      Patterns::Anything(),
      "Optional Gmsh mesh (ASCII format 2.2 or 4.1, path relative to the "
      "current directory) of 2-node line elements: every named physical curve "
      "is a member (one element per line element), named physical points name "
      "nodes (for supports, loads, monitors); other nodes are named '@<tag>'. "
      "Give each member's section and material in 'Member properties'. Members "
      "and nodes of the Members and Nodes entries are added to those of the "
      "file.");
  prm.declare_entry(
      "Member properties",
      "",
      Patterns::Anything(),
      "Section, material and optional local-y vector of the members read from "
      "the Mesh file, 'member: section, material[, yx, yy, yz]; ...'.");
  prm.declare_entry(
      "Point masses",
      "",
      Patterns::Anything(),
      "Nodal masses, 'node: m[, Ixx, Iyy, Izz]; ...' (kg, kg m^2 about global "
      "axes through the node).");
  prm.declare_entry(
      "Supports",
      "",
      Patterns::Anything(),
      "Supports, 'node: clamped | pinned | c1, c2, c3, c4, c5, c6; ...' with one code "
      "per "
      "DoF ux, uy, uz, rx, ry, rz: 'fixed', 'free' or a spring stiffness (N/m for "
      "translations, N m/rad for rotations). 'pinned' fixes the translations only.");
  prm.declare_entry(
      "Hinged joints",
      "",
      Patterns::Anything(),
      "Nodes where the members are hinged, 'node, node, ...': the first "
      "member at the node keeps the node's rotations, the others share only "
      "the translations. Joints are rigid by default.");
  prm.declare_entry(
      "Contacts",
      "",
      Patterns::Anything(),
      "Unilateral contacts (CD-Lagrange only), 'name: node, nx, ny, nz, gap[, e][, "
      "two-sided]; ...' for a node on a rigid plane (moving with the base) or 'name: "
      "node, other node, nx, ny, nz, gap[, e][, two-sided]; ...' for a node against "
      "another node (recognised by the second value naming a node). n (global axes, "
      "normalised) points from the obstacle (plane or other node) to the node; the gap "
      "is g = gap + n . (u_node - u_other) (m, >= 0) and the impulse pushes the two "
      "apart along n; e is the restitution coefficient (-, default "
      "Contact/Restitution coefficient). With 'two-sided' the gap value is the total "
      "clearance c (m, >= 0, e.g. a wheel flange's lateral play): two rows with "
      "normals n and -n and initial gaps c / 2, both under the one name. Rows sharing "
      "a name are summed in contacts.csv. With Method = HATI a node-to-node contact "
      "is explicit if either node touches an explicit cell.");
  prm.declare_entry(
      "Nodal loads",
      "",
      Patterns::Anything(),
      "Constant nodal loads, 'node: Fx, Fy, Fz[, Mx, My, Mz]; ...' (N, N m, "
      "global axes).");
  prm.declare_entry("Monitor nodes",
                    "",
                    Patterns::Anything(),
                    "Nodes written to history.csv, 'node, node, ...' (columns "
                    "NODE.ux ... NODE.urz, NODE.vx ... NODE.vrz).");
  prm.declare_entry("Section force members",
                    "",
                    Patterns::Anything(),
                    "Members whose section forces are written to section_forces.csv at "
                    "every history row, 'member, member, ...'.");
}

FrameSection Frame::Parameters::parse_section(const std::string &text,
                                              const std::string &where)
{
  std::vector<std::string> values;
  for (const std::string &v : Utilities::split_string_list(text, ','))
    values.push_back(Utilities::trim(v));
  AssertThrow(!values.empty() && !values[0].empty(),
              ExcMessage(where + " has no kind (rectangle, box or general)"));
  const std::string kind = values[0];
  std::vector<double> v;
  for (unsigned int i = 1; i < values.size(); ++i)
  {
    char *end = nullptr;
    const double x = std::strtod(values[i].c_str(), &end);
    AssertThrow(!values[i].empty() && *end == '\0' && std::isfinite(x),
                ExcMessage(where + ": '" + values[i] + "' is not a number"));
    AssertThrow(x >= 0., ExcMessage(where + " has a negative value"));
    v.push_back(x);
  }
  auto expect = [&](const unsigned int count, const std::string &form)
  {
    AssertThrow(values.size() == count,
                ExcMessage(where + " has " + std::to_string(values.size()) +
                           " values, expected " + form));
  };
  FrameSection s;
  if (kind == "rectangle")
  {
    expect(3, "'rectangle, b, h'");
    AssertThrow(v[0] > 0. && v[1] > 0.,
                ExcMessage(where + ": a rectangle needs b > 0 and h > 0 (m)"));
    s = FrameSection::rectangle(v[0], v[1]);
  }
  else if (kind == "box")
  {
    expect(5, "'box, b, h, t_web, t_flange'");
    AssertThrow(v[0] > 0. && v[1] > 0. && v[2] > 0. && v[3] > 0. && 2. * v[2] < v[0] &&
                    2. * v[3] < v[1],
                ExcMessage(where +
                           ": a box needs b, h, t_web, t_flange > 0 (m), 2 t_web < b "
                           "and 2 t_flange < h"));
    s = FrameSection::box(v[0], v[1], v[2], v[3]);
  }
  else if (kind == "general")
  {
    expect(7, "'general, A, Iy, Iz, J, Asy, Asz'");
    s.A = v[0];
    s.Iy = v[1];
    s.Iz = v[2];
    s.J = v[3];
    s.shear_area_y = v[4];
    s.shear_area_z = v[5];
  }
  else
    AssertThrow(false,
                ExcMessage(where + ": unknown kind '" + kind +
                           "', expected rectangle, box or general"));
  AssertThrow(s.A > 0. && s.Iy > 0. && s.Iz > 0. && s.J > 0.,
              ExcMessage(where + " needs A, Iy, Iz and J > 0"));
  return s;
}

void Frame::Parameters::parse_parameters(ParameterHandler &prm)
{
  for (const Item &it : parse_items(prm.get("Nodes"), "Nodes"))
  {
    expect_values(it, "Nodes", {3}, "3 (x, y, z)");
    AssertThrow(nodes.count(it.name) == 0,
                ExcMessage("Model/Frame/Nodes: node '" + it.name + "' is defined twice"));
    nodes[it.name] = Point<3>(to_number(it.values[0], "Nodes", it),
                              to_number(it.values[1], "Nodes", it),
                              to_number(it.values[2], "Nodes", it));
    node_order.push_back(it.name);
  }
  for (const Item &it : parse_items(prm.get("Materials"), "Materials"))
  {
    expect_values(it, "Materials", {3}, "3 (E, nu, rho)");
    FrameMaterial m;
    m.E = to_number(it.values[0], "Materials", it);
    const double nu = to_number(it.values[1], "Materials", it);
    m.rho = to_number(it.values[2], "Materials", it);
    AssertThrow(m.E > 0. && nu > -1. && nu < 0.5 && m.rho > 0.,
                ExcMessage("Model/Frame/Materials: item '" + it.name +
                           "' needs E > 0, -1 < nu < 0.5 and rho > 0"));
    m.G = m.E / (2. * (1. + nu));
    AssertThrow(
        materials.count(it.name) == 0,
        ExcMessage("Model/Frame/Materials: material '" + it.name + "' is defined twice"));
    materials[it.name] = m;
  }
  for (const Item &it : parse_items(prm.get("Sections"), "Sections"))
  {
    AssertThrow(
        sections.count(it.name) == 0,
        ExcMessage("Model/Frame/Sections: section '" + it.name + "' is defined twice"));
    std::string text;
    for (unsigned int i = 0; i < it.values.size(); ++i)
      text += (i ? ", " : "") + it.values[i];
    sections[it.name] =
        parse_section(text, "Model/Frame/Sections: item '" + it.name + "'");
  }
  for (const Item &it : parse_items(prm.get("Members"), "Members"))
  {
    expect_values(it,
                  "Members",
                  {5, 8},
                  "5 or 8 (start, end, section, material, elements[, yx, yy, yz])");
    Member m;
    m.name = it.name;
    m.start = it.values[0];
    m.end = it.values[1];
    m.section = it.values[2];
    m.material = it.values[3];
    const double ne = to_number(it.values[4], "Members", it);
    AssertThrow(ne >= 1. && ne == std::floor(ne) && ne <= max_elements_per_member,
                ExcMessage("Model/Frame/Members: member '" + it.name +
                           "': the number of elements must be an integer from 1 to " +
                           std::to_string(static_cast<long>(max_elements_per_member)) +
                           ", got " + it.values[4]));
    m.n_elements = static_cast<unsigned int>(ne);
    if (it.values.size() == 8)
    {
      for (unsigned int d = 0; d < 3; ++d)
        m.y_reference[d] = to_number(it.values[5 + d], "Members", it);
      AssertThrow(m.y_reference.norm() > 0.,
                  ExcMessage("Model/Frame/Members: member '" + it.name +
                             "': the section orientation vector (yx, yy, yz) is zero"));
    }
    members.push_back(m);
  }
  const std::string mesh_file = Utilities::trim(prm.get("Mesh file"));
  if (!mesh_file.empty())
  {
    const GmshFrame mesh = read_gmsh_frame(mesh_file);
    for (const auto &[name, x] : mesh.nodes)
    {
      AssertThrow(nodes.count(name) == 0 || nodes[name].distance(x) < 1e-12,
                  ExcMessage("Model/Frame/Mesh file: node '" + name +
                             "' is also in Model/Frame/Nodes at another position"));
      if (nodes.count(name) == 0)
        node_order.push_back(name);
      nodes[name] = x;
    }
    std::map<std::string, Item> properties;
    for (const Item &it : parse_items(prm.get("Member properties"), "Member properties"))
    {
      expect_values(
          it, "Member properties", {2, 5}, "2 or 5 (section, material[, yx, yy, yz])");
      AssertThrow(mesh.members.count(it.name),
                  ExcMessage("Model/Frame/Member properties: the mesh file '" +
                             mesh_file + "' has no member (physical curve) named '" +
                             it.name + "'"));
      properties[it.name] = it;
    }
    for (const auto &[name, path] : mesh.members)
    {
      AssertThrow(
          properties.count(name),
          ExcMessage("Model/Frame/Member properties: no section and material for the "
                     "member '" +
                     name + "' of the mesh file '" + mesh_file + "'"));
      const Item &it = properties[name];
      Member m;
      m.name = name;
      m.path = path;
      m.start = path.front();
      m.end = path.back();
      m.section = it.values[0];
      m.material = it.values[1];
      m.n_elements = path.size() - 1;
      if (it.values.size() == 5)
        for (unsigned int d = 0; d < 3; ++d)
          m.y_reference[d] = to_number(it.values[2 + d], "Member properties", it);
      members.push_back(m);
    }
  }
  for (const Item &it : parse_items(prm.get("Point masses"), "Point masses"))
  {
    expect_values(it, "Point masses", {1, 4}, "1 or 4 (m[, Ixx, Iyy, Izz])");
    PointMassData p;
    p.node = it.name;
    p.mass = to_number(it.values[0], "Point masses", it);
    if (it.values.size() == 4)
      for (unsigned int d = 0; d < 3; ++d)
        p.rotary_inertia[d] = to_number(it.values[1 + d], "Point masses", it);
    AssertThrow(p.mass >= 0. && p.rotary_inertia[0] >= 0. && p.rotary_inertia[1] >= 0. &&
                    p.rotary_inertia[2] >= 0.,
                ExcMessage("Model/Frame/Point masses: node '" + it.name +
                           "': the mass (kg) and the rotary inertias (kg m^2) must be "
                           ">= 0"));
    point_masses.push_back(p);
  }
  for (const Item &it : parse_items(prm.get("Supports"), "Supports"))
  {
    for (const auto &other : supports)
      AssertThrow(
          other.node != it.name,
          ExcMessage("Model/Frame/Supports: node '" + it.name + "' is listed twice"));
    Support s;
    s.node = it.name;
    if (it.values.size() == 1 && it.values[0] == "clamped")
      s.stiffness = {{0., 0., 0., 0., 0., 0.}};
    else if (it.values.size() == 1 && it.values[0] == "pinned")
      s.stiffness = {{0., 0., 0., -1., -1., -1.}};
    else
    {
      expect_values(it, "Supports", {6}, "'clamped', 'pinned' or 6 codes");
      for (unsigned int c = 0; c < 6; ++c)
      {
        const std::string &code = it.values[c];
        if (code == "fixed")
          s.stiffness[c] = 0.;
        else if (code == "free")
          s.stiffness[c] = -1.;
        else
        {
          s.stiffness[c] = to_number(code, "Supports", it);
          AssertThrow(s.stiffness[c] > 0.,
                      ExcMessage("Model/Frame/Supports: node '" + it.name +
                                 "': a spring stiffness must be > 0"));
        }
      }
    }
    supports.push_back(s);
  }
  auto names = [](const std::string &text)
  {
    std::vector<std::string> r;
    for (const auto &s : Utilities::split_string_list(text, ','))
      if (!Utilities::trim(s).empty())
        r.push_back(Utilities::trim(s));
    return r;
  };
  hinged_joints = names(prm.get("Hinged joints"));
  monitor_nodes = names(prm.get("Monitor nodes"));
  section_force_members = names(prm.get("Section force members"));
  for (const Item &it : parse_items(prm.get("Nodal loads"), "Nodal loads"))
  {
    expect_values(it, "Nodal loads", {3, 6}, "3 or 6 (Fx, Fy, Fz[, Mx, My, Mz])");
    std::array<double, 6> f{{0., 0., 0., 0., 0., 0.}};
    for (unsigned int c = 0; c < it.values.size(); ++c)
      f[c] = to_number(it.values[c], "Nodal loads", it);
    nodal_loads[it.name] = f;
  }

  for (const Item &it : parse_items(prm.get("Contacts"), "Contacts"))
  {
    // forms: node, nx, ny, nz, gap[, e][, two-sided] (rigid plane) or
    // node, other node, nx, ny, nz, gap[, e][, two-sided] (node to node)
    std::vector<std::string> v = it.values;
    NodeContact c;
    c.name = it.name;
    if (!v.empty() && v.back() == "two-sided")
    {
      c.two_sided = true;
      v.pop_back();
    }
    const bool node_to_node = v.size() >= 2 && nodes.count(v[1]) > 0 && !is_number(v[1]);
    const unsigned int first = node_to_node ? 2 : 1; // index of nx
    AssertThrow(v.size() == first + 4 || v.size() == first + 5,
                ExcMessage("Model/Frame/Contacts: item '" + it.name + "' has " +
                           std::to_string(it.values.size()) +
                           " values, expected 'node, nx, ny, nz, gap[, e][, two-sided]' "
                           "or 'node, other node, nx, ny, nz, gap[, e][, two-sided]'"));
    c.node = v[0];
    if (node_to_node)
    {
      c.other_node = v[1];
      AssertThrow(c.other_node != c.node,
                  ExcMessage("Model/Frame/Contacts: contact '" + it.name +
                             "' names the node '" + c.node + "' twice"));
    }
    else
      AssertThrow(is_number(v[1]),
                  ExcMessage("Model/Frame/Contacts: contact '" + it.name + "': '" + v[1] +
                             "' is neither a node of Model/Frame/Nodes nor a number "
                             "(the normal's nx)"));
    for (unsigned int d = 0; d < 3; ++d)
      c.normal[d] = to_number(v[first + d], "Contacts", it);
    AssertThrow(
        c.normal.norm() > 0.,
        ExcMessage("Model/Frame/Contacts: contact '" + it.name + "' has a zero normal"));
    c.normal /= c.normal.norm();
    c.gap = to_number(v[first + 3], "Contacts", it);
    AssertThrow(c.gap >= 0.,
                ExcMessage("Model/Frame/Contacts: contact '" + it.name + "': the " +
                           (c.two_sided ? "clearance" : "gap") +
                           " must be >= 0 (m), got " + v[first + 3]));
    if (v.size() == first + 5)
    {
      c.restitution = to_number(v[first + 4], "Contacts", it);
      AssertThrow(c.restitution >= 0. && c.restitution <= 1.,
                  ExcMessage("Model/Frame/Contacts: contact '" + it.name +
                             "': the restitution coefficient must be in [0, 1]"));
    }
    contacts.push_back(c);
  }

  // cross-checks, with the entry that is wrong
  AssertThrow(!members.empty(), ExcMessage("Model/Frame/Members: no member is defined"));
  std::set<std::string> member_names, used_nodes;
  for (const auto &m : members)
  {
    AssertThrow(
        member_names.insert(m.name).second,
        ExcMessage("Model/Frame/Members: member '" + m.name + "' is defined twice"));
    for (const auto &n : {m.start, m.end})
    {
      AssertThrow(nodes.count(n),
                  ExcMessage("Model/Frame/Members: member '" + m.name + "' names node '" +
                             n + "', which is not in Model/Frame/Nodes"));
      used_nodes.insert(n);
    }
    AssertThrow(sections.count(m.section),
                ExcMessage("Model/Frame/Members: member '" + m.name +
                           "' names section '" + m.section +
                           "', which is not in Model/Frame/Sections"));
    AssertThrow(materials.count(m.material),
                ExcMessage("Model/Frame/Members: member '" + m.name +
                           "' names material '" + m.material +
                           "', which is not in Model/Frame/Materials"));
    AssertThrow(nodes[m.start].distance(nodes[m.end]) > 0.,
                ExcMessage("Model/Frame/Members: member '" + m.name +
                           "' has zero length (both ends at the same point)"));
    AssertThrow(
        std::isfinite(nodes[m.start].square()) && std::isfinite(nodes[m.end].square()) &&
            std::isfinite(nodes[m.start].distance_square(nodes[m.end])),
        ExcMessage("Model/Frame/Members: member '" + m.name +
                   "': the coordinates of its nodes '" + m.start + "', '" + m.end +
                   "' overflow (not finite when squared): node coordinates too "
                   "large"));
    for (unsigned int i = 0; i + 1 < m.path.size(); ++i)
    {
      AssertThrow(nodes[m.path[i]].distance(nodes[m.path[i + 1]]) > 0.,
                  ExcMessage("Model/Frame/Mesh file: member '" + m.name +
                             "' has a zero-length element at node '" + m.path[i] + "'"));
      used_nodes.insert(m.path[i]);
    }
  }
  auto check_node = [&](const std::string &n, const std::string &entry)
  {
    AssertThrow(used_nodes.count(n),
                ExcMessage("Model/Frame/" + entry + ": node '" + n +
                           "' is not an end of any member in Model/Frame/Members"));
  };
  for (const auto &p : point_masses)
    check_node(p.node, "Point masses");
  for (const auto &s : supports)
    check_node(s.node, "Supports");
  for (const auto &n : hinged_joints)
    check_node(n, "Hinged joints");
  for (const auto &n : monitor_nodes)
    check_node(n, "Monitor nodes");
  for (const auto &l : nodal_loads)
    check_node(l.first, "Nodal loads");
  for (const auto &c : contacts)
  {
    check_node(c.node, "Contacts");
    if (!c.other_node.empty())
      check_node(c.other_node, "Contacts");
  }
  for (const auto &m : section_force_members)
    AssertThrow(
        member_names.count(m),
        ExcMessage("Model/Frame/Section force members: no member named '" + m + "'"));
}

Frame::Frame(const Parameters &parameters) : parameters(parameters), fe(FE_Q<1, 3>(1), 6)
{
}

void Frame::create_mesh()
{
  const auto &P = parameters;
  // every member its own vertices; remember the end vertices at each node
  std::vector<Point<3>> vertices;
  std::vector<CellData<1>> cell_data;
  std::map<std::string, std::vector<unsigned int>> node_vertices; // in member order
  std::vector<std::pair<unsigned int, unsigned int>> cell_member; // (member, element)
  std::vector<unsigned int> cell_start; // first vertex of a cell
  std::vector<double> cell_position;    // along the member
  {
    // refuse before allocating: 6 DoFs per vertex, 3 blocks of 6 x 6 per row
    double n_cells = 0.;
    for (const auto &member : P.members)
      n_cells += member.n_elements;
    const double n_vertices = n_cells + P.members.size();
    check_memory_estimate(
        "Model/Frame/Members", n_cells, 6. * n_vertices, 108. * n_vertices);
  }
  for (unsigned int m = 0; m < P.members.size(); ++m)
  {
    const auto &member = P.members[m];
    const unsigned int base = vertices.size();
    if (member.path.empty())
    {
      const Point<3> x1 = P.nodes.at(member.start), x2 = P.nodes.at(member.end);
      for (unsigned int i = 0; i <= member.n_elements; ++i)
        vertices.push_back(x1 + (x2 - x1) * (double(i) / member.n_elements));
      node_vertices[member.start].push_back(base);
      node_vertices[member.end].push_back(base + member.n_elements);
    }
    else // from a mesh file: every node along the member may be a joint
      for (unsigned int i = 0; i < member.path.size(); ++i)
      {
        vertices.push_back(P.nodes.at(member.path[i]));
        node_vertices[member.path[i]].push_back(base + i);
      }
    double position = 0.;
    for (unsigned int i = 0; i < member.n_elements; ++i)
    {
      CellData<1> c;
      c.vertices = {base + i, base + i + 1};
      c.material_id = m;
      cell_data.push_back(c);
      cell_member.emplace_back(m, i);
      cell_start.push_back(base + i);
      cell_position.push_back(position);
      position += vertices[base + i].distance(vertices[base + i + 1]);
    }
  }
  triangulation.create_triangulation(vertices, cell_data, SubCellData());
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(fe);

  // DoFs of every vertex, and the cells in creation order
  vertex_dofs.assign(vertices.size(), {});
  std::vector<std::vector<unsigned int>> vertex_cells(vertices.size());
  cells.clear();
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    CellInfo info;
    std::tie(info.member, info.element) = cell_member[cell->active_cell_index()];
    const auto &member = P.members[info.member];
    // local x from the member's start to its end, whatever the cell's orientation
    const unsigned int first =
        cell->vertex_index(0) == cell_start[cell->active_cell_index()] ? 0 : 1;
    info.position = cell_position[cell->active_cell_index()];
    for (unsigned int v = 0; v < 2; ++v)
      vertex_cells[cell->vertex_index(v)].push_back(cell->active_cell_index());
    for (unsigned int v = 0; v < 2; ++v)
      for (unsigned int c = 0; c < 6; ++c)
      {
        vertex_dofs[cell->vertex_index(v)][c] = cell->vertex_dof_index(v, c);
        info.dofs[6 * (v == first ? 0 : 1) + c] = cell->vertex_dof_index(v, c);
      }
    Tensor<1, 3> y_ref = member.y_reference;
    const Tensor<1, 3> axis = cell->vertex(1) - cell->vertex(0);
    if (y_ref.norm() == 0.)
    {
      y_ref[1] = 1.;
      if (std::abs(axis[1]) > (1. - 1e-9) * axis.norm())
        y_ref = Tensor<1, 3>({1., 0., 0.});
    }
    info.length = cell->vertex(0).distance(cell->vertex(1));
    try
    {
      info.rotation = frame_rotation(cell->vertex(first), cell->vertex(1 - first), y_ref);
    }
    catch (const std::exception &)
    {
      AssertThrow(
          false,
          ExcMessage("Model/Frame/Members: member '" + member.name +
                     "': its section orientation vector is parallel to the member"));
    }
    const FrameSection &section = P.sections.at(member.section);
    const FrameMaterial &material = P.materials.at(member.material);
    info.stiffness = local_stiffness(info.length, section, material);
    info.mass = local_consistent_mass(info.length, section, material);
    cells.push_back(info);
  }

  // joints and supports as constraints
  constraints.clear();
  node_dofs.clear();
  node_cells.clear();
  for (const auto &[node, list] : node_vertices)
    for (const unsigned int v : list)
      node_cells[node].insert(
          node_cells[node].end(), vertex_cells[v].begin(), vertex_cells[v].end());
  const std::set<std::string> hinged(P.hinged_joints.begin(), P.hinged_joints.end());
  for (const auto &[node, list] : node_vertices)
  {
    node_dofs[node] = vertex_dofs[list[0]];
    for (unsigned int k = 1; k < list.size(); ++k)
      for (unsigned int c = 0; c < (hinged.count(node) ? 3u : 6u); ++c)
      {
        const auto slave = vertex_dofs[list[k]][c], master = vertex_dofs[list[0]][c];
        constraints.add_line(slave);
        constraints.add_entry(slave, master, 1.);
      }
  }
  for (const auto &s : P.supports)
    for (unsigned int c = 0; c < 6; ++c)
      if (s.stiffness[c] == 0. && !constraints.is_constrained(node_dofs[s.node][c]))
        constraints.add_line(node_dofs[s.node][c]);
  constraints.close();
}

void Frame::build(const CommonModelParameters &common, DiscreteSystem &system)
{
  const auto &P = parameters;
  gravity = common.gravity;

  if (triangulation.n_active_cells() == 0)
    create_mesh();
  const unsigned int n = dof_handler.n_dofs();
  system.reinit(n);

  DynamicSparsityPattern dsp(n, n);
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
  system.stiffness_pattern.copy_from(dsp);
  system.stiffness.reinit(system.stiffness_pattern);
  system.consistent_mass.reinit(system.stiffness_pattern);

  FullMatrix<double> kg(12, 12), mg(12, 12);
  Vector<double> lumped_cell(12), mass_influence_cell(12);
  for (auto &mi : system.mass_influence)
    mi.reinit(n);
  // base excitation on some members only (Loading/Excited members)
  std::vector<bool> excited(P.members.size(), common.excited_members.empty());
  for (const auto &name : common.excited_members)
  {
    unsigned int m = 0;
    while (m < P.members.size() && P.members[m].name != name)
      ++m;
    AssertThrow(m < P.members.size(),
                ExcMessage("Loading/Excited members: no member named '" + name + "'"));
    excited[m] = true;
  }
  const bool restricted = !common.excited_members.empty();
  if (restricted)
  {
    for (auto &mi : system.excited_mass_influence)
      mi.reinit(n);
    system.excited_lumped_mass.reinit(n);
  }
  auto node_excited = [&](const std::string &node)
  {
    for (const unsigned int c : node_cells[node])
      if (excited[cells[c].member])
        return true;
    return false;
  };
  std::vector<types::global_dof_index> dofs(12);
  double omega2 = 0.;
  double mass = 0.; // of the part built
  for (unsigned int c = 0; c < cells.size(); ++c)
  {
    if (!cell_selected(c))
      continue;
    const auto &info = cells[c];
    const auto &member = P.members[info.member];
    const FrameSection &section = P.sections.at(member.section);
    const FrameMaterial &material = P.materials.at(member.material);
    kg = to_global(local_stiffness(info.length, section, material), info.rotation);
    mg = to_global(local_consistent_mass(info.length, section, material), info.rotation);
    // lumped: diagonal of T^T D T, so that it stays diagonal in global axes
    const auto &R = info.rotation;
    const auto D = local_lumped_mass(info.length, section, material);
    for (unsigned int b = 0; b < 4; ++b)
      for (unsigned int i = 0; i < 3; ++i)
      {
        double d = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          d += R[k][i] * R[k][i] * D[3 * b + k];
        lumped_cell[3 * b + i] = d;
      }
    std::copy(info.dofs.begin(), info.dofs.end(), dofs.begin());
    constraints.distribute_local_to_global(kg, dofs, system.stiffness);
    constraints.distribute_local_to_global(mg, dofs, system.consistent_mass);
    constraints.distribute_local_to_global(lumped_cell, dofs, system.lumped_mass);
    // M r_d element by element, so that the inertia coupled to supported
    // DoFs is kept (the condensed matrix has lost it)
    for (unsigned int d = 0; d < 3; ++d)
    {
      for (unsigned int i = 0; i < 12; ++i)
        mass_influence_cell[i] = mg(i, d) + mg(i, 6 + d);
      constraints.distribute_local_to_global(
          mass_influence_cell, dofs, system.mass_influence[d]);
      if (restricted && excited[info.member])
        constraints.distribute_local_to_global(
            mass_influence_cell, dofs, system.excited_mass_influence[d]);
    }
    if (restricted && excited[info.member])
      constraints.distribute_local_to_global(
          lumped_cell, dofs, system.excited_lumped_mass);
    omega2 =
        std::max(omega2,
                 element_omega_squared(
                     kg, std::vector<double>(lumped_cell.begin(), lumped_cell.end())));
    mass += material.rho * section.A * info.length;
  }

  std::vector<double> spring(n, 0.);
  for (const auto &s : P.supports)
    for (unsigned int c = 0; c < 6; ++c)
      if (s.stiffness[c] > 0. && owns_node(node_cells[s.node]))
      {
        system.stiffness.add(node_dofs[s.node][c], node_dofs[s.node][c], s.stiffness[c]);
        spring[node_dofs[s.node][c]] += s.stiffness[c];
      }
  for (const auto &p : P.point_masses)
    for (unsigned int c = 0; c < 6; ++c)
    {
      if (!owns_node(node_cells[p.node]))
        break;
      const auto i = node_dofs[p.node][c];
      if (constraints.is_constrained(i))
        continue;
      const double m = c < 3 ? p.mass : p.rotary_inertia[c - 3];
      system.lumped_mass[i] += m;
      system.consistent_mass.add(i, i, m);
      if (c < 3)
        system.mass_influence[c][i] += m;
      if (restricted && node_excited(p.node))
      {
        system.excited_lumped_mass[i] += m;
        if (c < 3)
          system.excited_mass_influence[c][i] += m;
      }
    }
  for (const auto &p : P.point_masses)
    if (owns_node(node_cells[p.node]))
      mass += p.mass;
  if (selected_part < 0)
    total_mass = mass;

  for (unsigned int i = 0; i < n; ++i)
    system.fixed[i] = constraints.is_constrained(i);

  // critical step bound: elements, plus the springs (Weyl's inequality:
  // lambda_max(M^-1 (K_e + K_s)) <= element bound + max k_i / m_i)
  double spring_bound = 0.;
  for (unsigned int i = 0; i < n; ++i)
    if (spring[i] > 0. && !system.fixed[i])
      spring_bound = std::max(spring_bound, spring[i] / system.lumped_mass[i]);
  system.omega_max_bound = std::sqrt(omega2 + spring_bound);

  // rigid translations; gravity F = M r g (consistent mass, inertia coupled
  // to the supports included); nodal loads
  for (unsigned int d = 0; d < 3; ++d)
  {
    system.influence[d].reinit(n);
    for (const auto &vd : vertex_dofs)
      if (!system.fixed[vd[d]])
        system.influence[d][vd[d]] = 1.;
    system.constant_force.add(common.gravity[d], system.mass_influence[d]);
  }
  system.gravity = common.gravity;
  for (const auto &[node, f] : P.nodal_loads)
    if (owns_node(node_cells[node]))
      for (unsigned int c = 0; c < 6; ++c)
        system.constant_force[node_dofs[node][c]] += f[c];
  for (unsigned int i = 0; i < n; ++i)
    if (system.fixed[i])
      system.constant_force[i] = 0.;

  // contacts (doc/theory.md 1.2): g = gap + n . (u_node - u_other), so L has
  // n on the node's translations and -n on the other node's (none for a rigid
  // plane); a two-sided contact is two such rows with normals n and -n and
  // gaps c / 2. A node-to-node contact belongs to the explicit subdomain if
  // either node touches an explicit cell.
  for (const auto &c : P.contacts)
  {
    std::vector<unsigned int> contact_cells = node_cells[c.node];
    if (!c.other_node.empty())
      contact_cells.insert(contact_cells.end(),
                           node_cells[c.other_node].begin(),
                           node_cells[c.other_node].end());
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
          row.dofs.push_back(node_dofs[c.node][d]);
          row.coefficients.push_back(side * c.normal[d]);
          if (!c.other_node.empty())
          {
            row.dofs.push_back(node_dofs[c.other_node][d]);
            row.coefficients.push_back(-side * c.normal[d]);
          }
        }
      row.initial_gap = c.two_sided ? 0.5 * c.gap : c.gap;
      row.restitution = c.restitution >= 0. ? c.restitution : common.restitution;
      system.contacts.push_back(row);
    }
  }

  for (const auto &node : P.monitor_nodes)
  {
    MonitorPoint m;
    m.name = node;
    for (unsigned int c = 0; c < 6; ++c)
    {
      m.labels.push_back(component_labels[c]);
      m.dofs.push_back(node_dofs[node][c]);
    }
    system.monitors.push_back(m);
  }
}

std::array<double, 12> Frame::cell_section_forces(const CellInfo &cell,
                                                  const Vector<double> &U) const
{
  Vector<double> ug(12), f(12), span(12), r(12);
  for (unsigned int i = 0; i < 12; ++i)
    ug[i] = U[cell.dofs[i]];
  cell.stiffness.vmult(f, to_local(ug, cell.rotation));
  // end forces f = k u - F_gravity, F_gravity = m r g in local axes: the
  // element's own weight is a span load (fixed-end forces)
  const Tensor<1, 3> g = cell.rotation * gravity;
  for (unsigned int d = 0; d < 3; ++d)
    r[d] = r[6 + d] = g[d];
  cell.mass.vmult(span, r);
  f -= span;
  return section_forces(f);
}

void Frame::write_vtu(std::ostream &out,
                      const std::vector<NamedVector> &fields,
                      const double time,
                      const unsigned int cycle) const
{
  DataOut<1, 3> data_out;
  data_out.attach_dof_handler(dof_handler);
  std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      6, DataComponentInterpretation::component_is_part_of_vector);
  std::vector<Vector<double>> distributed(fields.size());
  Vector<float> member_id(triangulation.n_active_cells());
  std::array<Vector<float>, 6> forces;
  for (auto &f : forces)
    f.reinit(triangulation.n_active_cells());
  for (unsigned int f = 0; f < fields.size(); ++f)
  {
    distributed[f] = *fields[f].second;
    constraints.distribute(distributed[f]);
    std::vector<std::string> names(3, fields[f].first);
    for (unsigned int c = 0; c < 3; ++c)
      names.push_back(fields[f].first + "_rotational");
    data_out.add_data_vector(
        distributed[f], names, DataOut<1, 3>::type_dof_data, interpretation);
    if (fields[f].first == "displacement")
      for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const auto s = cell_section_forces(cells[c], distributed[f]);
        for (unsigned int k = 0; k < 6; ++k)
          forces[k][c] = 0.5 * (s[k] + s[6 + k]); // mid-element value
      }
  }
  for (unsigned int c = 0; c < cells.size(); ++c)
    member_id[c] = cells[c].member;
  data_out.add_data_vector(member_id, "member", DataOut<1, 3>::type_cell_data);
  const Vector<float> subdomain = subdomain_field();
  if (subdomain.size() > 0)
    data_out.add_data_vector(subdomain, "subdomain", DataOut<1, 3>::type_cell_data);
  const char *force_names[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
  for (unsigned int k = 0; k < 6; ++k)
    data_out.add_data_vector(forces[k], force_names[k], DataOut<1, 3>::type_cell_data);
  data_out.build_patches();
  data_out.set_flags(DataOutBase::VtkFlags(time, cycle));
  data_out.write_vtu(out);
}

std::vector<Point<3>> Frame::cell_centres() const
{
  std::vector<Point<3>> centres(triangulation.n_active_cells());
  for (const auto &cell : triangulation.active_cell_iterators())
    centres[cell->active_cell_index()] = cell->center();
  return centres;
}

std::vector<std::string> Frame::cell_members() const
{
  std::vector<std::string> names(cells.size());
  for (unsigned int c = 0; c < cells.size(); ++c)
    names[c] = parameters.members[cells[c].member].name;
  return names;
}

std::string Frame::section_forces_header() const
{
  if (parameters.section_force_members.empty())
    return "";
  return "time,member,element,x,N,Vy,Vz,T,My,Mz";
}

void Frame::write_section_forces(std::ostream &out,
                                 const double time,
                                 const Vector<double> &U) const
{
  if (parameters.section_force_members.empty())
    return;
  Vector<double> u(U);
  constraints.distribute(u);
  for (const auto &name : parameters.section_force_members)
    for (const auto &cell : cells)
      if (parameters.members[cell.member].name == name)
      {
        const auto s = cell_section_forces(cell, u);
        for (unsigned int end = 0; end < 2; ++end)
        {
          // envelope of N, My, Mz (components 0, 4, 5 of each end)
          const unsigned int component[3] = {0, 4, 5};
          for (unsigned int e = 0; e < 3; ++e)
          {
            const double v = std::abs(s[6 * end + component[e]]);
            if (v > envelope[e].value)
              envelope[e] = {v, cell.position + end * cell.length, time, name};
          }
          out << time << ',' << name << ',' << cell.element << ','
              << cell.position + end * cell.length;
          for (unsigned int k = 0; k < 6; ++k)
            out << ',' << s[6 * end + k] + 0.; // + 0.: no "-0" in the file
          out << '\n';
        }
      }
}

SummaryEntries Frame::summary_entries(const std::map<std::string, double> &) const
{
  if (parameters.section_force_members.empty())
    return {};
  SummaryValue result = SummaryValue::object();
  const char *names[3] = {"N", "My", "Mz"};
  for (unsigned int e = 0; e < 3; ++e)
    result.set(names[e],
               SummaryValue::object()
                   .set("max_abs", envelope[e].value)
                   .set("member", envelope[e].member)
                   .set("x", envelope[e].x)
                   .set("time", envelope[e].time));
  return {{"section_force_envelope", result}};
}

std::string Frame::results_table() const
{
  if (parameters.section_force_members.empty())
    return "";
  std::ostringstream s;
  const char *names[3] = {"max |N|  (N)  ", "max |My| (N m)", "max |Mz| (N m)"};
  s << "  section forces of the members written to section_forces.csv (at its rows):\n";
  for (unsigned int e = 0; e < 3; ++e)
    s << "    " << names[e] << std::setw(16) << envelope[e].value << "  in "
      << envelope[e].member << " at x = " << envelope[e].x
      << " m, t = " << envelope[e].time << " s\n";
  return s.str();
}

std::string Frame::description() const
{
  std::ostringstream s;
  unsigned int ne = 0;
  for (const auto &m : parameters.members)
    ne += m.n_elements;
  s << "3D frame: " << parameters.nodes.size() << " nodes, " << parameters.members.size()
    << " members, " << ne << " Timoshenko elements, mass " << total_mass << " kg";
  return s.str();
}
} // namespace hati

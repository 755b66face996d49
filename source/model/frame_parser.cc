#include <deal.II/base/utilities.h>

#include <hati/model/frame_items.h>
#include <hati/model/frame_parser.h>
#include <hati/model/frame_solid_parser.h>
#include <hati/model/gmsh_frame_reader.h>

#include <cmath>
#include <cstdlib>
#include <map>

namespace hati
{
namespace
{

using Item = FrameItem;

/** Whether @p value is a finite number (a node named like a number is read as one). */
bool is_number(const std::string &value)
{
  char *end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  return !value.empty() && end != nullptr && *end == '\0' && std::isfinite(x);
}

/** The values @p first, @p first + 1, @p first + 2 of @p item as a vector. */
Tensor<1, 3>
to_vector(const Item &item, const unsigned int first, const std::string &entry)
{
  Tensor<1, 3> v;
  for (unsigned int k = 0; k < 3; ++k)
    v[k] = frame_item_number(item.values[first + k], entry, item);
  return v;
}

} // namespace

void FrameParameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Nodes",
                    "",
                    Patterns::Anything(),
                    "Named nodes, 'name: x, y, z; ...' (m, global axes). Names of "
                    "nodes, materials, sections, members and contacts have only "
                    "letters, digits, '_', '-' and '.'; a node name is not a number.");
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
      "t_flange' (thin-walled closed box, m) or 'general, A, Iy, Iz, J, Asy, Asz[, c_y, "
      "c_z]' (m^2, m^4, m^4, m^4, m^2, m^2, m, m; Iy = int z^2 dA for bending about "
      "local y; shear areas Asy, Asz, 0 for no shear deformation; c_y, c_z the extreme "
      "fibre distances from the centroid along local y and z, optional: without them "
      "the member has no stresses, beam_stresses in summary.json).");
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
      "is explicit if either node touches an explicit cell. Trailing options, "
      "in any order: 'mu=<coefficient>' Coulomb friction (-, >= 0, default 0: "
      "frictionless; CD-Lagrange and the explicit subdomain of HATI; static and "
      "modal analyses hold a closed frictional contact in its tangential "
      "directions) and 'rolls=<x|y|z>' the global axis, in the contact plane, "
      "along which the node rolls freely (no friction along it).");
  prm.declare_entry(
      "Ropes",
      "",
      Patterns::Anything(),
      "Ropes (tension only, geometrically exact; CD-Lagrange, or the explicit "
      "subdomain of HATI), 'name: node, other node, stiffness[, rest length]; ...': "
      "node is the hook point (a node of a member), other node the load (a node of a "
      "member, or a node held by the rope alone: it keeps its translations, its "
      "rotations are held); stiffness k = E A / L of all falls (N/m, > 0); rest length "
      "(m, > 0), default the distance between the two nodes (gravity then stretches "
      "the rope). Tension T = max(0, k (l - rest length)) with l the current "
      "distance between the nodes.");
  prm.declare_entry(
      "Flanges",
      "",
      Patterns::Anything(),
      "Wheel flanges that can leave their rail (CD-Lagrange, or the explicit "
      "subdomain of HATI; doc/theory.md D1-D2), 'name: tread contact, flange "
      "contact, flange depth, rail head width; ...': the tread contact is the "
      "wheel's one-sided contact on the rail (its gap is the uplift), the flange "
      "contact its two-sided lateral contact with a clearance c, of the same node. "
      "While the uplift exceeds the flange depth (m, > 0) the flange contact does "
      "not act; a wheel above its flange whose lateral offset exceeds c plus half "
      "the rail head width (m, >= 0) has derailed: the run stops with status "
      "'derailed' (summary.json derailment). Static and modal analyses take the "
      "flanges as engaged.");
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
                    "NODE.ux ... NODE.urz, NODE.vx ... NODE.vrz); items 'name: solid, "
                    "x, y, z' (m), separated by ';' from the node names and each "
                    "other, add the solid's node nearest to that point (columns "
                    "name.ux ... name.uz, name.vx ... name.vz: translations only).");
  prm.declare_entry("Section force members",
                    "",
                    Patterns::Anything(),
                    "Members whose section forces are written to section_forces.csv at "
                    "every history row, 'member, member, ...'.");
  declare_solid_entries(prm);
}

FrameSection parse_frame_section(const std::string &text, const std::string &where)
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
    AssertThrow(values.size() == 7 || values.size() == 9,
                ExcMessage(where + " has " + std::to_string(values.size()) +
                           " values, expected 'general, A, Iy, Iz, J, Asy, Asz[, c_y, "
                           "c_z]'"));
    if (values.size() == 9)
    {
      AssertThrow(v[6] > 0. && v[7] > 0.,
                  ExcMessage(where + ": the extreme fibre distances c_y, c_z of a "
                                     "general section must be > 0 (m)"));
      s.c_y = v[6];
      s.c_z = v[7];
    }
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

namespace
{
void parse_nodes(ParameterHandler &prm, FrameDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Nodes"), "Nodes"))
  {
    expect_frame_item_values(it, "Nodes", {3}, "3 (x, y, z)");
    d.add_node(it.name,
               Point<3>(frame_item_number(it.values[0], "Nodes", it),
                        frame_item_number(it.values[1], "Nodes", it),
                        frame_item_number(it.values[2], "Nodes", it)));
  }
}

void parse_materials(ParameterHandler &prm, FrameDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Materials"), "Materials"))
  {
    expect_frame_item_values(it, "Materials", {3}, "3 (E, nu, rho)");
    FrameMaterial m;
    m.E = frame_item_number(it.values[0], "Materials", it);
    const double nu = frame_item_number(it.values[1], "Materials", it);
    m.rho = frame_item_number(it.values[2], "Materials", it);
    AssertThrow(m.E > 0. && nu > -1. && nu < 0.5 && m.rho > 0.,
                ExcMessage("Model/Frame/Materials: item '" + it.name +
                           "' needs E > 0, -1 < nu < 0.5 and rho > 0"));
    m.G = m.E / (2. * (1. + nu));
    AssertThrow(
        d.materials.count(it.name) == 0,
        ExcMessage("Model/Frame/Materials: material '" + it.name + "' is defined twice"));
    d.materials[it.name] = m;
  }
}

void parse_sections(ParameterHandler &prm, FrameDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Sections"), "Sections"))
  {
    AssertThrow(
        d.sections.count(it.name) == 0,
        ExcMessage("Model/Frame/Sections: section '" + it.name + "' is defined twice"));
    std::string text;
    for (unsigned int i = 0; i < it.values.size(); ++i)
      text += (i ? ", " : "") + it.values[i];
    d.sections[it.name] =
        parse_frame_section(text, "Model/Frame/Sections: item '" + it.name + "'");
  }
}

void parse_members(ParameterHandler &prm, FrameDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Members"), "Members"))
  {
    expect_frame_item_values(
        it,
        "Members",
        {5, 8},
        "5 or 8 (start, end, section, material, elements[, yx, yy, yz])");
    FrameDescription::Member m;
    m.name = it.name;
    m.start = it.values[0];
    m.end = it.values[1];
    m.section = it.values[2];
    m.material = it.values[3];
    const double ne = frame_item_number(it.values[4], "Members", it);
    AssertThrow(ne >= 1. && ne == std::floor(ne) && ne <= max_elements_per_member,
                ExcMessage("Model/Frame/Members: member '" + it.name +
                           "': the number of elements must be an integer from 1 to " +
                           std::to_string(static_cast<long>(max_elements_per_member)) +
                           ", got " + it.values[4]));
    m.n_elements = static_cast<unsigned int>(ne);
    if (it.values.size() == 8)
    {
      m.y_reference = to_vector(it, 5, "Members");
      AssertThrow(m.y_reference.norm() > 0.,
                  ExcMessage("Model/Frame/Members: member '" + it.name +
                             "': the section orientation vector (yx, yy, yz) is zero"));
    }
    d.members.push_back(m);
  }
}

/**
 * The members and named nodes of the Mesh file, with their sections and
 * materials from Member properties, added to @p d.
 */
void merge_mesh_file(ParameterHandler &prm, FrameDescription &d)
{
  const std::string mesh_file = Utilities::trim(prm.get("Mesh file"));
  if (mesh_file.empty())
    return;
  const GmshFrame mesh = read_gmsh_frame(mesh_file, "Model/Frame/Mesh file");
  for (const auto &[name, x] : mesh.nodes)
  {
    const auto known = d.nodes.find(name);
    AssertThrow(known == d.nodes.end() || known->second.distance(x) < 1e-12,
                ExcMessage("Model/Frame/Mesh file: node '" + name +
                           "' is also in Model/Frame/Nodes at another position"));
    if (known == d.nodes.end())
      d.add_node(name, x);
    else
      known->second = x;
  }
  std::map<std::string, Item> properties;
  for (const Item &it :
       parse_frame_items(prm.get("Member properties"), "Member properties"))
  {
    expect_frame_item_values(
        it, "Member properties", {2, 5}, "2 or 5 (section, material[, yx, yy, yz])");
    AssertThrow(mesh.members.count(it.name),
                ExcMessage("Model/Frame/Member properties: the mesh file '" + mesh_file +
                           "' has no member (physical curve) named '" + it.name + "'"));
    properties[it.name] = it;
  }
  for (const auto &[name, path] : mesh.members)
  {
    AssertThrow(properties.count(name),
                ExcMessage("Model/Frame/Member properties: no section and material for "
                           "the member '" +
                           name + "' of the mesh file '" + mesh_file + "'"));
    const Item &it = properties[name];
    FrameDescription::Member m;
    m.name = name;
    m.path = path;
    m.start = path.front();
    m.end = path.back();
    m.section = it.values[0];
    m.material = it.values[1];
    m.n_elements = path.size() - 1;
    if (it.values.size() == 5)
      m.y_reference = to_vector(it, 2, "Member properties");
    d.members.push_back(m);
  }
}

void parse_point_masses(ParameterHandler &prm, FrameDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Point masses"), "Point masses"))
  {
    expect_frame_item_values(it, "Point masses", {1, 4}, "1 or 4 (m[, Ixx, Iyy, Izz])");
    FrameDescription::PointMassData p;
    p.node = it.name;
    p.mass = frame_item_number(it.values[0], "Point masses", it);
    if (it.values.size() == 4)
      p.rotary_inertia = to_vector(it, 1, "Point masses");
    d.point_masses.push_back(p);
  }
}

void parse_supports(ParameterHandler &prm, FrameDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Supports"), "Supports"))
  {
    FrameDescription::Support s;
    s.node = it.name;
    if (it.values.size() == 1 && it.values[0] == "clamped")
      s.stiffness = {{0., 0., 0., 0., 0., 0.}};
    else if (it.values.size() == 1 && it.values[0] == "pinned")
      s.stiffness = {{0., 0., 0., -1., -1., -1.}};
    else
    {
      expect_frame_item_values(it, "Supports", {6}, "'clamped', 'pinned' or 6 codes");
      for (unsigned int c = 0; c < 6; ++c)
      {
        const std::string &code = it.values[c];
        if (code == "fixed")
          s.stiffness[c] = 0.;
        else if (code == "free")
          s.stiffness[c] = -1.;
        else
        {
          s.stiffness[c] = frame_item_number(code, "Supports", it);
          AssertThrow(s.stiffness[c] > 0.,
                      ExcMessage("Model/Frame/Supports: node '" + it.name +
                                 "': a spring stiffness must be > 0"));
        }
      }
    }
    d.supports.push_back(s);
  }
}

/** The names of a list entry 'name, name, ...'. */
std::vector<std::string> names(const std::string &text)
{
  std::vector<std::string> r;
  for (const auto &s : Utilities::split_string_list(text, ','))
    if (!Utilities::trim(s).empty())
      r.push_back(Utilities::trim(s));
  return r;
}

void parse_nodal_loads(ParameterHandler &prm, FrameDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Nodal loads"), "Nodal loads"))
  {
    expect_frame_item_values(
        it, "Nodal loads", {3, 6}, "3 or 6 (Fx, Fy, Fz[, Mx, My, Mz])");
    std::array<double, 6> f{{0., 0., 0., 0., 0., 0.}};
    for (unsigned int c = 0; c < it.values.size(); ++c)
      f[c] = frame_item_number(it.values[c], "Nodal loads", it);
    d.nodal_loads[it.name] = f;
  }
}

/** One item of Ropes: 'node, other node, stiffness[, rest length]'. */
FrameDescription::RopeData parse_rope(const Item &it)
{
  expect_frame_item_values(
      it, "Ropes", {3, 4}, "3 or 4 (node, other node, stiffness[, rest length])");
  FrameDescription::RopeData r;
  r.name = it.name;
  r.node = it.values[0];
  r.other_node = it.values[1];
  r.stiffness = frame_item_number(it.values[2], "Ropes", it);
  AssertThrow(r.stiffness > 0. && r.stiffness <= FrameDescription::max_rope_stiffness,
              ExcMessage("Model/Frame/Ropes: rope '" + it.name +
                         "': the stiffness must be > 0 and at most 1e12 N/m, got " +
                         it.values[2]));
  if (it.values.size() == 4)
  {
    r.rest_length = frame_item_number(it.values[3], "Ropes", it);
    AssertThrow(r.rest_length > 0.,
                ExcMessage("Model/Frame/Ropes: rope '" + it.name +
                           "': the rest length must be > 0 (m), got " + it.values[3]));
  }
  return r;
}

/** One item of Flanges: 'tread contact, flange contact, flange depth, rail head width'.
 */
FrameDescription::Flange parse_flange(const Item &it)
{
  expect_frame_item_values(
      it,
      "Flanges",
      {4},
      "4 (tread contact, flange contact, flange depth, rail head width)");
  FrameDescription::Flange f;
  f.name = it.name;
  f.tread_contact = it.values[0];
  f.flange_contact = it.values[1];
  f.depth = frame_item_number(it.values[2], "Flanges", it);
  AssertThrow(f.depth > 0.,
              ExcMessage("Model/Frame/Flanges: flange '" + it.name +
                         "': the flange depth must be > 0 (m), got " + it.values[2]));
  f.rail_head_width = frame_item_number(it.values[3], "Flanges", it);
  AssertThrow(f.rail_head_width >= 0.,
              ExcMessage("Model/Frame/Flanges: flange '" + it.name +
                         "': the rail head width must be >= 0 (m), got " + it.values[3]));
  return f;
}

/**
 * The trailing options of a Contacts item, in any order, taken off the end
 * of @p v: 'two-sided', 'mu=<coefficient>' (Coulomb friction, A9) and
 * 'rolls=<x|y|z>' (the axis along which the node rolls freely).
 */
void parse_contact_options(const Item &it,
                           std::vector<std::string> &v,
                           FrameDescription::NodeContact &c)
{
  const std::string contact = "Model/Frame/Contacts: contact '" + it.name + "': ";
  std::string mu_given, rolls_given; // the option as given, once taken
  while (!v.empty())
  {
    const std::string &last = v.back();
    const auto eq = last.find('=');
    const std::string key = Utilities::trim(last.substr(0, eq)),
                      value = eq == std::string::npos
                                  ? ""
                                  : Utilities::trim(last.substr(eq + 1));
    // options are taken from the end: a repeat would silently keep the first
    const std::pair<const char *, std::string *> once[] = {{"mu", &mu_given},
                                                           {"rolls", &rolls_given}};
    for (const auto &[name, given] : once)
      if (eq != std::string::npos && key == name)
      {
        AssertThrow(given->empty(),
                    ExcMessage(contact + key + "= is given twice ('" + last +
                               "', then '" + *given + "'): give it once"));
        *given = last;
      }
    if (last == "two-sided")
      c.two_sided = true;
    else if (eq != std::string::npos && key == "mu")
    {
      char *end = nullptr;
      c.friction = std::strtod(value.c_str(), &end);
      AssertThrow(!value.empty() && *end == '\0' && std::isfinite(c.friction) &&
                      c.friction >= 0.,
                  ExcMessage(contact + "mu=" + value +
                             ": expected the friction coefficient, a number >= 0"));
    }
    else if (eq != std::string::npos && key == "rolls")
    {
      AssertThrow(value == "x" || value == "y" || value == "z",
                  ExcMessage(contact + "rolls=" + value +
                             ": expected the rolling axis x, y or z"));
      c.rolls = value[0] - 'x';
    }
    else if (eq != std::string::npos)
    {
      AssertThrow(false,
                  ExcMessage(contact + "unknown option '" + last +
                             "', expected mu=<coefficient> or rolls=<x|y|z>"));
    }
    else
      break;
    v.pop_back();
  }
}

/**
 * One item of Contacts: 'node, nx, ny, nz, gap[, e][, two-sided]' (rigid
 * plane) or 'node, other node, nx, ny, nz, gap[, e][, two-sided]' (node to
 * node, recognised by the second value naming a node of @p d).
 */
FrameDescription::NodeContact parse_contact(const Item &it, const FrameDescription &d)
{
  std::vector<std::string> v = it.values;
  FrameDescription::NodeContact c;
  c.name = it.name;
  parse_contact_options(it, v, c);
  const bool node_to_node = v.size() >= 2 && d.nodes.count(v[1]) > 0 && !is_number(v[1]);
  const unsigned int first = node_to_node ? 2 : 1; // index of nx
  AssertThrow(
      v.size() == first + 4 || v.size() == first + 5,
      ExcMessage("Model/Frame/Contacts: item '" + it.name + "' has " +
                 std::to_string(it.values.size()) +
                 " values, expected 'node, nx, ny, nz, gap[, e][, two-sided][, mu=..][, "
                 "rolls=..]' or 'node, other node, nx, ny, nz, gap[, e][, "
                 "two-sided][, mu=..][, rolls=..]'"));
  c.node = v[0];
  if (node_to_node)
    c.other_node = v[1];
  else
    AssertThrow(is_number(v[1]),
                ExcMessage("Model/Frame/Contacts: contact '" + it.name + "': '" + v[1] +
                           "' is neither a node of Model/Frame/Nodes nor a number "
                           "(the normal's nx)"));
  for (unsigned int k = 0; k < 3; ++k)
    c.normal[k] = frame_item_number(v[first + k], "Contacts", it);
  AssertThrow(
      c.normal.norm() > 0.,
      ExcMessage("Model/Frame/Contacts: contact '" + it.name + "' has a zero normal"));
  c.normal /= c.normal.norm();
  c.gap = frame_item_number(v[first + 3], "Contacts", it);
  AssertThrow(c.gap >= 0.,
              ExcMessage("Model/Frame/Contacts: contact '" + it.name + "': the " +
                         (c.two_sided ? "clearance" : "gap") + " must be >= 0 (m), got " +
                         v[first + 3]));
  if (v.size() == first + 5)
  {
    c.restitution = frame_item_number(v[first + 4], "Contacts", it);
    AssertThrow(c.restitution >= 0. && c.restitution <= 1.,
                ExcMessage("Model/Frame/Contacts: contact '" + it.name +
                           "': the restitution coefficient must be in [0, 1]"));
  }
  return c;
}
} // namespace

void FrameParameters::parse_parameters(ParameterHandler &prm)
{
  FrameDescription &d = description;
  parse_nodes(prm, d);
  parse_materials(prm, d);
  parse_sections(prm, d);
  parse_members(prm, d);
  merge_mesh_file(prm, d);
  parse_point_masses(prm, d);
  parse_supports(prm, d);
  d.hinged_joints = names(prm.get("Hinged joints"));
  parse_monitor_entry(prm.get("Monitor nodes"), d.monitor_nodes, d.solids);
  d.section_force_members = names(prm.get("Section force members"));
  parse_nodal_loads(prm, d);
  for (const Item &it : parse_frame_items(prm.get("Contacts"), "Contacts"))
    d.contacts.push_back(parse_contact(it, d));
  for (const Item &it : parse_frame_items(prm.get("Ropes"), "Ropes"))
    d.ropes.push_back(parse_rope(it));
  for (const Item &it : parse_frame_items(prm.get("Flanges"), "Flanges"))
    d.flanges.push_back(parse_flange(it));
  parse_solid_entries(prm, d.solids);
}
} // namespace hati

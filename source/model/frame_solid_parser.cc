#include <deal.II/base/utilities.h>

#include <hati/model/frame_items.h>
#include <hati/model/frame_solid_parser.h>

#include <cmath>

namespace hati
{
namespace
{
using Item = FrameItem;
using SolidItem = SolidDescription::Solid;

/** Throw "Model/Frame/<entry>: item '<name>': <what>" unless @p ok. */
void require(const bool ok,
             const std::string &entry,
             const Item &it,
             const std::string &what)
{
  AssertThrow(ok,
              ExcMessage("Model/Frame/" + entry + ": item '" + it.name + "': " + what));
}

Point<3> to_point(const Item &it, const unsigned int first, const std::string &entry)
{
  return Point<3>(frame_item_number(it.values[first], entry, it),
                  frame_item_number(it.values[first + 1], entry, it),
                  frame_item_number(it.values[first + 2], entry, it));
}

/** A positive integer number of cells. */
unsigned int to_cells(const Item &it, const unsigned int k)
{
  const double x = frame_item_number(it.values[k], "Solids", it);
  require(x >= 1. && x <= 1e4 && x == std::floor(x),
          "Solids",
          it,
          "the numbers of cells must be whole numbers from 1 to 10000, not '" +
              it.values[k] + "'");
  return static_cast<unsigned int>(x);
}

SolidItem parse_box(const Item &it)
{
  expect_frame_item_values(
      it, "Solids", {11}, "11 (box, x0, y0, z0, x1, y1, z1, nx, ny, nz, material)");
  SolidItem s;
  s.x0 = to_point(it, 1, "Solids");
  s.x1 = to_point(it, 4, "Solids");
  for (unsigned int d = 0; d < 3; ++d)
  {
    s.cells[d] = to_cells(it, 7 + d);
    require(s.x1[d] != s.x0[d], "Solids", it, "the box has zero extent along an axis");
  }
  s.material = it.values[10];
  return s;
}

SolidItem parse_box_girder(const Item &it)
{
  expect_frame_item_values(it,
                           "Solids",
                           {13, 14},
                           "13 or 14 (box girder, x0, y0, z0, x1, y1, z1, width, height, "
                           "web thickness, flange thickness, element size, material[, "
                           "diaphragm spacing])");
  SolidItem s;
  s.x0 = to_point(it, 1, "Solids");
  s.x1 = to_point(it, 4, "Solids");
  s.width = frame_item_number(it.values[7], "Solids", it);
  s.height = frame_item_number(it.values[8], "Solids", it);
  s.web_thickness = frame_item_number(it.values[9], "Solids", it);
  s.flange_thickness = frame_item_number(it.values[10], "Solids", it);
  s.element_size = frame_item_number(it.values[11], "Solids", it);
  s.material = it.values[12];
  if (it.values.size() == 14)
    s.diaphragm_spacing = frame_item_number(it.values[13], "Solids", it);
  require(s.x0.distance(s.x1) > 0., "Solids", it, "the girder has zero length");
  require(s.web_thickness > 0. && s.flange_thickness > 0. && s.element_size > 0. &&
              s.diaphragm_spacing >= 0.,
          "Solids",
          it,
          "thicknesses and the element size must be > 0, the diaphragm spacing >= 0 (m)");
  // one element through each wall and a hollow between them
  require(s.width > 2. * s.web_thickness,
          "Solids",
          it,
          "the width " + it.values[7] + " m is not more than 2 x the web thickness " +
              it.values[9] +
              " m: a box girder needs width > 2 x web thickness (one "
              "element through each web and a hollow between them)");
  require(s.height > 2. * s.flange_thickness,
          "Solids",
          it,
          "the height " + it.values[8] + " m is not more than 2 x the flange thickness " +
              it.values[10] +
              " m: a box girder needs height > 2 x flange thickness "
              "(one element through each flange and a hollow between them)");
  // diaphragms of web thickness at that spacing must not overlap
  if (s.diaphragm_spacing > 0.)
    require(s.diaphragm_spacing > s.web_thickness,
            "Solids",
            it,
            "the diaphragm spacing " + it.values[13] +
                " m is not more than the web thickness " + it.values[9] +
                " m (the diaphragms' thickness): they would overlap; give 0 for none");
  require(s.x0.distance(s.x1) > 2. * s.web_thickness || s.diaphragm_spacing == 0.,
          "Solids",
          it,
          "the girder is shorter than its two end diaphragms");
  return s;
}

SolidItem parse_solid(const Item &it)
{
  require(
      !it.values.empty(), "Solids", it, "no values: expected box, box girder or mesh");
  const std::string kind = it.values[0];
  SolidItem s;
  if (kind == "box")
    s = parse_box(it);
  else if (kind == "box girder")
    s = parse_box_girder(it);
  else if (kind == "mesh")
  {
    expect_frame_item_values(it, "Solids", {3}, "3 (mesh, file.msh, material)");
    s.file = it.values[1];
    s.material = it.values[2];
  }
  else
    require(false,
            "Solids",
            it,
            "'" + kind + "' is not a kind of solid: expected box, box girder or mesh");
  s.name = it.name;
  s.kind = kind;
  return s;
}

/**
 * `<axis>=<value>` at @p k and, after it, the optional `radius r` (or
 * `radius=r`) and `walls`, in either order: the face plane of a tie or a
 * support.
 */
SolidDescription::FacePlane
parse_plane(const Item &it, const unsigned int k, const std::string &entry)
{
  SolidDescription::FacePlane f;
  const std::string &v = it.values[k];
  const auto eq = v.find('=');
  const std::string axis =
      eq == std::string::npos ? "" : Utilities::trim(v.substr(0, eq));
  require(axis == "x" || axis == "y" || axis == "z",
          entry,
          it,
          "'" + v +
              "' is not a face plane: expected x=<value>, y=<value> or z=<value> (m)");
  f.axis = axis[0] - 'x';
  f.value = frame_item_number(Utilities::trim(v.substr(eq + 1)), entry, it);
  bool radius = false;
  for (unsigned int j = k + 1; j < it.values.size(); ++j)
  {
    const std::string &r = it.values[j];
    if (r == "walls" && !f.walls)
    {
      f.walls = true;
      continue;
    }
    require(r.rfind("radius", 0) == 0 && !radius,
            entry,
            it,
            "'" + r + "' is not 'radius <r>' (m) or 'walls' (each at most once)");
    std::string number = Utilities::trim(r.substr(6));
    if (!number.empty() && number[0] == '=')
      number = Utilities::trim(number.substr(1));
    f.radius = frame_item_number(number, entry, it);
    require(f.radius > 0., entry, it, "the radius must be > 0 (m)");
    radius = true;
  }
  return f;
}
} // namespace

void declare_solid_entries(ParameterHandler &prm)
{
  prm.declare_entry(
      "Solids",
      "",
      Patterns::Anything(),
      "3D linear elastic solids of the frame model, 'name: box, x0, y0, z0, x1, y1, "
      "z1, nx, ny, nz, material' (a block between two corners, m, with nx x ny x nz "
      "hexahedra); 'name: box girder, x0, y0, z0, x1, y1, z1, width, height, web "
      "thickness, flange thickness, element size, material[, diaphragm spacing]' (a "
      "hollow rectangular box between two axis points, m: its width along the local y "
      "and its height along the local z axis of a frame member between the same "
      "points, four plates one element thick with conforming corners, plates meshed "
      "at the element size, optional transverse diaphragms of web thickness at that "
      "spacing (> web thickness) and at both ends); 'name: mesh, file.msh, material' "
      "(a Gmsh ASCII mesh of 8-node hexahedra, format 4.1 or 2.2, m). Materials from "
      "Materials (E, nu, rho).");
  prm.declare_entry("Solid element degree",
                    "2",
                    Patterns::Integer(),
                    "Degree p of the solid elements FE_Q(p)^3 (1 to 4). 1 (trilinear) "
                    "locks in bending (a thin plate 0.33 of its deflection): a one-line "
                    "warning; 2 is within 1 % with one element through the thickness.");
  prm.declare_entry(
      "Ties",
      "",
      Patterns::Anything(),
      "Beam nodes tied to solid faces, 'name: node, solid, <axis>=<value>[, radius "
      "r][, walls]; ...': the node follows the area-weighted rigid fit of the solid's "
      "boundary face on the plane axis = value (m, global axes), or of its part within "
      "r (m) of the node's projection on that plane (faces whose centre lies within). "
      "The face may warp (no rigid face): a beam force F and moment M reach the face "
      "as the traction F/S + (I_G^-1 M) x r (doc/theory.md B1); so do the node's "
      "nodal loads, point masses and springs. The traction is linear over the face, "
      "not over the walls alone: the open end of a box girder distorts under it, give "
      "the girder its end diaphragms (diaphragm spacing). 'walls' (box girders): the "
      "fit over the walls' faces only (webs and flanges, as the beam's section), not "
      "the end diaphragm's face inside them, which would carry the traction across "
      "its thickness as a plate in bending (a joint far softer than the beam's).");
  prm.declare_entry("Solid supports",
                    "",
                    Patterns::Anything(),
                    "Fixed faces of solids, 'solid: <axis>=<value>[, radius r][, "
                    "walls]; ...': every translation of the nodes of the solid's "
                    "boundary face on that plane (m), or of its faces whose centre "
                    "lies within r (m) of the face's centroid, or of a box girder's "
                    "walls on it (not its diaphragms' faces), is fixed.");
  prm.declare_entry(
      "Solid cuts",
      "",
      Patterns::Anything(),
      "Cross-section cuts of solids, 'name: solid, <axis>=<value>; ...': the section "
      "forces N, Vy, Vz, T, My, Mz (N, N m, about the centroid of the cut, in the "
      "solid's local axes: a box girder's those of a frame member between its two "
      "axis points, x along it; global for box and mesh; N along the cut's axis, "
      "then the next two axes cyclically) of the plane axis = value (m, the "
      "coordinate along that local axis from the global origin), the force of the "
      "part at larger coordinate on the part at smaller coordinate (a beam's "
      "convention), integrated from the stresses over the layer of cells at the "
      "plane (doc/theory.md 11.4: exact in statics). Rows of section_forces.csv "
      "(member = name, element 0, x = value) and the envelope, at the rows of the "
      "Section force members.");
  prm.declare_entry("Rigid links",
                    "",
                    Patterns::Anything(),
                    "Rigid links, 'name: master node, slave node; ...': the slave node "
                    "follows the master rigidly, u_s = u_m + theta_m x (x_s - x_m), "
                    "theta_s = theta_m (eccentric connections, e.g. a wheel below its "
                    "end carriage's axis).");
}

void parse_solid_entries(ParameterHandler &prm, SolidDescription &d)
{
  for (const Item &it : parse_frame_items(prm.get("Solids"), "Solids"))
    d.solids.push_back(parse_solid(it));
  const long degree = prm.get_integer("Solid element degree");
  AssertThrow(degree >= 1 && degree <= 4,
              ExcMessage("Model/Frame/Solid element degree = " + std::to_string(degree) +
                         ": expected 1 to 4 (2: quadratic hexahedra)"));
  d.degree = static_cast<unsigned int>(degree);
  for (const Item &it : parse_frame_items(prm.get("Ties"), "Ties"))
  {
    expect_frame_item_values(it,
                             "Ties",
                             {3, 4, 5},
                             "3 to 5 (node, solid, <axis>=<value>[, radius r][, walls])");
    SolidDescription::Tie t;
    t.name = it.name;
    t.node = it.values[0];
    t.face = parse_plane(it, 2, "Ties");
    t.face.solid = it.values[1];
    d.ties.push_back(t);
  }
  for (const Item &it : parse_frame_items(prm.get("Solid supports"), "Solid supports"))
  {
    expect_frame_item_values(
        it, "Solid supports", {1, 2, 3}, "1 to 3 (<axis>=<value>[, radius r][, walls])");
    SolidDescription::FacePlane f = parse_plane(it, 0, "Solid supports");
    f.solid = it.name;
    d.supports.push_back(f);
  }
  for (const Item &it : parse_frame_items(prm.get("Rigid links"), "Rigid links"))
  {
    expect_frame_item_values(it, "Rigid links", {2}, "2 (master node, slave node)");
    d.rigid_links.push_back({it.name, it.values[0], it.values[1]});
  }
  for (const Item &it : parse_frame_items(prm.get("Solid cuts"), "Solid cuts"))
  {
    expect_frame_item_values(it, "Solid cuts", {2}, "2 (solid, <axis>=<value>)");
    SolidDescription::Cut c;
    c.name = it.name;
    c.solid = it.values[0];
    const SolidDescription::FacePlane plane = parse_plane(it, 1, "Solid cuts");
    c.axis = plane.axis;
    c.value = plane.value;
    d.cuts.push_back(c);
  }
}

void parse_monitor_entry(const std::string &text,
                         std::vector<std::string> &nodes,
                         SolidDescription &solids)
{
  // plain node names (no ':') keep their comma-separated list
  for (const auto &part : Utilities::split_string_list(text, ';'))
  {
    if (part.find(':') == std::string::npos)
    {
      for (const auto &n : Utilities::split_string_list(part, ','))
        if (!Utilities::trim(n).empty())
          nodes.push_back(Utilities::trim(n));
      continue;
    }
    for (const Item &it : parse_frame_items(part, "Monitor nodes"))
    {
      expect_frame_item_values(
          it, "Monitor nodes", {4}, "4 (solid, x, y, z) or plain node names");
      solids.monitors.push_back(
          {it.name, it.values[0], to_point(it, 1, "Monitor nodes")});
    }
  }
}
} // namespace hati

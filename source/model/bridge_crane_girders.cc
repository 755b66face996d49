// The bridge crane's girders as 3D solids (Model/Bridge crane/Girder model =
// solid, doc/user_guide.md "The three-dimensional crane"): box-girder solids
// with their diaphragms, the trolley rails as beams tied on the top flanges
// (B1) and the end carriages' joints tied to the girders' end faces.
#include <deal.II/base/utilities.h>

#include <hati/model/bridge_crane.h>
#include <hati/model/frame_parser.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hati
{
namespace
{

/**
 * Width of the rail's foot (m) for a `general` Rail section (no width in its
 * syntax): the A55's, 150 mm (DIN 536, doc/crane_data.md section 2).
 */
constexpr double general_rail_foot_width = 0.15;

/** The values of a section text, trimmed. */
std::vector<std::string> section_values(const std::string &text)
{
  std::vector<std::string> v = Utilities::split_string_list(text, ',');
  for (auto &x : v)
    x = Utilities::trim(x);
  return v;
}

/** The diaphragms' centres along a girder of length @p L (m), as the mesh has them. */
std::vector<double>
diaphragm_centres(const double L, const double spacing, const double t)
{
  // the same slabs as the box-girder mesh (solid_mesh.cc, axial_steps())
  std::vector<double> c;
  if (spacing <= 0.)
    return c;
  c.push_back(0.5 * t);
  for (double x = spacing; x + 0.5 * t < L - t; x += spacing)
    if (x - 0.5 * t > t)
      c.push_back(x);
  c.push_back(L - 0.5 * t);
  return c;
}
} // namespace

void BridgeCrane::Parameters::declare_girder_model(ParameterHandler &prm)
{
  prm.declare_entry(
      "Girder model",
      "beam",
      Patterns::Selection("beam|solid"),
      "beam (default): the girders are frame members of the Girder section. solid: "
      "each girder is a box-girder solid (Model/Frame/Solids) of the Girder section's "
      "width, height, web and flange thicknesses over the Span, with transverse "
      "diaphragms; the trolley rail is a beam of the Rail section on its top flange, "
      "tied at each node to the flange under it (B1); each end carriage joint is tied "
      "to the walls of the girder's end face (webs and flanges, not the end "
      "diaphragm's face, whose plate bending would make the joint soft). The end "
      "carriages, trolley, hoist, rope, load and "
      "wheels stay beams with their contacts. Method = HATI puts every solid in the "
      "implicit part.");
  prm.declare_entry("Girder element size",
                    "0.1",
                    Patterns::Double(0., 10.),
                    "Girder model = solid: in-plane size of the girder plates' elements "
                    "(m), > 0 and at most 10 m; one element through each plate's "
                    "thickness. Default 0.1 m.");
  prm.declare_entry(
      "Girder element degree",
      "2",
      Patterns::Integer(1, 4),
      "Girder model = solid: degree p of the solid elements FE_Q(p)^3 (-), 1 to 4. "
      "Default 2: one quadratic element through a plate's thickness is within 1 % of "
      "plate bending; 1 is allowed with a warning (linear hexahedra lock in bending).");
  prm.declare_entry("Girder diaphragm spacing",
                    "2",
                    Patterns::Double(0., 200.),
                    "Girder model = solid: spacing of the transverse diaphragms inside "
                    "each box girder (m), plates of web thickness at that spacing and "
                    "at both ends; 0: none. Default 2 m. The girders' Solid cuts (rows "
                    "of section_forces.csv) are at the diaphragms, or at every tenth "
                    "of the span without them.");
  prm.declare_entry(
      "Rail section",
      "general, 4.05e-3, 1.821e-6, 3.372e-6, 3.3e-7, 0, 0",
      Patterns::Anything(),
      "Girder model = solid: section of the trolley rail on each girder, "
      "Model/Frame/Sections syntax (m). Default: an A55 crane rail (DIN 536: A = 40.5 "
      "cm^2, I = 182.1 cm^4 in vertical bending, 337.2 cm^4 in lateral bending, J about "
      "33 cm^4 estimated from its head, web and foot, no shear deformation). Its "
      "density is chosen so that it weighs the Rail mass per metre (> 0). Its ties "
      "take the top flange within half the rail's foot (its width b, 150 mm for a "
      "general section) of each node, or within 3/4 of the Girder element size if "
      "that is larger (at least the face under the node).");
}

void BridgeCrane::Parameters::parse_girder_model(ParameterHandler &prm)
{
  girder_model = prm.get("Girder model");
  girder_element_size = prm.get_double("Girder element size");
  girder_element_degree = prm.get_integer("Girder element degree");
  girder_diaphragm_spacing = prm.get_double("Girder diaphragm spacing");
  rail_section = prm.get("Rail section");
  if (girder_model != "solid")
    return;
  AssertThrow(girder_element_size > 0.,
              ExcMessage(bridge_crane_where +
                         "Girder element size: expected > 0 (m), got " +
                         prm.get("Girder element size")));
  const std::vector<std::string> g = section_values(girder_section);
  AssertThrow(!g.empty() && g[0] == "box",
              ExcMessage(bridge_crane_where +
                         "Girder section: Girder model = solid needs a box "
                         "section 'box, b, h, t_web, t_flange', got '" +
                         girder_section + "'"));
  const double t_web = Utilities::string_to_double(g[3]);
  if (girder_diaphragm_spacing > 0. && girder_diaphragm_spacing <= t_web)
  {
    std::ostringstream m;
    m << bridge_crane_where << "Girder diaphragm spacing: " << girder_diaphragm_spacing
      << " m is not more than the web thickness " << t_web
      << " m (the diaphragms' thickness): they would overlap; give 0 for none";
    AssertThrow(false, ExcMessage(m.str()));
  }
  parse_frame_section(rail_section, bridge_crane_where + "Rail section");
  AssertThrow(rail_mass_per_metre > 0.,
              ExcMessage(bridge_crane_where +
                         "Rail mass per metre: expected > 0 with Girder model "
                         "= solid (the trolley rail is a beam of that mass)"));
}

double BridgeCrane::Parameters::rail_height() const
{
  if (girder_model != "solid")
    return 0.;
  return 0.5 * Utilities::string_to_double(section_values(girder_section)[2]);
}

double BridgeCrane::Parameters::solid_girder_volume() const
{
  const std::vector<std::string> g = section_values(girder_section);
  const double b = Utilities::string_to_double(g[1]),
               h = Utilities::string_to_double(g[2]),
               tw = Utilities::string_to_double(g[3]),
               tf = Utilities::string_to_double(g[4]);
  const double A =
      parse_frame_section(girder_section, bridge_crane_where + "Girder section").A;
  return A * span + diaphragm_centres(span, girder_diaphragm_spacing, tw).size() *
                        (b - 2. * tw) * (h - 2. * tf) * tw;
}

void BridgeCrane::Parameters::add_solid_girders(FrameDescription &f) const
{
  const std::vector<std::string> g = section_values(girder_section);
  const double b = Utilities::string_to_double(g[1]),
               h = Utilities::string_to_double(g[2]),
               tw = Utilities::string_to_double(g[3]),
               tf = Utilities::string_to_double(g[4]);
  const double S = span, a = 0.5 * girder_spacing;
  // the rail's section and a material whose density gives the Rail mass
  // per metre (its beams: add_girders() in bridge_crane_frame.cc)
  const FrameSection rail =
      parse_frame_section(rail_section, bridge_crane_where + "Rail section");
  f.sections["rail"] = rail;
  FrameMaterial rail_material = f.materials.at("steel");
  rail_material.rho = rail_mass_per_metre / rail.A;
  f.materials["rail"] = rail_material;
  f.solids.degree = girder_element_degree;
  for (unsigned int k = 1; k <= 2; ++k)
  {
    const std::string name = "girder_" + std::to_string(k);
    const double x = k == 1 ? -a : a;
    SolidDescription::Solid s;
    s.name = name;
    s.kind = "box girder";
    s.x0 = Point<3>(x, 0., 0.);
    s.x1 = Point<3>(x, S, 0.);
    s.width = b;
    s.height = h;
    s.web_thickness = tw;
    s.flange_thickness = tf;
    s.element_size = girder_element_size;
    s.diaphragm_spacing = girder_diaphragm_spacing;
    s.material = "steel";
    f.solids.solids.push_back(s);
    // the end carriages' joints on the walls of the girder's end faces:
    // tied to the end diaphragm's face too, the joint carried its moments
    // through that 6 mm plate in bending (the bridge's sway 37 % below the
    // beam crane's, doc/theory.md 11.2)
    for (unsigned int c = 1; c <= 2; ++c)
    {
      SolidDescription::Tie t;
      t.name = "joint_" + std::to_string(k) + "_" + std::to_string(c);
      t.node = t.name;
      t.face.solid = name;
      t.face.axis = 1;
      t.face.value = c == 1 ? 0. : S;
      t.face.walls = true;
      f.solids.ties.push_back(t);
    }
    // the mid-span deflection: the bottom flange's node nearest the axis
    f.solids.monitors.push_back(
        {name + "_midspan", name, Point<3>(x, 0.5 * S, -0.5 * h)});
    // cuts at the diaphragms, or at every tenth of the span
    std::vector<double> cuts = diaphragm_centres(S, girder_diaphragm_spacing, tw);
    if (cuts.empty())
      for (unsigned int j = 1; j < 10; ++j)
        cuts.push_back(0.1 * j * S);
    for (unsigned int j = 0; j < cuts.size(); ++j)
      f.solids.cuts.push_back({name + "_cut_" + std::to_string(j), name, 0, cuts[j]});
  }
}

double BridgeCrane::Parameters::rail_tie_radius() const
{
  const std::vector<std::string> r = section_values(rail_section);
  const double foot =
      r[0] == "general" ? general_rail_foot_width : Utilities::string_to_double(r[1]);
  return std::max(0.5 * foot, 0.75 * girder_element_size);
}
} // namespace hati

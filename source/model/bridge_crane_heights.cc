// The bridge crane's true heights (Model/Bridge crane/Eccentricities,
// doc/user_guide.md "True heights"): the entries and the heights of the
// offsets; the offsets' nodes, members and rigid links are generated with
// the rest of the frame (bridge_crane_frame.cc).
#include <deal.II/base/utilities.h>

#include <hati/model/bridge_crane.h>
#include <hati/model/frame_parser.h>

#include <cmath>
#include <sstream>

namespace hati
{
void BridgeCrane::Parameters::declare_heights(ParameterHandler &prm)
{
  prm.declare_entry(
      "Eccentricities",
      "true",
      Patterns::Bool(),
      "true (default): every wheel acts at its true height. The crane wheels' contact "
      "points (and the supports of Travel = tied or Crane wheels = pinned) lie on the "
      "runway rail head, End carriage height below the end carriages' axis; the "
      "trolley wheels' contact points on the trolley rails' heads, half the girder "
      "height plus the rail (65 mm) above the girder axis for beam girders, on the "
      "rail beams' nodes for solid girders; the trolley frame and the hook point 0.5 "
      "m above the rail heads. Each offset is a short member (a post) whose end "
      "follows the axis node by a rigid link (Model/Frame/Rigid links): horizontal "
      "forces have their lever arms and rock the crane. false: every mass and wheel "
      "on the member axes (no lever arm: horizontal and vertical responses "
      "uncoupled), the results of the crane before this entry; the paper-case and "
      "comparison parameter files set it.");
  prm.declare_entry(
      "End carriage height",
      "0.5",
      Patterns::Double(),
      "Eccentricities = true: height of the end carriages' axis (and of the girder "
      "axes joined to them) above the runway rail head (m), from 0.05 m (a wheel's "
      "radius at least; a shorter post would make the explicit step vanish) to 20 m. "
      "Default 0.5 m: the wheel's radius (about 0.2 m for a 20 t crane) plus half an "
      "end carriage 0.5 m deep (doc/crane_data.md section 3, estimate).");
}

void BridgeCrane::Parameters::parse_heights(ParameterHandler &prm)
{
  eccentricities = prm.get_bool("Eccentricities");
  end_carriage_height = prm.get_double("End carriage height");
  if (!(end_carriage_height >= 0.05 && end_carriage_height <= 20.))
  {
    std::ostringstream m;
    m << bridge_crane_where << "End carriage height: expected a height above the rail "
      << "head from 0.05 m (a wheel's radius at least: a shorter post stiffens the "
      << "explicit step to nothing) to 20 m, got " << prm.get("End carriage height")
      << " m";
    AssertThrow(false, ExcMessage(m.str()));
  }
}

void BridgeCrane::Parameters::check_flange_depth() const
{
  const FrameSection g =
      parse_frame_section(girder_section, bridge_crane_where + "Girder section");
  const double h = g.h > 0. ? g.h : 2. * std::sqrt(g.Iy / g.A);
  if (!(runway.flange_depth < h))
  {
    std::ostringstream m;
    m << bridge_crane_where << "Flange depth = " << runway.flange_depth
      << " m: expected less than the girder height (" << h
      << " m, Girder section); a wheel's flange is a few centimetres deep";
    AssertThrow(false, ExcMessage(m.str()));
  }
}

double BridgeCrane::Parameters::rail_head_height() const
{
  if (!eccentricities || girder_model == "solid")
    return rail_height();
  const std::vector<std::string> g = Utilities::split_string_list(girder_section, ',');
  // a general section has no height: its radius of gyration stands for half of it
  const double half_height =
      Utilities::trim(g[0]) == "general"
          ? std::sqrt(
                parse_frame_section(girder_section, bridge_crane_where + "Girder section")
                    .Iy /
                parse_frame_section(girder_section, bridge_crane_where + "Girder section")
                    .A)
          : 0.5 * Utilities::string_to_double(Utilities::trim(g[2]));
  return half_height + trolley_rail_height;
}

double BridgeCrane::Parameters::trolley_frame_height() const
{
  return rail_head_height() + trolley_height;
}

double BridgeCrane::Parameters::offset_mass(const bool bridge) const
{
  if (!eccentricities)
    return 0.;
  const double A_t =
      parse_frame_section(trolley_section, bridge_crane_where + "Trolley section").A;
  if (!bridge)
    return rho * A_t * 4. * trolley_height;
  const double A_ec = parse_frame_section(end_carriage_section,
                                          bridge_crane_where + "End carriage section")
                          .A;
  return rho * 4. *
         (A_ec * end_carriage_height +
          (girder_model == "solid" ? 0. : A_t * rail_head_height()));
}
} // namespace hati

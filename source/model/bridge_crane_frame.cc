#include <hati/model/bridge_crane.h>
#include <hati/model/frame_parser.h>

#include <algorithm>
#include <cmath>

namespace hati
{
namespace
{
using CraneParameters = BridgeCrane::Parameters;

/**
 * Stations along a line of length @p L: 0, L, the @p fixed points and the
 * edges of the @p zones (clipped to [0, L]), each interval divided into equal
 * elements no longer than @p h, or @p h_zone inside a zone.
 */
std::vector<double> stations(const double L,
                             const std::vector<double> &fixed,
                             const std::vector<std::pair<double, double>> &zones,
                             const double h,
                             const double h_zone)
{
  std::vector<double> breaks = {0., L};
  breaks.insert(breaks.end(), fixed.begin(), fixed.end());
  for (const auto &[a, b] : zones)
    for (const double x : {a, b})
      if (x > 0. && x < L)
        breaks.push_back(x);
  std::sort(breaks.begin(), breaks.end());
  std::vector<double> unique;
  for (const double x : breaks)
    if (unique.empty() || x - unique.back() > 1e-9 * L)
      unique.push_back(x);
  std::vector<double> s = {0.};
  for (unsigned int i = 0; i + 1 < unique.size(); ++i)
  {
    const double a = unique[i], b = unique[i + 1], mid = 0.5 * (a + b);
    bool in_zone = false;
    for (const auto &z : zones)
      in_zone = in_zone || (mid > z.first && mid < z.second);
    const unsigned int n = std::max(
        1u,
        static_cast<unsigned int>(std::ceil((b - a) / (in_zone ? h_zone : h) - 1e-9)));
    for (unsigned int k = 1; k <= n; ++k)
      s.push_back(k == n ? b : a + (b - a) * k / n);
  }
  return s;
}

/** Index of @p x in @p s (it is one of the stations). */
unsigned int station_index(const std::vector<double> &s, const double x)
{
  unsigned int best = 0;
  for (unsigned int i = 1; i < s.size(); ++i)
    if (std::abs(s[i] - x) < std::abs(s[best] - x))
      best = i;
  return best;
}

/** Add the node @p name at (x, y, z) (m) to @p f. */
void add_node(FrameDescription &f,
              const std::string &name,
              const double x,
              const double y,
              const double z)
{
  f.add_node(name, Point<3>(x, y, z));
}

/** Add a member of steel along the nodes @p path, one element between two. */
void add_path_member(FrameDescription &f,
                     const std::string &name,
                     const std::vector<std::string> &path,
                     const std::string &section)
{
  FrameDescription::Member m;
  m.name = name;
  m.path = path;
  m.start = path.front();
  m.end = path.back();
  m.section = section;
  m.material = section == "rail" ? "rail" : "steel";
  m.n_elements = path.size() - 1;
  f.members.push_back(m);
}

/** Add a point mass of @p mass (kg) at @p node. */
void add_point_mass(FrameDescription &f, const std::string &node, const double mass)
{
  FrameDescription::PointMassData p;
  p.node = node;
  p.mass = mass;
  f.point_masses.push_back(p);
}

/** The material `steel` and the sections `girder`, `end_carriage`, `trolley`. */
void add_materials_and_sections(const CraneParameters &p, FrameDescription &f)
{
  FrameMaterial steel;
  steel.E = p.E;
  steel.G = p.E / (2. * (1. + p.nu));
  steel.rho = p.rho;
  f.materials["steel"] = steel;
  f.sections["girder"] =
      parse_frame_section(p.girder_section, bridge_crane_where + "Girder section");
  f.sections["end_carriage"] = parse_frame_section(
      p.end_carriage_section, bridge_crane_where + "End carriage section");
  f.sections["trolley"] =
      parse_frame_section(p.trolley_section, bridge_crane_where + "Trolley section");
}

/**
 * End carriages along X at Y = 0 and Y = S: crane wheels cw1..cw4 at the
 * ends, girder joints at x = -a, +a.
 */
void add_end_carriages(const CraneParameters &p, FrameDescription &f)
{
  const double S = p.span, a = 0.5 * p.girder_spacing, w = 0.5 * p.end_carriage_wheelbase,
               hz = 0.5 * p.explicit_zone_length;
  const std::vector<double> xs = stations(2. * w,
                                          {w - a, w + a},
                                          {{-hz, hz}, {2. * w - hz, 2. * w + hz}},
                                          p.element_length,
                                          p.explicit_element_length);
  // the joints' stations, found once (a search per station would be
  // quadratic in the number of elements)
  const unsigned int joint_1 = station_index(xs, w - a),
                     joint_2 = station_index(xs, w + a);
  for (unsigned int c = 1; c <= 2; ++c)
  {
    const double y = c == 1 ? 0. : S;
    std::vector<std::string> path;
    for (unsigned int i = 0; i < xs.size(); ++i)
    {
      std::string name = "end_carriage_" + std::to_string(c) + "_" + std::to_string(i);
      // with eccentricities the crane wheels' nodes cw<k> lie on the rail
      // head below these (add_offsets())
      const std::string axis = p.eccentricities ? "_axis" : "";
      if (i == 0)
        name = "cw" + std::to_string(2 * c - 1) + axis;
      else if (i + 1 == xs.size())
        name = "cw" + std::to_string(2 * c) + axis;
      else if (i == joint_1)
        name = "joint_1_" + std::to_string(c);
      else if (i == joint_2)
        name = "joint_2_" + std::to_string(c);
      add_node(f, name, xs[i] - w, y, 0.);
      path.push_back(name);
    }
    add_path_member(f, "end_carriage_" + std::to_string(c), path, "end_carriage");
  }
}

/**
 * Girders along Y at x = -a (girder_1) and +a (girder_2), a node rail_<i>
 * under each trolley wheel; the rail mass lumped on their nodes. With
 * Girder model = solid: the box-girder solids (add_solid_girders()) and on
 * each a trolley rail, a beam trolley_rail_<g> at the top flange's height
 * with the same stations, tied at each node to the flange under it except
 * at the edges of the explicit zones (a node shared by HATI's two
 * subdomains cannot be tied; the rail spans the gap).
 */
void add_girders(const CraneParameters &p, FrameDescription &f)
{
  const double S = p.span, a = 0.5 * p.girder_spacing, yc = p.trolley_position * S,
               y1 = yc - 0.5 * p.trolley_wheelbase, y2 = yc + 0.5 * p.trolley_wheelbase,
               hz = 0.5 * p.explicit_zone_length, zr = p.rail_height();
  const bool solid = p.girder_model == "solid";
  if (solid)
    p.add_solid_girders(f);
  const std::vector<double> ys = stations(S,
                                          {y1, y2},
                                          {{y1 - hz, y1 + hz}, {y2 - hz, y2 + hz}},
                                          p.element_length,
                                          p.explicit_element_length);
  // the rail nodes' stations, found once (not a search per station)
  const unsigned int rail_1 = station_index(ys, y1), rail_2 = station_index(ys, y2);
  const std::string prefix = solid ? "trolley_rail_" : "girder_";
  // beam girders with eccentricities: the girder node under a trolley wheel
  // is rail_<k>_axis, rail_<k> is the rail head above it (add_offsets())
  const std::string axis = p.eccentricities && !solid ? "_axis" : "";
  for (unsigned int g = 1; g <= 2; ++g)
  {
    std::vector<std::string> path;
    for (unsigned int i = 0; i < ys.size(); ++i)
    {
      std::string name = prefix + std::to_string(g) + "_" + std::to_string(i);
      if (i == 0 && !solid)
        name = "joint_" + std::to_string(g) + "_1";
      else if (i + 1 == ys.size() && !solid)
        name = "joint_" + std::to_string(g) + "_2";
      else if (i == rail_1)
        name = "rail_" + std::to_string(2 * g - 1) + axis;
      else if (i == rail_2)
        name = "rail_" + std::to_string(2 * g) + axis;
      else
        add_node(f, name, g == 1 ? -a : a, ys[i], zr);
      path.push_back(name);
      if (solid)
      {
        const bool zone_edge = hz > 0. && (std::abs(ys[i] - (y1 - hz)) < 1e-9 * S ||
                                           std::abs(ys[i] - (y2 + hz)) < 1e-9 * S);
        if (!zone_edge)
          f.solids.ties.push_back(
              {"rail_tie_" + std::to_string(g) + "_" + std::to_string(i),
               name,
               {"girder_" + std::to_string(g), 2, zr, p.rail_tie_radius()}});
        continue; // the rail's own mass
      }
      const double tributary = 0.5 * ((i > 0 ? ys[i] - ys[i - 1] : 0.) +
                                      (i + 1 < ys.size() ? ys[i + 1] - ys[i] : 0.));
      if (p.rail_mass_per_metre > 0.)
        add_point_mass(f, name, p.rail_mass_per_metre * tributary);
    }
    add_node(f, "rail_" + std::to_string(2 * g - 1) + axis, g == 1 ? -a : a, y1, zr);
    add_node(f, "rail_" + std::to_string(2 * g) + axis, g == 1 ? -a : a, y2, zr);
    if (solid)
      add_path_member(f, "trolley_rail_" + std::to_string(g), path, "rail");
    else
      add_path_member(f, "girder_" + std::to_string(g), path, "girder");
  }
}

/**
 * The trolley frame above the girders: wheels tw1, tw2 on girder_1 (y1,
 * y2), tw3, tw4 on girder_2; the hoist on a beam across at yc; the trolley
 * and hoist masses.
 */
void add_trolley(const CraneParameters &p, FrameDescription &f)
{
  const double S = p.span, a = 0.5 * p.girder_spacing, yc = p.trolley_position * S,
               y1 = yc - 0.5 * p.trolley_wheelbase, y2 = yc + 0.5 * p.trolley_wheelbase;
  // above the rails (the girder axes for beam girders without eccentricities;
  // with them the frame's corners are tw<k>_frame, the wheels tw<k> on the
  // rail heads below them, add_offsets())
  const double zt = p.trolley_frame_height();
  const std::string corner = p.eccentricities ? "_frame" : "";
  const std::string tw1 = "tw1" + corner, tw2 = "tw2" + corner, tw3 = "tw3" + corner,
                    tw4 = "tw4" + corner;
  add_node(f, tw1, -a, y1, zt);
  add_node(f, tw2, -a, y2, zt);
  add_node(f, tw3, a, y1, zt);
  add_node(f, tw4, a, y2, zt);
  add_node(f, "ts1", -a, yc, zt);
  add_node(f, "ts2", a, yc, zt);
  add_node(f, "hoist", 0., yc, zt);
  auto straight = [&](const std::string &name,
                      const std::string &from,
                      const std::string &to,
                      const double length)
  {
    FrameDescription::Member m;
    m.name = name;
    m.start = from;
    m.end = to;
    m.section = "trolley";
    m.material = "steel";
    m.n_elements = std::max(
        1u, static_cast<unsigned int>(std::ceil(length / p.element_length - 1e-9)));
    f.members.push_back(m);
  };
  straight("trolley_side_1a", tw1, "ts1", 0.5 * p.trolley_wheelbase);
  straight("trolley_side_1b", "ts1", tw2, 0.5 * p.trolley_wheelbase);
  straight("trolley_side_2a", tw3, "ts2", 0.5 * p.trolley_wheelbase);
  straight("trolley_side_2b", "ts2", tw4, 0.5 * p.trolley_wheelbase);
  straight("trolley_end_1", tw1, tw3, p.girder_spacing);
  straight("trolley_end_2", tw2, tw4, p.girder_spacing);
  straight("trolley_beam_1", "ts1", "hoist", a);
  straight("trolley_beam_2", "hoist", "ts2", a);
  for (const std::string &n : {tw1, tw2, tw3, tw4})
    if (p.trolley_mass > 0.)
      add_point_mass(f, n, 0.25 * p.trolley_mass);
  if (p.hoist == "rigid")
  {
    if (p.hoist_mass > 0.)
      add_point_mass(f, "hoist", p.hoist_mass);
    return;
  }
  // the load on its rope below the trolley's centre (R1)
  add_node(f, "load", 0., yc, zt - p.rope_length);
  add_point_mass(f, "load", p.hoist_mass);
  FrameDescription::RopeData rope;
  rope.name = "hoist_rope";
  rope.node = "hoist";
  rope.other_node = "load";
  rope.stiffness = p.rope_stiffness;
  rope.rest_length = p.rope_length;
  f.ropes.push_back(rope);
}

/**
 * Eccentricities = true: the offsets of the true heights. Each is a post,
 * a member of one element between an axis node and the point where a wheel
 * acts, and a rigid link that makes the post rigid:
 * - crane wheel k: post `crane_wheel_post_<k>` (End carriage section) from
 *   the rail head node cw<k>, End carriage height below the end carriage's
 *   end cw<k>_axis; the link's master is cw<k>, which carries the wheel
 *   contact and the supports of Travel = tied or Crane wheels = pinned (a
 *   support on a rigid link's slave is refused);
 * - beam girders, trolley rail k: post `rail_post_<k>` (Trolley section)
 *   from the girder node rail_<k>_axis (master) up to the rail head node
 *   rail_<k> (slave), half the girder height plus the rail above;
 * - trolley wheel k: post `trolley_wheel_post_<k>` (Trolley section) from
 *   the frame's corner tw<k>_frame (master) down to the wheel tw<k> (slave)
 *   on the rail head, so that both nodes of a trolley wheel's contacts lie
 *   at the same point (a pair of contact nodes at different heights would
 *   put a spurious couple into every horizontal contact force).
 * The rigid link needs both its nodes on members (FrameDescription::
 * validate()): the posts give the offset nodes their member, and their
 * mass (offset_mass()), the wheel blocks'.
 */
void add_offsets(const CraneParameters &p, FrameDescription &f)
{
  if (!p.eccentricities)
    return;
  const double S = p.span, a = 0.5 * p.girder_spacing, w = 0.5 * p.end_carriage_wheelbase,
               yc = p.trolley_position * S, y1 = yc - 0.5 * p.trolley_wheelbase,
               y2 = yc + 0.5 * p.trolley_wheelbase, zh = p.rail_head_height();
  const bool solid = p.girder_model == "solid";
  for (unsigned int k = 1; k <= 4; ++k)
  {
    const std::string n = std::to_string(k);
    // wheels 1, 2 at Y = 0; odd wheels at x = -w (crane) or on girder_1 (trolley)
    add_node(f, "cw" + n, k % 2 == 1 ? -w : w, k <= 2 ? 0. : S, -p.end_carriage_height);
    add_path_member(
        f, "crane_wheel_post_" + n, {"cw" + n, "cw" + n + "_axis"}, "end_carriage");
    f.solids.rigid_links.push_back(
        {"crane_wheel_link_" + n, "cw" + n, "cw" + n + "_axis"});
    const double xt = k <= 2 ? -a : a, yt = k % 2 == 1 ? y1 : y2;
    if (!solid)
    {
      add_node(f, "rail_" + n, xt, yt, zh);
      add_path_member(
          f, "rail_post_" + n, {"rail_" + n + "_axis", "rail_" + n}, "trolley");
      f.solids.rigid_links.push_back(
          {"rail_link_" + n, "rail_" + n + "_axis", "rail_" + n});
    }
    add_node(f, "tw" + n, xt, yt, zh);
    add_path_member(
        f, "trolley_wheel_post_" + n, {"tw" + n + "_frame", "tw" + n}, "trolley");
    f.solids.rigid_links.push_back(
        {"trolley_wheel_link_" + n, "tw" + n + "_frame", "tw" + n});
  }
}

/** Supports: tied crane wheels along the runway; pinned wheels. */
void add_supports(const CraneParameters &p, FrameDescription &f)
{
  if (p.travel == "tied" || p.crane_wheels == "pinned")
    for (unsigned int k = 1; k <= 4; ++k)
    {
      FrameDescription::Support s;
      s.node = "cw" + std::to_string(k);
      s.stiffness[0] = 0.;
      if (p.crane_wheels == "pinned")
        s.stiffness[1] = s.stiffness[2] = 0.;
      f.supports.push_back(s);
    }
}

/** The wheel contacts of the crane wheels on the rails and the trolley wheels. */
void add_wheel_contacts(const CraneParameters &p, FrameDescription &f)
{
  // Travel = braked | free: Coulomb friction at the vertical wheel contacts,
  // a wheel that is not braked rolls along its rail (rolls=, A9)
  const bool friction = p.travel != "tied";
  auto contact = [&](const std::string &name,
                     const std::string &node_name,
                     const std::string &other,
                     const Tensor<1, 3> &normal,
                     const double gap,
                     const bool two_sided,
                     const int rolls = -2)
  {
    // friction where the wheel is braked (rolls = -1) or rolls along an axis
    const bool rubs = friction && rolls > -2;
    f.contacts.push_back(FrameDescription::NodeContact{name,
                                                       node_name,
                                                       other,
                                                       normal,
                                                       gap,
                                                       p.wheel_restitution,
                                                       two_sided,
                                                       rubs ? p.wheel_friction : 0.,
                                                       rubs ? rolls : -1});
  };
  const Tensor<1, 3> ex({1., 0., 0.}), ey({0., 1., 0.}), ez({0., 0., 1.});
  for (unsigned int k = 1; k <= 4 && p.crane_wheels == "contacts"; ++k)
  {
    const std::string cw = "crane_wheel_" + std::to_string(k);
    // on the ground, or on its runway node (Runway = springs)
    const std::string runway = p.runway.springs() ? "runway_" + std::to_string(k) : "";
    contact(cw,
            "cw" + std::to_string(k),
            runway,
            ez,
            0.,
            false,
            p.crane_wheel_braked(k) ? -1 : 0);
    contact(
        cw + "_lateral", "cw" + std::to_string(k), runway, ey, p.flange_clearance, true);
  }
  // solid girders: the trolley held along Y at one wheel per rail (1 and
  // 3), the others rolling: held at both, the top flange's strain between
  // them would load the trolley frame (the beam girders' rail nodes lie on
  // their neutral axes, where there is none)
  const bool solid = p.girder_model == "solid";
  for (unsigned int k = 1; k <= 4; ++k)
  {
    const std::string tw = "trolley_wheel_" + std::to_string(k),
                      wn = "tw" + std::to_string(k), rn = "rail_" + std::to_string(k);
    const bool held = !solid || k == 1 || k == 3;
    contact(tw, wn, rn, ez, 0., false, p.travel == "braked" && held ? -1 : 1);
    contact(tw + "_lateral", wn, rn, ex, p.flange_clearance, true);
    if (p.travel == "tied" && held)
      contact(tw + "_travel", wn, rn, ey, 0., true);
  }
  // with a Flange depth, each wheel's flanges over its rail (D1-D2)
  for (unsigned int k = 1; k <= 4; ++k)
  {
    if (p.crane_wheels == "contacts")
      p.runway.add_flange(f, "crane_wheel_" + std::to_string(k));
    p.runway.add_flange(f, "trolley_wheel_" + std::to_string(k));
  }
  // the seismic restraints after every wheel contact (the rows of an
  // unrestrained crane unchanged)
  for (unsigned int k = 1; k <= 4; ++k)
  {
    const std::string n = std::to_string(k);
    if (p.runway.restrained(false) && p.crane_wheels == "contacts")
      p.runway.add_restraint(
          f, "crane_wheel_" + n, "cw" + n, p.runway.springs() ? "runway_" + n : "");
    if (p.runway.restrained(true))
      p.runway.add_restraint(f, "trolley_wheel_" + n, "tw" + n, "rail_" + n);
  }
}
} // namespace

FrameDescription BridgeCrane::Parameters::frame() const
{
  FrameDescription f;
  add_materials_and_sections(*this, f);
  add_end_carriages(*this, f);
  add_girders(*this, f);
  add_trolley(*this, f);
  add_offsets(*this, f);
  add_supports(*this, f);
  add_wheel_contacts(*this, f);
  f.monitor_nodes = {"hoist", "tw1", "tw2", "tw3", "tw4", "cw1", "cw2", "cw3", "cw4"};
  if (hoist == "rope")
    f.monitor_nodes.push_back("load");
  // the runway nodes on their springs (their monitors after the crane's)
  for (unsigned int k = 1; k <= 4 && crane_wheels == "contacts"; ++k)
    runway.add_runway_node(f, k, E, nu);
  // solid girders: their cuts instead (add_solid_girders())
  if (girder_model != "solid")
    f.section_force_members = {"girder_1", "girder_2"};
  return f;
}

} // namespace hati

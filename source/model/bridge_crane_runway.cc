// The bridge crane on its runway (doc/user_guide.md "The crane on its
// runway"): the seismic restraints against uplift, the runway springs and
// the runway wheels and their flanges (BridgeCrane::runway_wheels(),
// wheel_lateral_contacts())
#include <hati/model/bridge_crane.h>
#include <hati/model/bridge_crane_runway.h>

#include <cmath>
#include <sstream>

namespace hati
{
namespace
{
const std::string runway_where = "Model/Bridge crane/";

std::string prm_number(const double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}
} // namespace

void RunwayParameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry(
      "Uplift restraints",
      "none",
      Patterns::Selection("none|crane wheels|trolley wheels|both"),
      "Seismic restraints against uplift (the lugs or clips under the rail head of "
      "ASME NOG-1 Type I and KTA 3902 cranes): a one-sided contact "
      "<wheel>_restraint that stops each restrained wheel when it has lifted by "
      "the Restraint clearance (contacts.csv, summary.json contacts). none "
      "(default): nothing holds a wheel down; crane wheels: the four bridge "
      "wheels, against the ground; trolley wheels: the four trolley wheels, "
      "against their rail nodes; both.");
  prm.declare_entry(
      "Runway",
      "rigid",
      Patterns::Selection("rigid|springs"),
      "What the crane wheels run on. rigid (default): the ground, which moves with "
      "the base; springs: each crane wheel on a runway node runway_<i> held to the "
      "ground by the Runway vertical, lateral and longitudinal stiffness (the "
      "runway girder's stiffness at the wheel, its column and bracket) with the "
      "Runway mass per wheel; the spring forces are summary.json runway_reaction.");
  prm.declare_entry("Runway vertical stiffness",
                    "2e8",
                    Patterns::Double(),
                    "Runway = springs: vertical stiffness at each crane wheel (N/m), "
                    "> 0 and at most 1e12 (user guide: a hand estimate from the "
                    "runway girder's span and section).");
  prm.declare_entry("Runway lateral stiffness",
                    "5e7",
                    Patterns::Double(),
                    "Runway = springs: stiffness across the rail (Y) at each crane "
                    "wheel (N/m), > 0 and at most 1e12.");
  prm.declare_entry("Runway longitudinal stiffness",
                    "5e8",
                    Patterns::Double(),
                    "Runway = springs: stiffness along the rail (X) at each crane wheel "
                    "(N/m), > 0 and at most 1e12.");
  prm.declare_entry("Runway mass per wheel",
                    "500",
                    Patterns::Double(),
                    "Runway = springs: the runway's mass that moves with each crane "
                    "wheel (kg), > 0 and at most 1e6.");
  prm.declare_entry(
      "Flange depth",
      "0",
      Patterns::Double(),
      "The depth of the wheels' flanges below the rail head's top (m), >= 0 and "
      "below the girder height: while a wheel has lifted by more than this its "
      "lateral flange contacts do not act (they pass over the rail head), and a "
      "wheel above its flange whose lateral offset exceeds the Flange clearance "
      "plus half the Rail head width has left its rail: the run stops with status "
      "derailed (summary.json derailment, exit code 0). Default 0: the flanges "
      "always engage. Every wheel, crane and trolley.");
  prm.declare_entry("Rail head width",
                    "0.055",
                    Patterns::Double(),
                    "The width of the rail head (m), > 0 and at most 0.5 m: with a "
                    "Flange depth, a wheel above its flange derails beyond a lateral "
                    "offset of Flange clearance + Rail head width / 2. Default 55 mm "
                    "(an A55 crane rail).");
  prm.declare_entry("Restraint clearance",
                    "0.01",
                    Patterns::Double(),
                    "The uplift a restraint allows (m), > 0 and at most 0.5 m: the gap "
                    "between the clip and the underside of the rail head. Default 10 "
                    "mm.");
  prm.declare_entry("Restraint restitution",
                    "0",
                    Patterns::Double(),
                    "Newton's restitution coefficient of the restraint contacts (-), "
                    "in [0, 1]. Default 0: plastic, as the wheel contacts.");
}

void RunwayParameters::parse_parameters(ParameterHandler &prm)
{
  uplift_restraints = prm.get("Uplift restraints");
  restraint_clearance = prm.get_double("Restraint clearance");
  AssertThrow(std::isfinite(restraint_clearance) && restraint_clearance > 0. &&
                  restraint_clearance <= 0.5,
              ExcMessage(runway_where +
                         "Restraint clearance = " + prm.get("Restraint clearance") +
                         ": expected an uplift > 0 and at most 0.5 m"));
  runway = prm.get("Runway");
  const auto positive =
      [&](const std::string &entry, const double bound, const char *unit)
  {
    const double x = prm.get_double(entry);
    AssertThrow(std::isfinite(x) && x > 0. && x <= bound,
                ExcMessage(runway_where + entry + " = " + prm.get(entry) +
                           ": expected a value > 0 and at most " + prm_number(bound) +
                           " " + unit));
    return x;
  };
  vertical_stiffness = positive("Runway vertical stiffness", 1e12, "N/m");
  lateral_stiffness = positive("Runway lateral stiffness", 1e12, "N/m");
  longitudinal_stiffness = positive("Runway longitudinal stiffness", 1e12, "N/m");
  mass_per_wheel = positive("Runway mass per wheel", 1e6, "kg");
  flange_depth = prm.get_double("Flange depth");
  AssertThrow(std::isfinite(flange_depth) && flange_depth >= 0.,
              ExcMessage(runway_where + "Flange depth = " + prm.get("Flange depth") +
                         ": expected a depth >= 0 m (0: the flanges always engage)"));
  rail_head_width = positive("Rail head width", 0.5, "m");
  restraint_restitution = prm.get_double("Restraint restitution");
  AssertThrow(std::isfinite(restraint_restitution) && restraint_restitution >= 0. &&
                  restraint_restitution <= 1.,
              ExcMessage(runway_where +
                         "Restraint restitution = " + prm.get("Restraint restitution") +
                         ": expected a coefficient in [0, 1]"));
}

std::string RunwayParameters::add_runway_node(FrameDescription &frame,
                                              const unsigned int k,
                                              const double E,
                                              const double nu) const
{
  if (!springs())
    return "";
  const std::string n = std::to_string(k), node = "runway_" + n,
                    anchor = "runway_anchor_" + n;
  const Point<3> x = frame.nodes.at("cw" + n);
  const double L = runway_post_length;
  frame.add_node(node, x);
  frame.add_node(anchor, x + Point<3>(0., 0., -L));
  // the post from the node down: local x = -Z, local y = Y, local z = X;
  // Iy bends it along X, Iz along Y (guided cantilever, 12 E I / L^3)
  FrameSection post;
  post.A = vertical_stiffness * L / E;
  post.Iy = longitudinal_stiffness * L * L * L / (12. * E);
  post.Iz = lateral_stiffness * L * L * L / (12. * E);
  post.J = post.Iy + post.Iz;
  frame.sections["runway_post"] = post;
  FrameMaterial material;
  material.E = E;
  material.G = E / (2. * (1. + nu));
  // a tenth of the runway's mass in the post (an element of negligible mass
  // would bound the explicit step at some 1e-8 s), the rest at the node, so
  // that the node's lumped mass is the Runway mass per wheel
  const double post_mass = 0.1 * mass_per_wheel;
  material.rho = post_mass / (post.A * L);
  frame.materials["runway"] = material;
  FrameDescription::Member m;
  m.name = "runway_post_" + n;
  m.start = node;
  m.end = anchor;
  m.section = "runway_post";
  m.material = "runway";
  m.n_elements = 1;
  frame.members.push_back(m);
  FrameDescription::Support held;
  held.node = node;
  held.stiffness = {{-1., -1., -1., 0., 0., 0.}};
  FrameDescription::Support clamped;
  clamped.node = anchor;
  clamped.stiffness = {{0., 0., 0., 0., 0., 0.}};
  frame.supports.push_back(held);
  frame.supports.push_back(clamped);
  FrameDescription::PointMassData mass;
  mass.node = node;
  mass.mass = mass_per_wheel - 0.5 * post_mass;
  frame.point_masses.push_back(mass);
  frame.monitor_nodes.push_back(node);
  return node;
}

void RunwayParameters::add_restraint(FrameDescription &frame,
                                     const std::string &wheel,
                                     const std::string &node,
                                     const std::string &rail) const
{
  // the normal from the clip (above) to the wheel: down; frictionless
  FrameDescription::NodeContact c;
  c.name = wheel + "_restraint";
  c.node = node;
  c.other_node = rail;
  c.normal = Tensor<1, 3>({0., 0., -1.});
  c.gap = restraint_clearance;
  c.restitution = restraint_restitution;
  frame.contacts.push_back(c);
}
void RunwayParameters::add_flange(FrameDescription &frame, const std::string &wheel) const
{
  if (flange_depth > 0.)
    frame.flanges.push_back(
        {wheel, wheel, wheel + "_lateral", flange_depth, rail_head_width});
}

void RunwayParameters::add_reaction_springs(DiscreteSystem &system) const
{
  if (!springs())
    return;
  // vertical: compression, the runway node pushed down
  for (unsigned int k = 1; k <= 4; ++k)
  {
    const std::string wheel = "crane_wheel_" + std::to_string(k),
                      node = "runway_" + std::to_string(k);
    system.reaction_springs.push_back(
        {"runway_reaction", wheel, "longitudinal", node, 0, longitudinal_stiffness, 1.});
    system.reaction_springs.push_back(
        {"runway_reaction", wheel, "lateral", node, 1, lateral_stiffness, 1.});
    system.reaction_springs.push_back(
        {"runway_reaction", wheel, "vertical", node, 2, vertical_stiffness, -1.});
  }
}

std::vector<Model::RunwayWheel> BridgeCrane::runway_wheels() const
{
  if (crane.crane_wheels != "contacts")
    return {};
  std::vector<RunwayWheel> wheels;
  for (unsigned int k = 1; k <= 4; ++k)
  {
    RunwayWheel w;
    w.name = "crane_wheel_" + std::to_string(k);
    w.lateral_contact = w.name + "_lateral";
    if (crane.travel != "tied")
    {
      // as add_wheel_contacts(): braked wheels hold along X and Y, the
      // others roll along X (friction across the rail only)
      const bool braked = crane.crane_wheel_braked(k);
      w.longitudinal_tangent = braked ? 0 : -1;
      w.lateral_tangent = braked ? 1 : 0;
    }
    wheels.push_back(w);
  }
  return wheels;
}

std::vector<std::string> BridgeCrane::wheel_lateral_contacts() const
{
  std::vector<std::string> names = wheel_contacts();
  for (std::string &name : names)
    name += "_lateral";
  return names;
}

} // namespace hati

// The bridge crane on its runway (doc/user_guide.md "The crane on its
// runway"): the seismic restraints against uplift
#include <hati/model/bridge_crane_runway.h>

#include <cmath>

namespace hati
{
namespace
{
const std::string runway_where = "Model/Bridge crane/";
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
  restraint_restitution = prm.get_double("Restraint restitution");
  AssertThrow(std::isfinite(restraint_restitution) && restraint_restitution >= 0. &&
                  restraint_restitution <= 1.,
              ExcMessage(runway_where +
                         "Restraint restitution = " + prm.get("Restraint restitution") +
                         ": expected a coefficient in [0, 1]"));
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
} // namespace hati

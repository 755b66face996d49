#include <deal.II/base/data_out_base.h>

#include <hati/model/point_mass.h>

#include <sstream>

namespace hati
{
void PointMassParameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Mass", "1", Patterns::Double(0.), "Mass of the ball (kg), > 0.");
  prm.declare_entry("Initial height",
                    "1",
                    Patterns::Double(0.),
                    "Height z0 of the ball above the rigid ground z = 0 at t = 0 (m).");
  prm.declare_entry("Initial velocity",
                    "0",
                    Patterns::Double(),
                    "Vertical velocity v0 at t = 0 (m/s), positive upwards.");
}

void PointMassParameters::parse_parameters(ParameterHandler &prm)
{
  mass = prm.get_double("Mass");
  AssertThrow(mass > 0., ExcMessage("Model/Point mass/Mass must be > 0 (kg)."));
  initial_height = prm.get_double("Initial height");
  initial_velocity = prm.get_double("Initial velocity");
}

PointMass::PointMass(const Parameters &parameters) : parameters(parameters) {}

void PointMass::build(const CommonModelParameters &common, DiscreteSystem &system)
{
  system.reinit(3);
  for (unsigned int d = 0; d < 3; ++d)
  {
    system.lumped_mass[d] = parameters.mass;
    system.constant_force[d] = parameters.mass * common.gravity[d]; // F = M g
  }
  system.initial_velocity[2] = parameters.initial_velocity;
  for (unsigned int d = 0; d < 3; ++d)
  {
    system.influence[d].reinit(3);
    system.influence[d][d] = 1.;
  }

  ContactRow ground;
  ground.name = common.contact_name;
  ground.dofs = {2};
  ground.coefficients = {1.};
  ground.initial_gap = parameters.initial_height;
  ground.restitution = common.restitution;
  system.contacts.push_back(ground);

  system.monitors.push_back({"ball", {"x", "y", "z"}, {0, 1, 2}, {}});
}

void PointMass::write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const
{
  const auto &[fields, time, cycle] = snapshot;
  // a single VTK vertex at the current position, 3 components per field
  std::vector<DataOutBase::Patch<0, 3>> patches(1);
  auto &patch = patches[0];
  patch.patch_index = 0;
  patch.vertices[0] = Point<3>(0., 0., parameters.initial_height);
  patch.data.reinit(3 * fields.size(), 1);
  std::vector<std::string> names;
  std::vector<std::tuple<unsigned int,
                         unsigned int,
                         std::string,
                         DataComponentInterpretation::DataComponentInterpretation>>
      ranges;
  for (unsigned int f = 0; f < fields.size(); ++f)
  {
    for (unsigned int d = 0; d < 3; ++d)
    {
      patch.data(3 * f + d, 0) = (*fields[f].second)[d];
      names.push_back(fields[f].first);
    }
    ranges.emplace_back(3 * f,
                        3 * f + 2,
                        fields[f].first,
                        DataComponentInterpretation::component_is_part_of_vector);
  }
  DataOutBase::VtkFlags flags(time, cycle);
  DataOutBase::write_vtu(patches, names, ranges, flags, out);
}

std::string PointMass::description() const
{
  std::ostringstream s;
  s << "point mass m = " << parameters.mass << " kg at z0 = " << parameters.initial_height
    << " m above a rigid ground";
  return s.str();
}
} // namespace hati

namespace hati
{
std::vector<Point<3>> PointMass::cell_centres() const
{
  return {}; // a rigid body has no cells: it cannot be decomposed
}
} // namespace hati

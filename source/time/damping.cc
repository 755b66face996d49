#include <hati/time/damping.h>

namespace hati
{
namespace
{
/** Rayleigh damping: RayleighDamping read from its entries. */
RayleighDamping read_rayleigh_damping(dealii::ParameterHandler &prm)
{
  RayleighDamping damping;
  damping.parse_parameters(prm);
  return damping;
}
} // namespace

const Registry<DampingFactory> &damping_registry()
{
  // one entry per damping model: name, documentation, parameters, reader
  static const Registry<DampingFactory> registry(
      "Time integration/Damping/Type",
      {{"Rayleigh",
        "Rayleigh: C = a0 M + a1 K in CD-Lagrange (A7) and Newmark, from the "
        "coefficients or from a damping ratio at two frequencies",
        RayleighDamping::declare_parameters,
        read_rayleigh_damping}});
  return registry;
}

void declare_damping_parameters(dealii::ParameterHandler &prm)
{
  const auto &models = damping_registry();
  prm.declare_entry("Type",
                    "Rayleigh",
                    dealii::Patterns::Selection(models.selection()),
                    "Damping model of a transient run: " + models.join("; ", "; ", true) +
                        ". Static and modal analyses ignore damping.");
  models.declare_parameters(prm);
}

RayleighDamping parse_damping_parameters(dealii::ParameterHandler &prm)
{
  return damping_registry().get(prm.get("Type")).create(prm);
}
} // namespace hati

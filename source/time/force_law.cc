#include <deal.II/base/exceptions.h>

#include <hati/model/discrete_system.h>
#include <hati/output/law_output.h>
#include <hati/time/force_law.h>
#include <hati/time/rope_forces.h>
#include <hati/time/unilateral_contacts.h>

namespace hati
{
Registry<ForceLawFactory> &force_law_registry()
{
  // one line per law: its registration (name, documentation, factory); the
  // forces are summed and the rows resolved in this order
  static Registry<ForceLawFactory> registry(
      "force law", {RopeForces::registration(), UnilateralContacts::registration()});
  return registry;
}

std::vector<std::unique_ptr<ForceLaw>> make_force_laws(const DiscreteSystem &system)
{
  std::vector<std::unique_ptr<ForceLaw>> laws;
  for (const auto &entry : force_law_registry().entries())
    if (auto law = entry.create(system))
      laws.push_back(std::move(law));
  return laws;
}

std::unique_ptr<LawOutput> ForceLaw::make_output(const LawOutputContext &context) const
{
  (void)context;
  return nullptr;
}

std::string ForceLaw::refusal(const std::string &method) const
{
  if (method == "CD-Lagrange" || method == "HATI")
    return "";
  return "Time integration/Method = " + method + ": the force law '" + name() +
         "' needs the explicit CD-Lagrange integrator (or HATI).";
}

void check_force_laws(const DiscreteSystem &system, const std::string &method)
{
  for (const auto &law : make_force_laws(system))
  {
    const std::string message = law->refusal(method);
    AssertThrow(message.empty(), ExcMessage(message));
  }
}

void sample_force_laws(const std::vector<std::unique_ptr<ForceLaw>> &laws,
                       const Vector<double> &V,
                       LawSample &sample)
{
  for (const auto &law : laws)
    law->sample(V, sample);
}
} // namespace hati

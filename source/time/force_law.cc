#include <deal.II/base/exceptions.h>

#include <hati/model/discrete_system.h>
#include <hati/output/law_output.h>
#include <hati/time/flange_engagement.h>
#include <hati/time/force_law.h>
#include <hati/time/rope_forces.h>
#include <hati/time/unilateral_contacts.h>

#include <algorithm>

namespace hati
{
Registry<ForceLawFactory> &force_law_registry()
{
  // one line per law: its registration (name, documentation, factory); the
  // forces are summed and the rows resolved in this order
  static Registry<ForceLawFactory> registry("force law",
                                            {RopeForces::registration(),
                                             FlangeEngagement::registration(),
                                             UnilateralContacts::registration()});
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

std::any ForceLaw::part_data(const std::vector<int> &local,
                             const std::vector<bool> &fixed) const
{
  (void)local;
  (void)fixed;
  AssertThrow(false,
              ExcMessage("Model/Decomposition: the force law '" + name() +
                         "' cannot be split into HATI's subdomains (it does not "
                         "renumber its data: ForceLaw::part_data())"));
  return {};
}

void extract_law_data(const DiscreteSystem &full,
                      const std::vector<int> &local,
                      DiscreteSystem &part)
{
  part.law_data.clear();
  if (full.law_data.empty())
    return;
  std::vector<std::string> taken;
  for (const auto &law : make_force_laws(full))
    if (full.law_data.count(law->name()) > 0)
    {
      std::any data = law->part_data(local, full.fixed);
      if (data.has_value())
        part.law_data[law->name()] = std::move(data);
      taken.push_back(law->name());
    }
  for (const auto &entry : full.law_data)
    AssertThrow(std::find(taken.begin(), taken.end(), entry.first) != taken.end(),
                ExcMessage("Model/Decomposition: DiscreteSystem::law_data holds '" +
                           entry.first + "', which no registered force law takes"));
}

void sample_force_laws(const std::vector<std::unique_ptr<ForceLaw>> &laws,
                       const Vector<double> &V,
                       LawSample &sample)
{
  for (const auto &law : laws)
    law->sample(V, sample);
}
} // namespace hati

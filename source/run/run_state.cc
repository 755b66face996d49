#include <hati/analysis/reduced_part.h>
#include <hati/run/problem.h>
#include <hati/run/run_state.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/newmark.h>

#include <cstdint>
#include <iomanip>
#include <sstream>
#include <type_traits>
#include <vector>

namespace hati
{
template <class Integrator>
RunState current_run_state(const Integrator &integrator, const Problem &problem)
{
  RunState state;
  state.time = integrator.time();
  state.model = problem.model->description();
  state.displacement = integrator.displacement();
  if constexpr (std::is_same_v<Integrator, Newmark>)
  {
    state.velocity = integrator.velocity();
    state.contact_force.reinit(state.velocity.size());
  }
  else if constexpr (std::is_same_v<Integrator, CDLagrange>)
  {
    integrator.integer_velocity(state.velocity);
    integrator.contact_force(state.contact_force);
  }
  else
  {
    state.velocity = integrator.integer_velocity();
    state.contact_force = integrator.contact_force();
    state.interface_multiplier = integrator.interface_multiplier();
    state.interface_signature = coupling_signature(*problem.decomposition);
    // the implicit side's own values of the interface DoFs
    const std::vector<unsigned int> shared = shared_implicit_dofs(*problem.decomposition);
    const Newmark &implicit = integrator.implicit_part();
    state.implicit_interface.reinit(2 * shared.size());
    for (unsigned int s = 0; s < shared.size(); ++s)
    {
      state.implicit_interface[s] = implicit.displacement()[shared[s]];
      state.implicit_interface[shared.size() + s] = implicit.velocity()[shared[s]];
    }
  }
  if constexpr (!std::is_same_v<Integrator, CDLagrange>)
  {
    std::vector<bool> held(state.displacement.size(), false);
    if (problem.decomposition)
      for (const auto &part : problem.decomposition->parts)
        for (const auto i : part.global_dofs)
          held[i] = true;
    for (Vector<double> *v : {&state.displacement, &state.velocity})
    {
      Vector<double> completed = *v;
      problem.model->complete_solution(completed);
      for (unsigned int i = 0; i < v->size(); ++i)
        if (!held[i])
          (*v)[i] = completed[i];
    }
  }
  return state;
}

std::string coupling_signature(const Decomposition &decomposition)
{
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&hash](const void *data, const std::size_t bytes)
  {
    const auto *b = static_cast<const unsigned char *>(data);
    for (std::size_t i = 0; i < bytes; ++i)
      hash = (hash ^ b[i]) * 1099511628211ull;
  };
  for (const SparseRow &row : decomposition.rows[0])
    for (unsigned int i = 0; i < row.dofs.size(); ++i)
    {
      const std::uint64_t dof = decomposition.parts[0].global_dofs[row.dofs[i]];
      add(&dof, sizeof(dof));
      add(&row.coefficients[i], sizeof(double));
    }
  // the implicit part as it is stepped: its DoFs or reduced coordinates
  const std::uint64_t n_implicit = implicit_system(decomposition).n_dofs();
  add(&n_implicit, sizeof(n_implicit));
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << hash;
  return s.str();
}

std::vector<unsigned int> shared_implicit_dofs(const Decomposition &decomposition)
{
  std::vector<unsigned int> shared;
  const auto &explicit_dofs = decomposition.parts[0].global_dofs;
  const auto &implicit_dofs = decomposition.parts[1].global_dofs;
  if (implicit_system(decomposition).n_dofs() != implicit_dofs.size())
    return shared;
  std::vector<bool> held_explicitly;
  for (const auto i : explicit_dofs)
  {
    if (i >= held_explicitly.size())
      held_explicitly.resize(i + 1, false);
    held_explicitly[i] = true;
  }
  for (unsigned int j = 0; j < implicit_dofs.size(); ++j)
    if (implicit_dofs[j] < held_explicitly.size() && held_explicitly[implicit_dofs[j]])
      shared.push_back(j);
  return shared;
}

template RunState current_run_state(const CDLagrange &, const Problem &);
template RunState current_run_state(const Newmark &, const Problem &);
template RunState current_run_state(const HATICoupling &, const Problem &);
} // namespace hati

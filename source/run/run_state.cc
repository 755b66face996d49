#include <hati/run/problem.h>
#include <hati/run/run_state.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/newmark.h>

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

template RunState current_run_state(const CDLagrange &, const Problem &);
template RunState current_run_state(const Newmark &, const Problem &);
template RunState current_run_state(const HATICoupling &, const Problem &);
} // namespace hati

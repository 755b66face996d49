#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>
#include <hati/run/time_loop.h>
#include <hati/time/force_law.h>
#include <hati/time/newmark.h>

#include <iostream>

namespace hati
{
void run_newmark(Problem &problem, RunDirectory &directory)
{
  // the laws it cannot integrate (ForceLaw::refusal(): contacts, ropes, ...)
  check_force_laws(problem.system, "Newmark");
  const NewmarkParameters &parameters = problem.newmark_parameters;
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  timer.enter_subsection("setup (assembly, factorisation)");
  Newmark integrator(problem.system,
                     problem.time_parameters.time_step,
                     parameters,
                     problem.damping.rayleigh,
                     problem.damping.branches);
  timer.leave_subsection();
  std::cout << "  Newmark (beta = " << parameters.beta << ", gamma = " << parameters.gamma
            << ", " << integrator.linear_solver() << " solver): factorisation "
            << integrator.factorization_time() << " s";
  if (integrator.memory().active())
    std::cout << ", frequency-range damping (" << integrator.memory().n_branches()
              << " branches, beta_s = " << integrator.memory().stiffness_factor() << ")";
  else
    std::cout << ", Rayleigh a0 = " << integrator.mass_damping_coefficient()
              << " 1/s, a1 = " << integrator.stiffness_damping_coefficient() << " s";
  std::cout << std::endl;
  const SummaryEntries method = {{"method", "Newmark"},
                                 {"factorization_time", integrator.factorization_time()}};
  run_time_loop(integrator, problem, directory, timer, method);
}
} // namespace hati

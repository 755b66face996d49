#include <deal.II/base/timer.h>

#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>
#include <hati/run/time_loop.h>
#include <hati/time/cd_lagrange.h>

#include <iostream>

namespace hati
{
void run_cd_lagrange(Problem &problem, RunDirectory &directory)
{
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  timer.enter_subsection("setup");
  CDLagrange integrator(problem.system,
                        problem.time_parameters.time_step,
                        problem.time_parameters.safety_factor,
                        problem.damping.rayleigh,
                        problem.damping.branches);
  timer.leave_subsection();
  std::cout << "  CD-Lagrange: dt_crit = " << integrator.critical_time_step() << " s";
  if (integrator.damped())
    std::cout << ", Rayleigh a0 = " << integrator.mass_damping_coefficient()
              << " 1/s, a1 = " << integrator.stiffness_damping_coefficient() << " s";
  if (integrator.memory().active())
    std::cout << ", frequency-range damping (" << integrator.memory().n_branches()
              << " branches, sum alpha = " << integrator.memory().alpha_sum() << ")";
  std::cout << std::endl;
  const SummaryEntries method = {{"method", "CD-Lagrange"},
                                 {"dt_crit", integrator.critical_time_step()}};
  run_time_loop(integrator, problem, directory, timer, method);
}
} // namespace hati

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <hati/base/wall_clock.h>
#include <hati/output/output_writer.h>
#include <hati/output/run_directory.h>
#include <hati/output/summary.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>
#include <hati/run/run_tools.h>
#include <hati/time/event_driven.h>
#include <hati/time/force_law.h>

#include <iostream>

namespace hati
{

void run_event_driven(Problem &problem, RunDirectory &directory)
{
  const DiscreteSystem &system = problem.system;
  // the laws it cannot integrate (ForceLaw::refusal(): ropes, friction, ...)
  check_force_laws(system, "event-driven");
  const OutputParameters &output = problem.output_parameters;
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  const double T = problem.time_parameters.end_time;
  const double sample = output.history_interval > 0. ? output.history_interval
                                                     : problem.time_parameters.time_step;

  timer.enter_subsection("setup");
  EventDriven integrator(system, problem.time_parameters);
  OutputWriter writer(directory, system, *problem.model);
  timer.leave_subsection();
  std::cout << "  event-driven (CVODE, root finding): sampling every " << sample
            << " s to t = " << T << " s" << std::endl;

  WallClock output_clock; // a TimerOutput section costs more than a row
  const Watchdog watchdog(*problem.model, system);
  auto write = [&]()
  {
    const WallClock::Scope scope(output_clock);
    const OutputState s = contact_state(integrator, 0.); // impulses act at an instant
    check_state(watchdog, writer, *s.displacement, s.velocity, s.time);
    writer.write_history(s);
    writer.write_energy(s.time, integrator.energies());
    writer.track_contacts(s.gaps, s.impulses);
  };

  Progress progress(output.progress_interval, T);
  write();
  const unsigned long n_samples = std::llround(std::ceil(T / sample - 1e-9));
  const unsigned long vtu_every =
      output.vtu_interval > 0. ? steps_between(output.vtu_interval, sample) : 0;
  if (vtu_every > 0)
    writer.write_vtu(contact_state(integrator, 0.));
  unsigned long samples_done = 0; // n_samples unless SIGINT/SIGTERM stopped the loop
  {
    TimerOutput::Scope scope(timer, "time integration");
    for (unsigned long i = 1; i <= n_samples; ++i)
    {
      integrator.advance_to(std::min(T, i * sample), write);
      samples_done = i;
      write();
      if (vtu_every > 0 && (i % vtu_every == 0 || i == n_samples))
        writer.write_vtu(contact_state(integrator, 0.));
      if (progress.due())
      {
        progress.print(integrator.time(), i);
        writer.flush();
      }
      if (stop_requested()) // SIGINT/SIGTERM: stop after a complete sample
        break;
    }
  }
  writer.finish();
  const auto [drift, scale] = writer.energy_balance();
  write_summary(directory.path() + "/summary.json",
                {{"method", "event-driven"},
                 {"model", problem.model->description()},
                 {"n_dofs", system.n_dofs()},
                 {"n_contacts", system.contacts.size()},
                 {"dt", sample},
                 {"dt_crit", SummaryValue()},
                 {"end_time", integrator.time()},
                 {"n_steps", samples_done},
                 {"wall_time", progress.wall_time()},
                 {"n_impacts", integrator.n_events()},
                 {"max_penetration", writer.max_penetration()},
                 {"energy_balance_error", drift},
                 {"energy_balance_relative", scale > 0. ? drift / scale : 0.}},
                problem.warnings);
  std::cout << "  done: " << integrator.n_events()
            << " impacts located, energy balance error " << drift << " J (output "
            << output_clock.seconds() << " s in " << output_clock.calls()
            << " calls)\n  summary: " << directory.path() << "/summary.json" << std::endl;
  timer.print_summary();
}
} // namespace hati

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <hati/output/output_writer.h>
#include <hati/simulation.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/event_driven.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hati
{
namespace
{
std::string json_number(const double x)
{
  if (!std::isfinite(x))
    return "null";
  std::ostringstream s;
  s << std::setprecision(15) << x;
  return s.str();
}

std::string json_string(const std::string &x)
{
  std::string r = "\"";
  for (const char c : x)
  {
    if (c == '"' || c == '\\')
      r += '\\';
    r += c;
  }
  return r + "\"";
}

/** Steps between two outputs of interval @p interval (s); 0 means every step. */
unsigned long steps_between(const double interval, const double dt)
{
  if (interval <= 0.)
    return 1;
  return std::max<unsigned long>(1, std::llround(interval / dt));
}

void check_finite(const Vector<double> &u, const double t)
{
  if (!std::isfinite(u.l2_norm()))
  {
    std::ostringstream s;
    s << "the solution became non-finite (NaN or Inf) at t = " << t << " s";
    AssertThrow(false, ExcMessage(s.str()));
  }
}

/** Progress lines at most every @p interval seconds of wall time. */
class Progress
{
public:
  Progress(const double interval, const double end_time)
      : interval(interval), end_time(end_time), start(std::chrono::steady_clock::now()),
        last(start)
  {
  }

  bool due()
  {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last).count() < interval)
      return false;
    last = now;
    return true;
  }

  void print(const double t, const unsigned long step) const
  {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double fraction = t / end_time;
    std::cout << "  t = " << std::setw(12) << std::setprecision(6) << t << " s ("
              << std::setw(5) << std::fixed << std::setprecision(1) << 100. * fraction
              << " %), step " << step << ", wall " << std::setprecision(1) << wall
              << " s, remaining ~"
              << (fraction > 0. ? wall * (1. - fraction) / fraction : 0.) << " s"
              << std::defaultfloat << std::endl;
  }

  double wall_time() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
  }

private:
  const double interval, end_time;
  const std::chrono::steady_clock::time_point start;
  std::chrono::steady_clock::time_point last;
};
} // namespace

void Simulation::declare_parameters(ParameterHandler &prm)
{
  declare_model_parameters(prm);
  TimeIntegrationParameters::declare_parameters(prm);
  OutputParameters::declare_parameters(prm);
}

Simulation::Simulation(ParameterHandler &prm, const std::string &parameter_file)
    : parameter_file(parameter_file)
{
  time_parameters.parse_parameters(prm);
  output_parameters.parse_parameters(prm);
  common_parameters.parse_parameters(prm);
  model = create_model(prm);

  output_directory = output_parameters.directory;
  if (output_directory.empty())
    output_directory = "output/" + std::filesystem::path(parameter_file).stem().string();
  std::filesystem::create_directories(output_directory);
  // remove what an earlier run wrote here, so that the directory never mixes
  // two runs (files of other programs are left alone)
  for (const auto &entry : std::filesystem::directory_iterator(output_directory))
  {
    const std::string name = entry.path().filename().string();
    const bool vtu =
        name.rfind("solution-", 0) == 0 && entry.path().extension() == ".vtu";
    if (vtu || name == "solution.pvd" || name == "history.csv" ||
        name == "contacts.csv" || name == "energy.csv" || name == "summary.json")
      std::filesystem::remove(entry.path());
  }
  std::ofstream used(output_directory + "/parameters.prm");
  prm.print_parameters(used, ParameterHandler::PRM);
}

Simulation::~Simulation() = default;

void Simulation::run()
{
  model->build(common_parameters, system);
  std::cout << "hati: " << parameter_file << "\n  model: " << model->description()
            << "\n  DoFs: " << system.n_dofs() << ", contacts: " << system.contacts.size()
            << "\n  output: " << output_directory << "/" << std::endl;
  if (time_parameters.method == "event-driven")
    run_event_driven();
  else
    run_cd_lagrange();
}

void Simulation::run_cd_lagrange()
{
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  const double dt = time_parameters.time_step, T = time_parameters.end_time;

  timer.enter_subsection("setup");
  CDLagrange integrator(system, dt, time_parameters.safety_factor);
  OutputWriter writer(output_directory, system, *model);
  timer.leave_subsection();

  const unsigned long n_steps = std::llround(std::ceil(T / dt - 1e-9));
  const unsigned long every_history =
      steps_between(output_parameters.history_interval, dt);
  const unsigned long every_vtu = output_parameters.vtu_interval > 0.
                                      ? steps_between(output_parameters.vtu_interval, dt)
                                      : 0;
  std::cout << "  CD-Lagrange: dt = " << dt
            << " s, dt_crit = " << integrator.critical_time_step() << " s, " << n_steps
            << " steps to t = " << T << " s" << std::endl;

  auto state = [&]()
  {
    OutputState s;
    s.time = integrator.time();
    s.displacement = &integrator.displacement();
    s.velocity = &integrator.velocity();
    s.gaps = integrator.gaps();
    s.normal_velocities = integrator.normal_velocities();
    s.impulses = integrator.impulses();
    s.active = integrator.active();
    s.impulse_duration = dt;
    return s;
  };
  auto write = [&](const unsigned long step)
  {
    TimerOutput::Scope scope(timer, "output");
    const OutputState s = state();
    check_finite(*s.displacement, s.time);
    if (step % every_history == 0 || step == n_steps)
    {
      writer.write_history(s);
      writer.write_energy(s.time, integrator.energies());
    }
    if (every_vtu > 0 && (step % every_vtu == 0 || step == n_steps))
      writer.write_vtu(s);
  };

  Progress progress(output_parameters.progress_interval, T);
  write(0);
  {
    TimerOutput::Scope scope(timer, "time stepping");
    for (unsigned long step = 1; step <= n_steps; ++step)
    {
      integrator.step();
      if (!system.contacts.empty())
        writer.track_contacts(integrator.gaps(), integrator.impulses());
      if (step % every_history == 0 || (every_vtu > 0 && step % every_vtu == 0) ||
          step == n_steps)
        write(step);
      if ((step & 255) == 0 && progress.due())
      {
        check_finite(integrator.displacement(), integrator.time());
        progress.print(integrator.time(), step);
        writer.flush();
      }
    }
  }
  writer.flush();

  const auto [drift, scale] = writer.energy_balance();
  const double wall = progress.wall_time();
  // time of the steps alone: the stepping loop minus the output inside it
  auto times = timer.get_summary_data(TimerOutput::total_wall_time);
  const double stepping = times["time stepping"] - times["output"];
  write_summary(
      output_directory + "/summary.json",
      {{"method", json_string("CD-Lagrange")},
       {"model", json_string(model->description())},
       {"n_dofs", std::to_string(system.n_dofs())},
       {"n_contacts", std::to_string(system.contacts.size())},
       {"dt", json_number(dt)},
       {"dt_crit", json_number(integrator.critical_time_step())},
       {"end_time", json_number(integrator.time())},
       {"n_steps", std::to_string(n_steps)},
       {"wall_time", json_number(wall)},
       {"stepping_wall_time", json_number(stepping)},
       {"ns_per_dof_per_step",
        json_number(1e9 * stepping / (double(n_steps) * system.n_dofs()))},
       {"n_impacts", std::to_string(writer.n_impacts())},
       {"max_penetration", json_number(writer.max_penetration())},
       {"energy_balance_error", json_number(drift)},
       {"energy_balance_relative", json_number(scale > 0. ? drift / scale : 0.)}});
  std::cout << "  done: " << n_steps << " steps in " << wall
            << " s; impacts: " << writer.n_impacts()
            << ", max penetration: " << writer.max_penetration()
            << " m, energy balance error: " << drift << " J ("
            << (scale > 0. ? drift / scale : 0.) << " of the largest energy)\n"
            << "  summary: " << output_directory << "/summary.json" << std::endl;
  timer.print_summary();
}

void Simulation::run_event_driven()
{
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  const double T = time_parameters.end_time;
  const double sample = output_parameters.history_interval > 0.
                            ? output_parameters.history_interval
                            : time_parameters.time_step;

  timer.enter_subsection("setup");
  EventDriven integrator(system, time_parameters);
  OutputWriter writer(output_directory, system, *model);
  timer.leave_subsection();
  std::cout << "  event-driven (CVODE, root finding): sampling every " << sample
            << " s to t = " << T << " s" << std::endl;

  auto state = [&]()
  {
    OutputState s;
    s.time = integrator.time();
    s.displacement = &integrator.displacement();
    s.velocity = &integrator.velocity();
    s.gaps = integrator.gaps();
    s.normal_velocities = integrator.normal_velocities();
    s.impulses = integrator.impulses();
    s.active = integrator.active();
    s.impulse_duration = 0.;
    return s;
  };
  auto write = [&]()
  {
    TimerOutput::Scope scope(timer, "output");
    const OutputState s = state();
    check_finite(*s.displacement, s.time);
    writer.write_history(s);
    writer.write_energy(s.time, integrator.energies());
    writer.track_contacts(s.gaps, s.impulses);
  };

  Progress progress(output_parameters.progress_interval, T);
  write();
  const unsigned long n_samples = std::llround(std::ceil(T / sample - 1e-9));
  unsigned long vtu_every = output_parameters.vtu_interval > 0.
                                ? steps_between(output_parameters.vtu_interval, sample)
                                : 0;
  if (vtu_every > 0)
    writer.write_vtu(state());
  {
    TimerOutput::Scope scope(timer, "time integration");
    for (unsigned long i = 1; i <= n_samples; ++i)
    {
      integrator.advance_to(std::min(T, i * sample), write);
      write();
      if (vtu_every > 0 && (i % vtu_every == 0 || i == n_samples))
        writer.write_vtu(state());
      if (progress.due())
      {
        progress.print(integrator.time(), i);
        writer.flush();
      }
    }
  }
  writer.flush();
  const auto [drift, scale] = writer.energy_balance();
  write_summary(
      output_directory + "/summary.json",
      {{"method", json_string("event-driven")},
       {"model", json_string(model->description())},
       {"n_dofs", std::to_string(system.n_dofs())},
       {"n_contacts", std::to_string(system.contacts.size())},
       {"dt", json_number(sample)},
       {"dt_crit", "null"},
       {"end_time", json_number(integrator.time())},
       {"n_steps", std::to_string(n_samples)},
       {"wall_time", json_number(progress.wall_time())},
       {"n_impacts", std::to_string(integrator.n_events())},
       {"max_penetration", json_number(writer.max_penetration())},
       {"energy_balance_error", json_number(drift)},
       {"energy_balance_relative", json_number(scale > 0. ? drift / scale : 0.)}});
  std::cout << "  done: " << integrator.n_events()
            << " impacts located, energy balance error " << drift
            << " J\n  summary: " << output_directory << "/summary.json" << std::endl;
  timer.print_summary();
}
} // namespace hati

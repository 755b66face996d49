#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/modal_damping.h>
#include <hati/analysis/static_analysis.h>
#include <hati/loading/accelerogram.h>
#include <hati/loading/base_excitation.h>
#include <hati/output/contact_statistics.h>
#include <hati/output/output_writer.h>
#include <hati/output/run_directory.h>
#include <hati/output/wall_clock.h>
#include <hati/simulation.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/event_driven.h>
#include <hati/time/newmark.h>
#include <hati/time/rayleigh_damping.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <type_traits>

namespace hati
{
namespace
{
/** Micro steps per step: m for the coupling, 1 otherwise. */
template <class Integrator> unsigned int time_step_ratio(const Integrator &integrator)
{
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
    return integrator.time_step_ratio();
  else
    return 1;
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
    const auto precision = std::cout.precision();
    std::cout << "  t = " << std::setw(12) << std::setprecision(6) << t << " s ("
              << std::setw(5) << std::fixed << std::setprecision(1) << 100. * fraction
              << " %), step " << step << ", wall " << std::setprecision(1) << wall
              << " s, remaining ~"
              << (fraction > 0. ? wall * (1. - fraction) / fraction : 0.) << " s"
              << std::defaultfloat << std::setprecision(precision) << std::endl;
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
  AnalysisParameters::declare_parameters(prm);
  TimeIntegrationParameters::declare_parameters(prm);
  prm.enter_subsection("Time integration");
  prm.enter_subsection("Newmark");
  NewmarkParameters::declare_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Damping");
  RayleighDamping::declare_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("HATI");
  HATIParameters::declare_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  OutputParameters::declare_parameters(prm);
}

Simulation::Simulation(ParameterHandler &prm, const std::string &parameter_file)
    : parameter_file(parameter_file)
{
  analysis_parameters.parse_parameters(prm);
  time_parameters.parse_parameters(prm);
  prm.enter_subsection("Time integration");
  prm.enter_subsection("Newmark");
  newmark_parameters.parse_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Damping");
  damping.parse_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("HATI");
  hati_parameters.parse_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  prm.enter_subsection("Model");
  prm.enter_subsection("Decomposition");
  decomposition_parameters.parse_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  output_parameters.parse_parameters(prm);
  common_parameters.parse_parameters(prm);
  model = create_model(prm);

  output_directory = output_parameters.directory;
  if (output_directory.empty())
    output_directory = "output/" + std::filesystem::path(parameter_file).stem().string();
  // the directory is not touched before the analysis begins (RunDirectory)
  std::ostringstream used;
  prm.print_parameters(used, ParameterHandler::PRM);
  run_directory = std::make_unique<RunDirectory>(output_directory, used.str());
}

Simulation::~Simulation() = default;

void Simulation::record_failure(const std::string &message) noexcept
{
  if (run_directory)
    run_directory->fail(message);
}

void Simulation::run()
{
  model->build(common_parameters, system);
  check_finite(system);
  std::cout << "hati: " << parameter_file << "\n  model: " << model->description()
            << "\n  DoFs: " << system.n_dofs() << ", contacts: " << system.contacts.size()
            << "\n  output: " << output_directory << "/" << std::endl;
  system.fill_default_mass_influence();
  auto acceleration = base_acceleration_step(common_parameters.base_acceleration,
                                             common_parameters.base_acceleration_start);
  for (unsigned int d = 0; d < 3; ++d)
    if (!common_parameters.accelerogram_files[d].empty())
    {
      const auto record = std::make_shared<Accelerogram>(
          Accelerogram::read(common_parameters.accelerogram_files[d],
                             common_parameters.accelerogram_units,
                             common_parameters.accelerogram_scale));
      const auto [peak, at] = record->peak();
      std::cout << "  accelerogram along "
                << "xyz"[d] << ": " << common_parameters.accelerogram_files[d] << ", "
                << record->values().size() << " samples to t = " << record->times().back()
                << " s, peak " << peak << " m/s^2 (" << peak / standard_gravity
                << " g) at t = " << at << " s" << std::endl;
      const auto step = acceleration[d];
      acceleration[d] = [record, step](const double t)
      { return (*record)(t) + (step ? step(t) : 0.); };
    }
  add_base_excitation(system, acceleration);
  ground_acceleration = acceleration;
  if (!common_parameters.excited_members.empty())
  {
    std::cout << "  base excitation on the members:";
    for (const auto &m : common_parameters.excited_members)
      std::cout << ' ' << m;
    std::cout << std::endl;
  }
  if (analysis_parameters.type == "static")
    return run_static();
  if (analysis_parameters.type == "modal")
    return run_modal();
  if (time_parameters.method == "HATI")
  {
    // the subdomains (their initial state is copied below)
    decomposition = std::make_unique<Decomposition>();
    if (decomposition_parameters.boxes.empty() &&
        decomposition_parameters.members.empty())
      decomposition_parameters = model->default_decomposition();
    decompose(*model, common_parameters, decomposition_parameters, *decomposition);
    for (auto &part : decomposition->parts)
      add_base_excitation(part.system, acceleration);
  }
  if (analysis_parameters.initial_state == "static")
  {
    std::cout << "  initial state: static equilibrium under the constant loads"
              << std::endl;
    // under the loads the integrators apply: CD-Lagrange (and the explicit
    // subdomain of HATI) applies gravity with the lumped mass, so that its
    // first steps start at rest (doc/theory.md 1.1)
    Vector<double> correction(system.n_dofs());
    if (time_parameters.method == "CD-Lagrange")
      correction = system.lumped_gravity_correction();
    else if (time_parameters.method == "HATI")
    {
      const auto &E = decomposition->parts[0];
      const Vector<double> c = E.system.lumped_gravity_correction();
      for (unsigned int i = 0; i < c.size(); ++i)
        correction[E.global_dofs[i]] += c[i];
    }
    system.constant_force += correction;
    std::vector<double> forces;
    solve_static(system,
                 0.,
                 system.initial_displacement,
                 newmark_parameters.linear_solver,
                 true,
                 &forces);
    system.constant_force -= correction;
    system.initial_velocity = 0.;
    const std::string entry = report_static_contact_forces(forces);
    if (!entry.empty())
      initial_state_summary.emplace_back("static_contact_forces", entry);
  }
  if (decomposition)
    for (auto &part : decomposition->parts)
      for (unsigned int i = 0; i < part.global_dofs.size(); ++i)
      {
        part.system.initial_displacement[i] =
            system.initial_displacement[part.global_dofs[i]];
        part.system.initial_velocity[i] = system.initial_velocity[part.global_dofs[i]];
      }
  for (const auto &entry :
       apply_default_damping(*model, system, time_parameters.method, damping))
    initial_state_summary.push_back(entry);
  AssertThrow(time_parameters.method != "event-driven" ||
                  (damping.a0 == 0. && damping.a1 == 0.),
              ExcMessage("Time integration/Damping: Rayleigh damping is applied by the "
                         "CD-Lagrange and Newmark integrators only; remove it for "
                         "Method = event-driven."));
  if (time_parameters.method == "event-driven")
    run_event_driven();
  else if (time_parameters.method == "Newmark")
    run_newmark();
  else if (time_parameters.method == "HATI")
    run_hati();
  else
    run_cd_lagrange();
}

namespace
{
/** State of an integrator with contacts for the output writer. */
template <class Integrator>
OutputState contact_state(const Integrator &integrator, const double impulse_duration)
{
  OutputState s;
  s.time = integrator.time();
  s.displacement = &integrator.displacement();
  s.velocity = &integrator.velocity();
  s.gaps = integrator.gaps();
  s.normal_velocities = integrator.normal_velocities();
  s.impulses = integrator.impulses();
  s.active = integrator.active();
  s.impulse_duration = impulse_duration;
  return s;
}

OutputState output_state(const CDLagrange &integrator)
{
  return contact_state(integrator, integrator.time_step());
}

OutputState output_state(const EventDriven &integrator)
{
  return contact_state(integrator, 0.); // impulses act at an instant
}

OutputState output_state(const HATICoupling &integrator)
{
  // contacts.csv is written at the micro steps (run_transient)
  OutputState s = contact_state(integrator, integrator.micro_time_step());
  s.contact_rows = false;
  return s;
}

OutputState output_state(const Newmark &integrator)
{
  OutputState s;
  s.time = integrator.time();
  s.displacement = &integrator.displacement();
  s.velocity = &integrator.velocity();
  return s;
}
} // namespace

template <class Integrator>
void Simulation::run_transient(Integrator &integrator,
                               TimerOutput &timer,
                               std::vector<std::pair<std::string, std::string>> summary)
{
  constexpr bool explicit_scheme = std::is_same_v<Integrator, CDLagrange>;
  const double dt = integrator.time_step(), T = time_parameters.end_time;
  OutputWriter writer(*run_directory, system, *model);

  const unsigned long n_steps = std::llround(std::ceil(T / dt - 1e-9));
  const unsigned long every_history =
      steps_between(output_parameters.history_interval, dt);
  const unsigned long every_vtu = output_parameters.vtu_interval > 0.
                                      ? steps_between(output_parameters.vtu_interval, dt)
                                      : 0;
  std::cout << "  " << n_steps << " steps of " << dt << " s to t = " << T << " s"
            << std::endl;

  WallClock output_clock; // a TimerOutput section costs more than a row
  // absolute accelerations of the monitor points (m/s^2): the relative
  // velocity differenced between two history rows plus the ground
  // acceleration at the middle of the interval
  std::vector<std::pair<double, double>> peak_acceleration(system.monitors.size());
  std::vector<std::vector<double>> last_velocity(system.monitors.size());
  double last_time = 0.;
  bool have_last = false;
  auto track_acceleration = [&](const OutputState &s)
  {
    for (unsigned int k = 0; k < system.monitors.size(); ++k)
    {
      const auto &m = system.monitors[k];
      std::vector<double> &last = last_velocity[k];
      last.resize(m.dofs.size());
      double a2 = 0.;
      for (unsigned int i = 0; i < m.dofs.size(); ++i)
      {
        const double v = (*s.velocity)[m.dofs[i]];
        if (have_last && s.time > last_time)
        {
          const unsigned int d = m.labels[i] == "x" ? 0 : m.labels[i] == "y" ? 1 : 2;
          const double a =
              (v - last[i]) / (s.time - last_time) +
              (ground_acceleration[d] ? ground_acceleration[d](0.5 * (s.time + last_time))
                                      : 0.);
          a2 += a * a;
        }
        last[i] = v;
      }
      if (std::sqrt(a2) > peak_acceleration[k].first)
        peak_acceleration[k] = {std::sqrt(a2), s.time};
    }
    last_time = s.time;
    have_last = true;
  };

  auto write = [&](const unsigned long step)
  {
    const WallClock::Scope scope(output_clock);
    const OutputState s = output_state(integrator);
    check_finite(*s.displacement, s.time);
    if (step % every_history == 0 || step == n_steps)
    {
      track_acceleration(s);
      writer.write_history(s);
      writer.write_energy(s.time, integrator.energies());
    }
    if (every_vtu > 0 && (step % every_vtu == 0 || step == n_steps))
      writer.write_vtu(s);
  };

  // per contact name: impacts, peak force, time out of contact, episodes
  std::vector<double> initial_gaps;
  for (const auto &c : system.contacts)
    initial_gaps.push_back(c.initial_gap + c.apply(system.initial_displacement));
  ContactStatistics statistics(
      system.contacts, initial_gaps, output_parameters.contact_force_window);
  writer.set_initial_contacts(initial_gaps);

  // HATI: contact statistics and contacts.csv rows at the micro steps
  unsigned long micro_step = 0;
  const unsigned long every_contact_row =
      std::is_same_v<Integrator, HATICoupling>
          ? steps_between(output_parameters.history_interval,
                          dt / time_step_ratio(integrator))
          : 1;
  OutputState contact_row;
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
    if (!integrator.gaps().empty())
      integrator.after_micro_step = [&](const HATICoupling::ContactSample &sample)
      {
        writer.track_contacts(sample.gaps, sample.impulses);
        statistics.add_step(sample.time, integrator.micro_time_step(), sample.impulses);
        if (++micro_step % every_contact_row == 0)
        {
          contact_row.time = sample.time;
          contact_row.gaps = sample.gaps;
          contact_row.normal_velocities = sample.normal_velocities;
          contact_row.impulses = sample.impulses;
          contact_row.active = sample.active;
          contact_row.impulse_duration = integrator.micro_time_step();
          writer.write_contacts(contact_row);
        }
      };

  Progress progress(output_parameters.progress_interval, T);
  write(0);
  unsigned long steps_done = 0; // n_steps unless SIGINT/SIGTERM stopped the loop
  {
    TimerOutput::Scope scope(timer, "time stepping");
    for (unsigned long step = 1; step <= n_steps; ++step)
    {
      integrator.step();
      steps_done = step;
      if constexpr (explicit_scheme)
        if (!system.contacts.empty())
        {
          writer.track_contacts(integrator.gaps(), integrator.impulses());
          statistics.add_step(integrator.time(), dt, integrator.impulses());
        }
      if (step % every_history == 0 || (every_vtu > 0 && step % every_vtu == 0) ||
          step == n_steps)
        write(step);
      if ((!explicit_scheme || (step & 255) == 0) && progress.due())
      {
        check_finite(integrator.displacement(), integrator.time());
        progress.print(integrator.time(), step);
        writer.flush();
      }
      if (stop_requested()) // SIGINT/SIGTERM: stop after a complete step
        break;
    }
  }
  writer.finish();

  const auto [drift, scale] = writer.energy_balance();
  const double wall = progress.wall_time();
  // time of the steps alone: the stepping loop minus the output inside it
  auto times = timer.get_summary_data(TimerOutput::total_wall_time);
  const double stepping = times["time stepping"] - output_clock.seconds();
  summary.insert(
      summary.end(), initial_state_summary.begin(), initial_state_summary.end());
  for (const auto &entry : model->summary_entries(static_contact_forces))
    summary.push_back(entry);
  summary.insert(
      summary.end(),
      {{"model", json_string(model->description())},
       {"n_dofs", std::to_string(system.n_dofs())},
       {"n_contacts", std::to_string(system.contacts.size())},
       {"dt", json_number(dt)},
       {"end_time", json_number(integrator.time())},
       {"n_steps", std::to_string(steps_done)},
       {"wall_time", json_number(wall)},
       {"stepping_wall_time", json_number(stepping)},
       {"ns_per_dof_per_step",
        json_number(steps_done > 0
                        ? 1e9 * stepping / (double(steps_done) * system.n_dofs())
                        : std::nan(""))},
       {"n_impacts", std::to_string(writer.n_impacts())},
       {"max_penetration", json_number(writer.max_penetration())},
       {"energy_balance_error", json_number(drift)},
       {"energy_balance_relative", json_number(scale > 0. ? drift / scale : 0.)}});
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
  {
    summary.insert(
        summary.end(),
        {{"time_step_ratio", std::to_string(integrator.time_step_ratio())},
         {"micro_dt", json_number(integrator.micro_time_step())},
         {"n_dofs_explicit", std::to_string(decomposition->parts[0].system.n_dofs())},
         {"n_dofs_implicit", std::to_string(decomposition->parts[1].system.n_dofs())},
         {"n_interface_dofs", std::to_string(integrator.n_interface_dofs())},
         {"wall_time_explicit", json_number(integrator.explicit_seconds())},
         {"wall_time_implicit", json_number(integrator.implicit_seconds())},
         {"wall_time_interface", json_number(integrator.interface_seconds())},
         {"wall_time_setup", json_number(integrator.setup_seconds())},
         {"interface_velocity_jump", json_number(integrator.interface_velocity_jump())},
         {"redone_macro_steps", std::to_string(integrator.redone_macro_steps())},
         {"interface_iterations", std::to_string(integrator.interface_iterations())},
         {"ramp_patterns", std::to_string(integrator.ramp_patterns())}});
    std::cout << "  HATI wall time: explicit " << integrator.explicit_seconds()
              << " s, implicit " << integrator.implicit_seconds() << " s, interface "
              << integrator.interface_seconds() << " s, set-up "
              << integrator.setup_seconds() << " s; interface velocity jump "
              << integrator.interface_velocity_jump() << " m/s" << std::endl;
  }
  if (!system.contacts.empty())
  {
    summary.emplace_back("contacts", statistics.json());
    summary.emplace_back("contact_force_window",
                         json_number(output_parameters.contact_force_window));
    const auto wheels = model->wheel_contacts();
    if (!wheels.empty())
      summary.emplace_back("wheels", statistics.json(wheels));
    const std::string episodes_file = run_directory->create("contact_episodes.csv");
    std::ofstream episodes(episodes_file);
    statistics.write_episodes(episodes);
    episodes.close();
    AssertThrow(episodes, ExcMessage("cannot write " + episodes_file));
    statistics.print_table(std::cout);
  }
  std::cout << model->results_table();
  if (!system.monitors.empty())
  {
    std::ostringstream json;
    json << '{';
    std::cout << "  largest absolute acceleration of the monitor points (m/s^2, between "
                 "history rows):\n";
    for (unsigned int k = 0; k < system.monitors.size(); ++k)
    {
      json << (k ? ", " : "") << json_string(system.monitors[k].name)
           << ": {\"value\": " << json_number(peak_acceleration[k].first)
           << ", \"time\": " << json_number(peak_acceleration[k].second) << '}';
      std::cout << "    " << std::setw(12) << system.monitors[k].name << std::setw(14)
                << peak_acceleration[k].first << " at t = " << peak_acceleration[k].second
                << " s\n";
    }
    json << '}';
    summary.emplace_back("max_absolute_acceleration", json.str());
  }
  write_summary(output_directory + "/summary.json", summary);
  std::cout << "  done: " << steps_done << " steps in " << wall << " s (output "
            << output_clock.seconds() << " s in " << output_clock.calls() << " calls); ";
  if (!system.contacts.empty())
    std::cout << "impacts: " << writer.n_impacts()
              << ", max penetration: " << writer.max_penetration() << " m, ";
  std::cout << "energy balance error: " << drift << " J ("
            << (scale > 0. ? drift / scale : 0.) << " of the largest energy)\n"
            << "  summary: " << output_directory << "/summary.json" << std::endl;
  timer.print_summary();
}

void Simulation::run_cd_lagrange()
{
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  timer.enter_subsection("setup");
  CDLagrange integrator(
      system, time_parameters.time_step, time_parameters.safety_factor, damping);
  timer.leave_subsection();
  std::cout << "  CD-Lagrange: dt_crit = " << integrator.critical_time_step() << " s";
  if (integrator.damped())
    std::cout << ", Rayleigh a0 = " << integrator.mass_damping_coefficient()
              << " 1/s, a1 = " << integrator.stiffness_damping_coefficient() << " s";
  std::cout << std::endl;
  run_transient(integrator,
                timer,
                {{"method", json_string("CD-Lagrange")},
                 {"dt_crit", json_number(integrator.critical_time_step())}});
}

void Simulation::run_newmark()
{
  AssertThrow(
      system.contacts.empty(),
      ExcMessage("Time integration/Method = Newmark: the model has contacts, which "
                 "need the explicit CD-Lagrange integrator."));
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  timer.enter_subsection("setup (assembly, factorisation)");
  Newmark integrator(system, time_parameters.time_step, newmark_parameters, damping);
  timer.leave_subsection();
  std::cout << "  Newmark (beta = " << newmark_parameters.beta
            << ", gamma = " << newmark_parameters.gamma << ", "
            << newmark_parameters.linear_solver << " solver): factorisation "
            << integrator.factorization_time()
            << " s, Rayleigh a0 = " << integrator.mass_damping_coefficient()
            << " 1/s, a1 = " << integrator.stiffness_damping_coefficient() << " s"
            << std::endl;
  run_transient(integrator,
                timer,
                {{"method", json_string("Newmark")},
                 {"factorization_time", json_number(integrator.factorization_time())}});
}

void Simulation::run_hati()
{
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  timer.enter_subsection("setup (factorisation, ramp response)");
  std::unique_ptr<HATICoupling> coupling;
  try
  {
    coupling = std::make_unique<HATICoupling>(*decomposition,
                                              system.n_dofs(),
                                              time_parameters.time_step,
                                              time_parameters.safety_factor,
                                              hati_parameters,
                                              newmark_parameters,
                                              damping);
  }
  catch (const ExceptionBase &e)
  {
    // name the subdomain in the message (e.g. the critical step refusal)
    std::ostringstream info;
    e.print_info(info);
    std::string text = info.str();
    const std::string prefix = "Additional information:";
    if (text.find(prefix) != std::string::npos)
      text = text.substr(text.find(prefix) + prefix.size());
    AssertThrow(false, ExcMessage("HATI (explicit subdomain): " + Utilities::trim(text)));
  }
  timer.leave_subsection();
  std::cout << "  HATI (G3'): explicit subdomain "
            << decomposition->parts[0].system.n_dofs()
            << " DoFs (CD-Lagrange, dt = " << coupling->micro_time_step()
            << " s, dt_crit = " << coupling->critical_time_step()
            << " s), implicit subdomain " << decomposition->parts[1].system.n_dofs()
            << " DoFs (Newmark, DT = " << coupling->time_step()
            << " s, m = " << coupling->time_step_ratio() << "), "
            << coupling->n_interface_dofs() << " interface DoFs" << std::endl;
  run_transient(*coupling,
                timer,
                {{"method", json_string("HATI")},
                 {"dt_crit", json_number(coupling->critical_time_step())}});
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
  OutputWriter writer(*run_directory, system, *model);
  timer.leave_subsection();
  std::cout << "  event-driven (CVODE, root finding): sampling every " << sample
            << " s to t = " << T << " s" << std::endl;

  auto state = [&]() { return output_state(integrator); };
  WallClock output_clock; // a TimerOutput section costs more than a row
  auto write = [&]()
  {
    const WallClock::Scope scope(output_clock);
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
  unsigned long samples_done = 0; // n_samples unless SIGINT/SIGTERM stopped the loop
  {
    TimerOutput::Scope scope(timer, "time integration");
    for (unsigned long i = 1; i <= n_samples; ++i)
    {
      integrator.advance_to(std::min(T, i * sample), write);
      samples_done = i;
      write();
      if (vtu_every > 0 && (i % vtu_every == 0 || i == n_samples))
        writer.write_vtu(state());
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
  write_summary(
      output_directory + "/summary.json",
      {{"method", json_string("event-driven")},
       {"model", json_string(model->description())},
       {"n_dofs", std::to_string(system.n_dofs())},
       {"n_contacts", std::to_string(system.contacts.size())},
       {"dt", json_number(sample)},
       {"dt_crit", "null"},
       {"end_time", json_number(integrator.time())},
       {"n_steps", std::to_string(samples_done)},
       {"wall_time", json_number(progress.wall_time())},
       {"n_impacts", std::to_string(integrator.n_events())},
       {"max_penetration", json_number(writer.max_penetration())},
       {"energy_balance_error", json_number(drift)},
       {"energy_balance_relative", json_number(scale > 0. ? drift / scale : 0.)}});
  std::cout << "  done: " << integrator.n_events()
            << " impacts located, energy balance error " << drift << " J (output "
            << output_clock.seconds() << " s in " << output_clock.calls()
            << " calls)\n  summary: " << output_directory << "/summary.json" << std::endl;
  timer.print_summary();
}
} // namespace hati

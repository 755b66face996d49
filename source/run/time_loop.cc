#include <hati/base/wall_clock.h>
#include <hati/output/contact_output.h>
#include <hati/output/law_output.h>
#include <hati/output/output_writer.h>
#include <hati/output/postprocessor.h>
#include <hati/output/run_directory.h>
#include <hati/output/summary.h>
#include <hati/run/problem.h>
#include <hati/run/qualification_run.h>
#include <hati/run/run_state.h>
#include <hati/run/run_tools.h>
#include <hati/run/time_loop.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/newmark.h>

#include <algorithm>
#include <cmath>
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

/** The force laws' columns of an output row: those of the laws' sample @p l. */
void set_law_columns(const LawSample &l, OutputState &s)
{
  s.gaps = l.gaps;
  s.normal_velocities = l.normal_velocities;
  s.impulses = l.impulses;
  s.active = l.active;
  s.tangential_impulses = l.tangential_impulses;
  s.slip_velocities = l.slip_velocities;
  s.friction_states = l.friction_states;
}

/**
 * The output row of CD-Lagrange: its state and its laws' sample (into
 * @p sample). (`history_dofs_only`: see the HATI overload.)
 */
OutputState
output_state(const CDLagrange &integrator, LawSample &sample, const bool, const bool)
{
  OutputState s;
  s.time = integrator.time();
  s.displacement = &integrator.displacement();
  s.velocity = &integrator.velocity();
  s.impulse_duration = integrator.time_step();
  sample_force_laws(integrator.force_laws(), integrator.velocity(), sample);
  set_law_columns(sample, s);
  return s;
}

/** The force laws of an integrator; none for Newmark (it refuses them). */
const std::vector<std::unique_ptr<ForceLaw>> &force_laws_of(const CDLagrange &integrator)
{
  return integrator.force_laws();
}
const std::vector<std::unique_ptr<ForceLaw>> &
force_laws_of(const HATICoupling &integrator)
{
  return integrator.force_laws();
}
const std::vector<std::unique_ptr<ForceLaw>> &force_laws_of(const Newmark &)
{
  static const std::vector<std::unique_ptr<ForceLaw>> none;
  return none;
}

/**
 * The output row of HATI. With @p history_displacements (a history row
 * without section forces and VTU) and @p history_velocities (a row without
 * VTU: only the VTU reads every velocity), a reduced implicit part recovers
 * only the DoFs that the row reads (HATICoupling::set_history_dofs()).
 */
OutputState output_state(const HATICoupling &integrator,
                         LawSample &,
                         const bool history_displacements,
                         const bool history_velocities)
{
  // contacts.csv is written at the micro steps (connect_micro_steps())
  OutputState s = contact_state(integrator,
                                integrator.micro_time_step(),
                                integrator.displacement(history_displacements),
                                integrator.velocity(history_velocities));
  s.contact_rows = false;
  return s;
}

/** The DoFs of the monitors (history.csv, the acceleration peaks, the spectra). */
std::vector<types::global_dof_index> monitor_dofs(const DiscreteSystem &system)
{
  std::vector<types::global_dof_index> dofs;
  for (const auto &monitor : system.monitors)
  {
    dofs.insert(dofs.end(), monitor.dofs.begin(), monitor.dofs.end());
    for (const auto &row : monitor.rows)
      dofs.insert(dofs.end(), row.dofs.begin(), row.dofs.end());
  }
  return dofs;
}

/**
 * The state of the checks between the output rows: with HATI, a reduced
 * implicit part recovers only its history DoFs (its others were checked at
 * the last full row; non-finite reduced coordinates are recovered in full).
 */
template <class Integrator>
const Vector<double> &checked_displacement(const Integrator &i)
{
  return i.displacement();
}
template <class Integrator> const Vector<double> &checked_velocity(const Integrator &i)
{
  return i.velocity();
}
const Vector<double> &checked_displacement(const HATICoupling &i)
{
  return i.displacement(true);
}
const Vector<double> &checked_velocity(const HATICoupling &i) { return i.velocity(true); }

OutputState output_state(const Newmark &integrator, LawSample &, const bool, const bool)
{
  OutputState s;
  s.time = integrator.time();
  s.displacement = &integrator.displacement();
  s.velocity = &integrator.velocity();
  return s;
}

/** Fewer macro steps of HATI than this get a warning. */
constexpr unsigned long min_macro_steps = 10;

/**
 * The check of the coupling's interface work (G5, doc/theory.md 9.6). G3' is
 * stable (spectral radius 1 for the linear scheme) but not strictly
 * dissipative: its interface work `W_G` is a quadrature error of what crosses
 * the interface within a macro step and may be positive for a while. On the
 * reference bar it stays below 7 % of the run's largest physical energy
 * (kinetic, internal, external and contact work, branch storage) for m up to
 * 10 at DT = 4 times the implicit part's critical step, and below 48 % even
 * at m = 30 on a 25-element bar (DT = 15 critical steps). An unstable macro
 * step grows without bound: the default crane under Rinaldi at DT = 4e-4 s
 * passes 5 % at 0.92 s, 50 % at 1.5 s and 100 % at 1.66 s (4.5 times by
 * 2.5 s), its wheel forces 10 to 400 times too large. So `W_G` above
 * warn_share of the largest energy gets one warning (the coupling exchanges
 * energy at this DT: compare with a smaller one), and above refuse_share,
 * more than the largest physical energy the run ever held, the run is
 * stopped.
 */
class InterfaceEnergyGuard
{
public:
  static constexpr double warn_share = 0.05;
  static constexpr double refuse_share = 1.;

  /**
   * Check the energies @p e of a history row of @p coupling: a warning
   * through @p problem the first time `W_G` passes warn_share of the
   * largest energy, an ExcMessage (after flushing @p writer) when it passes
   * refuse_share.
   */
  void check(const Energies &e,
             const HATICoupling &coupling,
             const bool has_contacts,
             Problem &problem,
             OutputWriter &writer)
  {
    scale = std::max({scale,
                      std::abs(e.kinetic),
                      std::abs(e.internal),
                      std::abs(e.external_work),
                      std::abs(e.contact_work),
                      std::abs(e.damping_stored)});
    const double W = e.interface_work;
    if (!(W > warn_share * scale))
      return;
    std::ostringstream s;
    s << std::setprecision(3) << "HATI: the interface has put " << W
      << " J into the model by t = " << coupling.time() << " s (" << 100. * W / scale
      << " % of the largest physical energy so far, " << scale << " J)";
    const std::string step = [&]
    {
      std::ostringstream d;
      d << "the macro step DT = " << coupling.time_step() << " s (Time step "
        << coupling.micro_time_step() << " s x Time step ratio "
        << coupling.time_step_ratio() << ")";
      return d.str();
    }();
    if (!(W > refuse_share * scale))
    {
      if (!warned)
        problem.warn(s.str() +
                     ": G3' is stable but exchanges this much energy across "
                     "the interface at " +
                     step +
                     "; compare with a run at a smaller Time step ratio (user guide "
                     "4.7)");
      warned = true;
      return;
    }
    try
    {
      writer.flush(); // the rows so far, whole
    }
    catch (...)
    {
    }
    s << ", more than the model ever held: the coupling is unstable at " << step
      << (has_contacts ? ", too large for this model's contacts" : "")
      << "; reduce the Time step ratio or the Time step";
    throw ExcMessage(s.str());
  }

private:
  /** The largest physical energy so far (J). */
  double scale = 0.;
  bool warned = false;
};

/** One transient run of a stepping integrator: run_time_loop() in parts. */
template <class Integrator> class TimeLoop
{
public:
  TimeLoop(Integrator &integrator, Problem &problem, RunDirectory &directory);
  /** The steps, with the outputs and the progress lines. */
  void run(TimerOutput &timer);
  /** summary.json and the terminal summary after run(). */
  void finish(TimerOutput &timer, SummaryEntries summary);

private:
  static constexpr bool explicit_scheme = std::is_same_v<Integrator, CDLagrange>;
  /** The output rows due at @p step (history, energy, VTU). */
  void write(const unsigned long step);
  /** state.bin of the current step (Output/State interval, RunState). */
  void write_state();
  /** HATI: contact statistics and contacts.csv rows at the micro steps. */
  void connect_micro_steps();
  /** Update the envelopes with the rows HATI deferred (defer_displacement()). */
  void update_deferred_envelopes();
  /** Envelope rows expanded together (2.7 ms a row by 16 on the 3D crane, 10 ms alone).
   */
  static constexpr unsigned int deferred_rows = 16;
  /** The entries of the coupling (subdomains, time per part). */
  void add_coupling_summary(SummaryEntries &summary) const;
  /** The outputs of the force laws (LawOutput::finish(), e.g. the contact statistics). */
  void add_law_output_summary(SummaryEntries &summary);
  /** The force laws' entries (ForceLaw::add_summary(), e.g. `rope_tension` of R1). */
  void add_force_law_summary(SummaryEntries &summary) const;
  /** The first end of the run a force law gives (ForceLaw::run_end()), or nullptr. */
  const RunEnd *law_run_end() const;

  Integrator &integrator;
  Problem &problem;
  const DiscreteSystem &system;
  RunDirectory &directory;
  const double dt, end_time;
  OutputWriter writer;
  const unsigned long n_steps, every_history, every_state, every_vtu;
  /** Steps between two rows of section_forces.csv, a multiple of every_history. */
  const unsigned long every_section_row;
  WallClock output_clock; // a TimerOutput section costs more than a row
  /**
   * The stepping loop and the output inside it, on the one clock of
   * output_clock (write(0) comes before the loop), so that their difference,
   * stepping_wall_time, is never negative.
   */
  WallClock loop_clock;
  double loop_output = 0.;
  /** The registered post-processors that apply (postprocessor_registry()). */
  std::vector<std::unique_ptr<Postprocessor>> postprocessors;
  /** The force laws' outputs (ForceLaw::make_output(), e.g. the contacts'). */
  LawOutputs law_outputs;
  Progress progress;
  /** The state finite and within its bound (at rows and between them). */
  const Watchdog watchdog;
  /**
   * Steps between two checks of the state besides the output rows: every
   * Newmark step; CD-Lagrange every Watchdog::check_interval steps and HATI
   * every check_interval micro steps (at least every macro step: its global
   * state is assembled for the check).
   */
  const unsigned long every_check;
  /** n_steps unless SIGINT/SIGTERM or a RunEnd stopped the loop. */
  unsigned long steps_done = 0;
  unsigned long micro_step = 0;
  /** The result that ended the run before End time (a derailment, D2), or nullptr. */
  const RunEnd *run_end = nullptr;
  OutputState contact_row;
  /** The laws' sample of an output row (CD-Lagrange). */
  LawSample row_sample;
  /** HATI: the check of the interface work (G5). */
  InterfaceEnergyGuard interface_guard;
  /**
   * The laws' outputs and contacts.csv rows of every (micro) step, timed
   * on one step in SampledWallClock::sample_every.
   */
  SampledWallClock statistics_clock;
};

template <class Integrator>
TimeLoop<Integrator>::TimeLoop(Integrator &integrator,
                               Problem &problem,
                               RunDirectory &directory)
    : integrator(integrator), problem(problem), system(problem.system),
      directory(directory), dt(integrator.time_step()),
      end_time(problem.time_parameters.end_time),
      writer(directory, problem.system, *problem.model),
      n_steps(std::llround(std::ceil((end_time - system.start_time) / dt - 1e-9))),
      every_history(steps_between(problem.output_parameters.history_interval, dt)),
      every_state(problem.output_parameters.state_interval > 0.
                      ? steps_between(problem.output_parameters.state_interval, dt)
                      : 0),
      every_vtu(problem.output_parameters.vtu_interval > 0.
                    ? steps_between(problem.output_parameters.vtu_interval, dt)
                    : 0),
      // at most one row past the last step (an interval of 1e20 s gives the
      // rows at t = 0 and at the end, not an overflowed rounding)
      every_section_row(every_history *
                        steps_between(problem.output_parameters.section_force_interval,
                                      every_history * dt,
                                      n_steps / every_history + 1)),
      law_outputs(force_laws_of(integrator),
                  {problem.system,
                   *problem.model,
                   problem.output_parameters,
                   end_time,
                   directory,
                   [&problem](const std::string &message) { problem.warn(message); }}),
      progress(problem.output_parameters.progress_interval, end_time, system.start_time),
      watchdog(*problem.model, problem.system),
      every_check(
          explicit_scheme ? Watchdog::check_interval
          : std::is_same_v<Integrator, HATICoupling>
              ? std::max(1ul, Watchdog::check_interval / time_step_ratio(integrator))
              : 1ul)
{
  std::cout << "  " << n_steps << " steps of " << dt << " s to t = " << end_time << " s"
            << std::endl;
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
    if (n_steps < min_macro_steps)
    {
      std::ostringstream s;
      s << "Time integration/HATI/Time step ratio = " << integrator.time_step_ratio()
        << " makes the macro step DT = " << dt << " s: only " << n_steps << " macro step"
        << (n_steps == 1 ? "" : "s") << " to End time = " << end_time << " s (fewer than "
        << min_macro_steps
        << "; the implicit subdomain and the outputs are sampled that coarsely)";
      problem.warn(s.str());
    }
  // per contact name: impacts, peak force, time out of contact, episodes
  writer.set_initial_contacts(initial_gaps(system));
  for (const auto &entry : postprocessor_registry().entries())
    if (auto p = entry.create(
            {problem.system, problem.ground_acceleration, problem.output_parameters}))
      postprocessors.push_back(std::move(p));
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
  {
    // a history row without section forces and VTU reads the monitors, the
    // DoFs of Model::write_section_forces() (its envelope) and the values of
    // the model's output functionals (the solid cuts), which a reduced
    // implicit part gives from its coordinates
    integrator.set_output_functionals(problem.model->output_functionals());
    std::vector<types::global_dof_index> displacement_dofs =
        problem.model->section_force_dofs();
    const auto velocity_dofs = monitor_dofs(system);
    displacement_dofs.insert(
        displacement_dofs.end(), velocity_dofs.begin(), velocity_dofs.end());
    integrator.set_history_dofs(displacement_dofs, velocity_dofs);
    connect_micro_steps();
  }
}

template <class Integrator> void TimeLoop<Integrator>::write(const unsigned long step)
{
  const WallClock::Scope scope(output_clock);
  const bool section_force_row = step % every_section_row == 0 || step == n_steps;
  const bool vtu_row = every_vtu > 0 && (step % every_vtu == 0 || step == n_steps);
  // a reduced implicit part's envelope rows are expanded by batches (C1):
  // the rows before a VTU row (its envelope file) first, in time order
  bool envelope_deferred = false;
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
  {
    if (vtu_row)
      update_deferred_envelopes();
    else if (section_force_row && integrator.defer_displacement())
    {
      envelope_deferred = true;
      if (integrator.n_deferred() >= deferred_rows)
        update_deferred_envelopes();
    }
  }
  const bool history_row = (!section_force_row || envelope_deferred) && !vtu_row;
  OutputState s = output_state(integrator, row_sample, history_row, !vtu_row);
  s.envelope_deferred = envelope_deferred;
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
    if (history_row)
      s.output_functionals = integrator.output_functionals();
  check_state(watchdog, writer, *s.displacement, s.velocity, s.time);
  if (step % every_history == 0 || step == n_steps)
  {
    s.section_force_rows = section_force_row;
    for (const auto &p : postprocessors)
      p->history_row(s);
    writer.write_history(s);
    const Energies e = integrator.energies();
    writer.write_energy(s.time, e);
    if constexpr (std::is_same_v<Integrator, HATICoupling>)
      interface_guard.check(e, integrator, !system.contacts.empty(), problem, writer);
  }
  if (vtu_row)
    writer.write_vtu(s);
}

template <class Integrator> void TimeLoop<Integrator>::write_state()
{
  const WallClock::Scope scope(output_clock);
  directory.replace(
      "state.bin", state_file_content(current_run_state(integrator, problem)), true);
}

template <class Integrator> void TimeLoop<Integrator>::update_deferred_envelopes()
{
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
    integrator.expand_deferred([this](const double time, const Vector<double> &U)
                               { writer.update_envelopes(time, U); });
}

template <class Integrator> void TimeLoop<Integrator>::connect_micro_steps()
{
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
  {
    if (integrator.gaps().empty() && law_outputs.empty())
      return;
    const unsigned long every_contact_row = steps_between(
        problem.output_parameters.history_interval, dt / time_step_ratio(integrator));
    integrator.after_micro_step =
        [this, every_contact_row](const HATICoupling::ContactSample &sample)
    {
      const SampledWallClock::Scope scope(statistics_clock);
      writer.track_contacts(sample.gaps, sample.impulses);
      law_outputs.add_step(sample, integrator.micro_time_step());
      if (++micro_step % every_contact_row == 0)
      {
        contact_row.time = sample.time;
        contact_row.gaps = sample.gaps;
        contact_row.normal_velocities = sample.normal_velocities;
        contact_row.impulses = sample.impulses;
        contact_row.active = sample.active;
        contact_row.impulse_duration = integrator.micro_time_step();
        contact_row.tangential_impulses = sample.tangential_impulses;
        contact_row.slip_velocities = sample.slip_velocities;
        contact_row.friction_states = sample.friction_states;
        writer.write_contacts(contact_row);
      }
    };
  }
}

template <class Integrator> void TimeLoop<Integrator>::run(TimerOutput &timer)
{
  write(0);
  const double output_before = output_clock.seconds();
  const WallClock::Scope loop(loop_clock);
  TimerOutput::Scope scope(timer, "time stepping");
  for (unsigned long step = 1; step <= n_steps; ++step)
  {
    integrator.step();
    steps_done = step;
    if constexpr (explicit_scheme)
      if (!law_outputs.empty()) // e.g. the contacts' statistics
      {
        const SampledWallClock::Scope scope(statistics_clock);
        const LawSample &sample =
            law_outputs.take_sample(integrator.time(), integrator.velocity());
        writer.track_contacts(sample.gaps, sample.impulses);
        law_outputs.add_step(sample, dt);
      }
    if (step % every_history == 0 || (every_vtu > 0 && step % every_vtu == 0) ||
        step == n_steps)
      write(step); // checks the state
    else if (step % every_check == 0)
      check_state(watchdog,
                  writer,
                  checked_displacement(integrator),
                  &checked_velocity(integrator),
                  integrator.time());
    if ((!explicit_scheme || (step & 255) == 0) && progress.due())
    {
      progress.print(integrator.time(), step);
      writer.flush();
    }
    // a result that ends the run (RunEnd, e.g. a derailment, D2): the rows of
    // this step, then stop
    if (const RunEnd *end = law_run_end(); end != nullptr && run_end == nullptr)
    {
      run_end = end;
      if (step % every_history != 0 && step != n_steps)
        write(step);
      std::cout << "hati: " << end->message << std::endl;
    }
    const bool stop = stop_requested(); // SIGINT/SIGTERM: stop after a complete step
    if (every_state > 0 && (step % every_state == 0 || step == n_steps || stop))
      write_state();
    if (stop || run_end != nullptr)
      break;
  }
  loop_output = output_clock.seconds() - output_before;
}

template <class Integrator>
void TimeLoop<Integrator>::add_coupling_summary(SummaryEntries &summary) const
{
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
  {
    const auto &parts = problem.decomposition->parts;
    summary.insert(
        summary.end(),
        {{"time_step_ratio", integrator.time_step_ratio()},
         {"micro_dt", integrator.micro_time_step()},
         {"n_dofs_explicit", parts[0].system.n_dofs()},
         {"n_dofs_implicit", parts[1].system.n_dofs()},
         {"n_interface_dofs", integrator.n_interface_dofs()},
         {"wall_time_explicit", integrator.explicit_seconds()},
         {"wall_time_implicit", integrator.implicit_seconds()},
         {"wall_time_interface", integrator.interface_seconds()},
         {"wall_time_superposition", integrator.superposition_seconds()},
         {"wall_time_redo", integrator.redo_seconds()},
         {"wall_time_setup", integrator.setup_seconds()},
         {"interface_velocity_jump", integrator.interface_velocity_jump()},
         {"redone_macro_steps", integrator.redone_macro_steps()},
         {"hati_redone_macro_steps", integrator.redone_macro_steps()},
         {"hati_redo_passes", integrator.redo_passes()},
         {"hati_correction_halvings", integrator.correction_halvings()},
         {"hati_discontinuous_macro_steps", integrator.discontinuous_macro_steps()},
         {"hati_largest_discontinuous_residual",
          integrator.largest_discontinuous_residual()},
         {"hati_frozen_closure_macro_steps", integrator.frozen_closure_macro_steps()},
         {"hati_largest_frozen_closure_gap", integrator.largest_frozen_closure_gap()},
         {"hati_jacobian_macro_steps", integrator.jacobian_macro_steps()},
         {"interface_iterations", integrator.interface_iterations()},
         {"ramp_patterns", integrator.ramp_patterns()}});
    std::cout << "  HATI wall time: explicit " << integrator.explicit_seconds()
              << " s, implicit " << integrator.implicit_seconds() << " s, interface "
              << integrator.interface_seconds() << " s, set-up "
              << integrator.setup_seconds() << " s; interface velocity jump "
              << integrator.interface_velocity_jump() << " m/s; "
              << integrator.redone_macro_steps() << " macro steps redone" << std::endl;
    if (integrator.discontinuous_macro_steps() > 0)
    {
      std::ostringstream m;
      m << "HATI: " << integrator.discontinuous_macro_steps()
        << " redone macro step(s) kept an interface velocity jump of up to "
        << integrator.largest_discontinuous_residual()
        << " of the interface velocity scale (the largest jump of the run: "
        << integrator.interface_velocity_jump()
        << " m/s): a contact closing within the macro step "
           "makes the macro-end velocity jump as the closure moves by a micro step, "
           "and the continuity had no root (doc/theory.md 9.6); the energy balance "
           "includes it";
      problem.warn(m.str());
    }
    if (integrator.frozen_closure_macro_steps() > 0)
      std::cout << "  HATI: " << integrator.frozen_closure_macro_steps()
                << " redone macro step(s) kept a pass with the contacts' closures "
                   "frozen at the best pass's (largest gap of a contact taken as closed "
                   "or open against its sign: "
                << integrator.largest_frozen_closure_gap() << " m)" << std::endl;
  }
  else
    (void)summary;
}

template <class Integrator>
void TimeLoop<Integrator>::add_law_output_summary(SummaryEntries &summary)
{
  LawOutputTimes times;
  if constexpr (!std::is_same_v<Integrator, Newmark>)
    times.rows = integrator.contact_seconds();
  times.outputs = statistics_clock.seconds();
  if constexpr (std::is_same_v<Integrator, HATICoupling>)
    times.outputs += integrator.statistics_sample_seconds();
  law_outputs.finish(summary, std::cout, times);
}

template <class Integrator>
void TimeLoop<Integrator>::add_force_law_summary(SummaryEntries &summary) const
{
  if constexpr (!std::is_same_v<Integrator, Newmark>)
  {
    for (const auto &law : integrator.force_laws())
      law->add_summary(summary, std::cout);
  }
  else
    (void)summary;
}

template <class Integrator> const RunEnd *TimeLoop<Integrator>::law_run_end() const
{
  if constexpr (!std::is_same_v<Integrator, Newmark>)
  {
    for (const auto &law : integrator.force_laws())
      if (const RunEnd *end = law->run_end())
        return end;
  }
  return nullptr;
}

template <class Integrator>
void TimeLoop<Integrator>::finish(TimerOutput &timer, SummaryEntries summary)
{
  {
    const WallClock::Scope scope(output_clock);
    update_deferred_envelopes();
  }
  writer.finish();
  const auto [drift, scale] = writer.energy_balance();
  const double wall = progress.wall_time();
  // time of the steps alone: the stepping loop minus the output inside it
  // (one clock; the guard only against a clock that is not monotonic)
  const double stepping = std::max(0., loop_clock.seconds() - loop_output);
  // the integrator's set-up (assembly, factorisations, ramp responses): the
  // timer's sections before the loop
  double setup = 0.;
  for (const auto &[section, seconds] :
       timer.get_summary_data(TimerOutput::OutputData::total_wall_time))
    if (section != "time stepping")
      setup += seconds;
  summary.insert(summary.end(),
                 problem.initial_state_summary.begin(),
                 problem.initial_state_summary.end());
  for (const auto &entry : problem.model->summary_entries(problem.static_contact_forces))
    summary.push_back(entry);
  summary.insert(
      summary.end(),
      {{"model", problem.model->description()},
       {"n_dofs", system.n_dofs()},
       {"n_contacts", n_contacts(system.contacts)},
       {"dt", dt},
       {"end_time", integrator.time()},
       {"n_steps", steps_done},
       {"wall_time", wall},
       {"setup_wall_time", setup},
       {"stepping_wall_time", stepping},
       {"wall_time_output", loop_output},
       {"ns_per_dof_per_step",
        steps_done > 0 ? 1e9 * stepping / (double(steps_done) * system.n_dofs())
                       : std::nan("")},
       {"n_impacts", writer.n_impacts()},
       {"max_penetration", writer.max_penetration()},
       {"energy_balance_error", drift},
       {"energy_balance_relative", scale > 0. ? drift / scale : 0.}});
  add_coupling_summary(summary);
  add_law_output_summary(summary);
  add_force_law_summary(summary);
  std::cout << problem.model->results_table();
  for (const auto &p : postprocessors)
    p->finish(summary, std::cout);
  for (const auto &p : postprocessors)
    p->write_files(directory);
  add_qualification(problem, directory, summary);
  write_summary(directory.path() + "/summary.json",
                summary,
                problem.warnings,
                run_end != nullptr ? run_end->status : "");
  if (run_end != nullptr)
    std::cout << "  " << run_end->status << ": " << run_end->message << std::endl;
  std::cout << "  done: " << steps_done << " steps in " << wall << " s (output "
            << output_clock.seconds() << " s in " << output_clock.calls() << " calls); ";
  if (n_contacts(system.contacts) > 0)
    std::cout << "impacts: " << writer.n_impacts()
              << ", max penetration: " << writer.max_penetration() << " m, ";
  std::cout << "energy balance error: " << drift << " J ("
            << (scale > 0. ? drift / scale : 0.) << " of the largest energy)\n"
            << "  summary: " << directory.path() << "/summary.json" << std::endl;
  timer.print_summary();
}
} // namespace

template <class Integrator>
void run_time_loop(Integrator &integrator,
                   Problem &problem,
                   RunDirectory &directory,
                   TimerOutput &timer,
                   SummaryEntries summary)
{
  TimeLoop<Integrator> loop(integrator, problem, directory);
  loop.run(timer);
  loop.finish(timer, std::move(summary));
}

template void
run_time_loop(CDLagrange &, Problem &, RunDirectory &, TimerOutput &, SummaryEntries);
template void
run_time_loop(Newmark &, Problem &, RunDirectory &, TimerOutput &, SummaryEntries);
template void
run_time_loop(HATICoupling &, Problem &, RunDirectory &, TimerOutput &, SummaryEntries);
} // namespace hati

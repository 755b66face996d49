#include <deal.II/base/utilities.h>

#include <hati/parameters/run_parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hati
{
void TimeIntegrationParameters::declare_parameters(ParameterHandler &prm,
                                                   const Choice &methods)
{
  prm.enter_subsection("Time integration");
  prm.declare_entry("Method",
                    "CD-Lagrange",
                    Patterns::Selection(methods.selection),
                    methods.documentation);
  prm.declare_entry(
      "Time step",
      "1e-3",
      Patterns::Double(0.),
      "Time step dt of CD-Lagrange (s), > 0. Refused above the critical "
      "step 2/omega_max times the Safety factor; with stiffness damping a1 the "
      "critical step is (2/omega_max) (sqrt(1 + xi^2) - xi), xi = a1 omega_max / 2. "
      "For event-driven: the sampling interval of history.csv when Output/History "
      "interval is 0.");
  prm.declare_entry("End time", "1", Patterns::Double(0.), "End of the simulation (s).");
  prm.declare_entry("Safety factor",
                    "1",
                    Patterns::Double(0., 1.),
                    "The time step must satisfy dt <= Safety factor * dt_crit (-), "
                    "0 < factor <= 1.");
  prm.declare_entry("Maximum number of steps",
                    "1e9",
                    Patterns::Double(1.),
                    "Refuse a run whose End time / Time step exceeds this number of "
                    "steps (-): a time step given in the wrong unit would otherwise run "
                    "for days.");
  prm.declare_entry("Maximum number of events",
                    "200",
                    Patterns::Integer(1),
                    "event-driven: stop with an error after this many impacts (Zeno "
                    "accumulation: an event-driven scheme cannot pass the accumulation "
                    "point, an event-capturing one can).");
  prm.declare_entry("Maximum number of DoFs",
                    "36",
                    Patterns::Integer(1),
                    "event-driven: refuse models with more DoFs than this (-).");
  prm.declare_entry("Relative tolerance",
                    "1e-12",
                    Patterns::Double(0.),
                    "event-driven: CVODE relative tolerance (-).");
  prm.declare_entry("Absolute tolerance",
                    "1e-14",
                    Patterns::Double(0.),
                    "event-driven: CVODE absolute tolerance (m, m/s).");
  prm.leave_subsection();
}

void TimeIntegrationParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Time integration");
  method = prm.get("Method");
  time_step = prm.get_double("Time step");
  end_time = prm.get_double("End time");
  safety_factor = prm.get_double("Safety factor");
  max_steps = prm.get_double("Maximum number of steps");
  max_events = prm.get_integer("Maximum number of events");
  max_event_driven_dofs = prm.get_integer("Maximum number of DoFs");
  relative_tolerance = prm.get_double("Relative tolerance");
  absolute_tolerance = prm.get_double("Absolute tolerance");
  prm.leave_subsection();
  AssertThrow(time_step > 0.,
              ExcMessage("Time integration/Time step must be > 0 (s), got " +
                         std::to_string(time_step) + "."));
  AssertThrow(safety_factor > 0.,
              ExcMessage("Time integration/Safety factor must be > 0."));
  const double n_steps = std::ceil(end_time / time_step - 1e-9);
  if (n_steps > max_steps)
  {
    std::ostringstream s;
    s << "Time integration: End time / Time step = " << end_time << " / " << time_step
      << " = " << n_steps << " steps, more than 'Maximum number of steps' = " << max_steps
      << ": check the Time step (s) or raise the maximum.";
    AssertThrow(false, ExcMessage(s.str()));
  }
}

void AnalysisParameters::declare_parameters(ParameterHandler &prm, const Choice &analyses)
{
  prm.enter_subsection("Analysis");
  prm.declare_entry("Type",
                    "transient",
                    Patterns::Selection(analyses.selection),
                    analyses.documentation);
  prm.declare_entry(
      "Number of modes",
      "6",
      Patterns::Integer(1),
      "modal: number of natural frequencies and mode shapes to compute (-).");
  prm.declare_entry(
      "Initial state",
      "given",
      Patterns::Selection("given|static|file"),
      "transient: start from the model's initial displacement and velocity "
      "(given) or at rest from the static equilibrium under the constant loads "
      "(gravity, nodal loads), without the base excitation (static); contacts "
      "with a zero initial gap are closed in that equilibrium and must push. "
      "file: restart from the state an earlier run of the same model wrote "
      "(Initial state file, Output/State interval): its displacements, "
      "velocities and contact forces at its time t_0 (s), from which the run "
      "goes on to End time with the records at t_0 onwards (any method and "
      "time step; the memory of frequency-range damping starts afresh).");
  prm.declare_entry("Initial state file",
                    "",
                    Patterns::Anything(),
                    "Initial state = file: the state.bin an earlier run of the same "
                    "model wrote (its Output/State interval), as a path absolute or "
                    "relative to the current directory.");
  prm.leave_subsection();
}

void AnalysisParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Analysis");
  type = prm.get("Type");
  n_modes = prm.get_integer("Number of modes");
  initial_state = prm.get("Initial state");
  initial_state_file = prm.get("Initial state file");
  AssertThrow(
      initial_state != "file" || !initial_state_file.empty(),
      ExcMessage("Analysis/Initial state = file needs Analysis/Initial state file "
                 "(the state.bin of an earlier run, Output/State interval)"));
  prm.leave_subsection();
}

void OutputParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Output");
  prm.declare_entry("Output directory",
                    "",
                    Patterns::Anything(),
                    "Directory of every output file; empty: output/<name of the "
                    "parameter file without extension>/ in the current directory.");
  prm.declare_entry("Output interval",
                    "0",
                    Patterns::Double(0.),
                    "Simulated time between two VTU snapshots (s); 0: no VTU output.");
  prm.declare_entry("History interval",
                    "0",
                    Patterns::Double(0.),
                    "Simulated time between two rows of history.csv, contacts.csv and "
                    "energy.csv (s); 0: every time step.");
  prm.declare_entry("Section force interval",
                    "0",
                    Patterns::Double(0.),
                    "Simulated time between two rows of section_forces.csv (s); 0: at "
                    "every history row. Rounded to a whole number of history rows. The "
                    "section_force_envelope of summary.json is taken at every history "
                    "row whatever this interval.");
  prm.declare_entry(
      "Contact force window",
      "0.001",
      Patterns::Double(0.),
      "Window of the mean contact force (s): summary.json gives per contact name "
      "peak_mean_force (N), the largest impulse the contact takes within any interval "
      "of this length divided by the length. Unlike peak_impact_force (the impulse "
      "of one step / dt, which grows as dt falls because a plastic impact is resolved "
      "in one step) it does not depend on the time step once the window spans many "
      "steps: compare runs with different steps by it. A window longer than the run is "
      "taken as the End time. 0: not computed.");
  prm.declare_entry(
      "State interval",
      "0",
      Patterns::Double(0.),
      "Simulated time between two writes of the whole state (displacement and "
      "velocity of every DoF, the contact forces) to state.bin (s), each "
      "replacing the last one whole, at the end of the run and when it is "
      "stopped (Ctrl-C): a later run restarts from it (Analysis/Initial "
      "state = file). CD-Lagrange, Newmark and HATI runs. 0: no state file.");
  prm.declare_entry("Progress interval",
                    "2",
                    Patterns::Double(0.),
                    "Wall-clock time between two progress lines on the terminal (s).");
  prm.declare_entry(
      "Spectra",
      "",
      Patterns::List(Patterns::Anything()),
      "Monitor points whose pseudo-acceleration response spectra (of their absolute "
      "acceleration, m/s^2) go to spectra.csv with those of the base excitation "
      "(transient runs with CD-Lagrange, Newmark or HATI), 'name, name, ...'; empty: "
      "none. Computed from the history rows (exact recursion of Nigam & Jennings "
      "1969): the history interval must be at most a tenth of the shortest period.");
  prm.declare_entry("Spectrum damping ratios",
                    "0.02, 0.05",
                    Patterns::List(Patterns::Double(0., 0.99)),
                    "Damping ratios of the response spectra (-), from 0 to 0.99.");
  prm.declare_entry("Spectrum periods",
                    "",
                    Patterns::List(Patterns::Double(0.)),
                    "Periods of the response spectra (s), increasing, > 0; empty: 100 "
                    "periods from 0.02 s to 4 s, equally spaced in log T.");
  prm.leave_subsection();
}

void OutputParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Output");
  directory = prm.get("Output directory");
  vtu_interval = prm.get_double("Output interval");
  history_interval = prm.get_double("History interval");
  section_force_interval = prm.get_double("Section force interval");
  contact_force_window = prm.get_double("Contact force window");
  progress_interval = prm.get_double("Progress interval");
  state_interval = prm.get_double("State interval");
  const std::string spectra_text = prm.get("Spectra"),
                    ratios_text = prm.get("Spectrum damping ratios");
  spectra = Utilities::split_string_list(spectra_text);
  spectrum_damping_ratios =
      Utilities::string_to_double(Utilities::split_string_list(ratios_text));
  const std::string periods = prm.get("Spectrum periods");
  spectrum_periods = Utilities::string_to_double(Utilities::split_string_list(periods));
  prm.leave_subsection();
  if (spectrum_periods.empty()) // 0.02-4 s, 100 log-spaced (log_spaced_periods())
    for (unsigned int i = 0; i < 100; ++i)
      spectrum_periods.push_back(i == 99 ? 4. : 0.02 * std::pow(200., i / 99.));
  for (unsigned int i = 0; i < spectrum_periods.size(); ++i)
    AssertThrow(spectrum_periods[i] > 0. &&
                    (i == 0 || spectrum_periods[i] > spectrum_periods[i - 1]),
                ExcMessage("Output/Spectrum periods: the periods must be > 0 and "
                           "increasing (s), got " +
                           periods));
  // a name or a ratio given twice would give two identical columns
  for (unsigned int i = 0; i < spectra.size(); ++i)
    AssertThrow(std::find(spectra.begin(), spectra.begin() + i, spectra[i]) ==
                    spectra.begin() + i,
                ExcMessage("Output/Spectra: the monitor '" + spectra[i] +
                           "' is named twice (name each monitor once), got " +
                           spectra_text));
  for (unsigned int i = 0; !spectra.empty() && i < spectrum_damping_ratios.size(); ++i)
    AssertThrow(std::find(spectrum_damping_ratios.begin(),
                          spectrum_damping_ratios.begin() + i,
                          spectrum_damping_ratios[i]) ==
                    spectrum_damping_ratios.begin() + i,
                ExcMessage("Output/Spectrum damping ratios: a ratio is given twice "
                           "(give each ratio once), got " +
                           ratios_text));
  AssertThrow(spectra.empty() || !spectrum_damping_ratios.empty(),
              ExcMessage("Output/Spectrum damping ratios: at least one damping ratio "
                         "is needed for Output/Spectra"));
}
} // namespace hati

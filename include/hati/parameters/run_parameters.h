#ifndef hati_parameters_run_parameters_h
#define hati_parameters_run_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The values a selecting parameter accepts (`a|b|c`, those of a Registry)
 * and its documentation.
 */
struct Choice
{
  std::string selection, documentation;
};

/** `Time integration` subsection: scheme, steps, limits. */
struct TimeIntegrationParameters
{
  /** Declare the subsection; `Method` is one of the registered @p methods. */
  static void declare_parameters(ParameterHandler &prm, const Choice &methods);
  void parse_parameters(ParameterHandler &prm);

  /** "CD-Lagrange" (event capturing) or "event-driven" (CVODE reference). */
  std::string method = "CD-Lagrange";
  double time_step = 1e-3;   ///< s
  double end_time = 1.;      ///< s
  double safety_factor = 1.; ///< dt <= safety * dt_crit
  /** Refuse runs of more steps than this, End time / Time step (-). */
  double max_steps = 1e9;
  unsigned int max_events = 200;
  unsigned int max_event_driven_dofs = 36;
  double relative_tolerance = 1e-12;
  double absolute_tolerance = 1e-14;
};

/** `Analysis` subsection: what to compute. */
struct AnalysisParameters
{
  /** Declare the subsection; `Type` is one of the registered @p analyses. */
  static void declare_parameters(ParameterHandler &prm, const Choice &analyses);
  void parse_parameters(ParameterHandler &prm);

  /** "transient", "static" or "modal". */
  std::string type = "transient";
  unsigned int n_modes = 6;
  /**
   * "given" (the model's initial state), "static" (static equilibrium) or
   * "file" (the state of an earlier run, initial_state_file).
   */
  std::string initial_state = "given";
  /** Initial state = file: the state.bin to restart from (RunState). */
  std::string initial_state_file;
};

/** `Output` subsection. */
struct OutputParameters
{
  static void declare_parameters(ParameterHandler &prm);
  void parse_parameters(ParameterHandler &prm);

  /** Output directory; empty: `output/<parameter file name>/`. */
  std::string directory;
  double vtu_interval = 0.;     ///< s; 0: no VTU output
  double history_interval = 0.; ///< s; 0: every step
  /// s; 0: at every history row (section_forces.csv)
  double section_force_interval = 0.;
  /** s; window of the mean contact force (peak_mean_force); 0: none. */
  double contact_force_window = 1e-3;
  double progress_interval = 2.; ///< s of wall time between progress lines
  /** s of simulated time between two writes of state.bin; 0: none. */
  double state_interval = 0.;
  /** Monitor points whose response spectra go to spectra.csv; empty: none. */
  std::vector<std::string> spectra;
  /** Damping ratios of the response spectra (-), each in [0, 1). */
  std::vector<double> spectrum_damping_ratios = {0.02, 0.05};
  /** Periods of the response spectra (s), increasing; default 0.02-4 s, 100 log-spaced.
   */
  std::vector<double> spectrum_periods;
};
} // namespace hati

#endif

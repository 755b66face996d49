#ifndef hati_simulation_h
#define hati_simulation_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/base/timer.h>

#include <hati/model/decomposition.h>
#include <hati/model/discrete_system.h>
#include <hati/model/model.h>
#include <hati/parameters/run_parameters.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/newmark.h>
#include <hati/time/rayleigh_damping.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

class RunDirectory;

/**
 * One run: reads the parameters, builds the model's discrete system, runs
 * the chosen time integration with its outputs, prints a summary.
 */
class Simulation
{
public:
  /** Declare every parameter of hati. */
  static void declare_parameters(ParameterHandler &prm);

  /**
   * Parse @p prm (already read from @p parameter_file) and build the model.
   * The output directory defaults to `output/<parameter file stem>/`.
   */
  Simulation(ParameterHandler &prm, const std::string &parameter_file);
  ~Simulation();

  /** Run the time integration and write every output. */
  void run();

  /**
   * After run() threw: `summary.json` says `"status": "failed"` with
   * @p message if the run had begun writing its outputs (RunDirectory::fail()).
   */
  void record_failure(const std::string &message) noexcept;

private:
  void run_cd_lagrange();
  void run_event_driven();
  void run_newmark();
  void run_hati();
  void run_static();
  void run_modal();
  /** The time loop with outputs, for CDLagrange and Newmark. */
  template <class Integrator>
  void run_transient(Integrator &integrator,
                     TimerOutput &timer,
                     std::vector<std::pair<std::string, std::string>> summary);

  AnalysisParameters analysis_parameters;
  TimeIntegrationParameters time_parameters;
  NewmarkParameters newmark_parameters;
  RayleighDamping damping;
  HATIParameters hati_parameters;
  DecompositionParameters decomposition_parameters;
  OutputParameters output_parameters;
  CommonModelParameters common_parameters;
  std::unique_ptr<Model> model;
  /** The whole model's system: single-domain methods and every output. */
  DiscreteSystem system;
  /** The explicit and implicit subdomains of Method = HATI. */
  std::unique_ptr<Decomposition> decomposition;
  std::string output_directory;
  /** The output directory, locked and cleaned when the analysis begins. */
  std::unique_ptr<RunDirectory> run_directory;
  std::string parameter_file;

  /**
   * Print the static contact forces @p forces (N, one per contact row of
   * the system, summed per contact name) as a table and return the
   * `static_contact_forces` entry of summary.json (name -> N; empty string
   * if the system has no closed contact).
   */
  std::string report_static_contact_forces(const std::vector<double> &forces);
  /** Static contact forces per contact name (N), filled by the above. */
  std::map<std::string, double> static_contact_forces;
  /** Ground acceleration per direction (m/s^2; empty: none), for absolute accelerations.
   */
  std::array<std::function<double(double)>, 3> ground_acceleration;
  /** summary.json entries of the static initial state (transient runs). */
  std::vector<std::pair<std::string, std::string>> initial_state_summary;
};

/**
 * The command line of the `hati` executable (Boost.Program_options):
 * `hati file.prm [--set "Subsection/Entry=value"]...`,
 * `hati --print-parameters`, `hati --help`. Returns the exit code; errors
 * are printed as one line on stderr.
 */
int run_command_line(int argc, char **argv);

/**
 * Apply one `--set "Subsection/Entry=value"` override of the command line
 * to @p prm (whose parameters are declared, at its top level): the path
 * before `=` is split at `/` into subsections and the entry, each trimmed,
 * and the trimmed value set. Throws a one-line message naming the
 * assignment if there is no `=`, the entry is not declared or the value
 * does not match its pattern; @p prm is back at its top level either way.
 */
void apply_override(ParameterHandler &prm, const std::string &assignment);
} // namespace hati

#endif

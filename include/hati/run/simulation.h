#ifndef hati_run_simulation_h
#define hati_run_simulation_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>

namespace hati
{
using namespace dealii;

class Problem;
class RunDirectory;

/**
 * One run of the `hati` executable: the Problem set up from the parameters
 * (Problem), the output directory (RunDirectory, not touched before the
 * analysis begins) and the analysis chosen by `Analysis/Type`
 * (analysis_registry()), which for transient runs is the method of
 * `Time integration/Method` (method_registry()).
 */
class Simulation
{
public:
  /** Declare every parameter of hati (Problem::declare_parameters()). */
  static void declare_parameters(ParameterHandler &prm);

  /**
   * Parse @p prm (already read from @p parameter_file) and create the model.
   * The output directory defaults to `output/<parameter file stem>/`.
   */
  Simulation(ParameterHandler &prm, const std::string &parameter_file);
  ~Simulation();

  /** Build the model, run the analysis and write every output. */
  void run();

  /**
   * What run() does before its first output (the model built, every input
   * file read, the analysis set up up to RunDirectory::begin()), then stop
   * with the output directory untouched: throws run()'s one-line message if
   * the run would be refused. A Simulation runs or checks once.
   */
  void check();

  /**
   * Call @p hook once run() has locked and cleaned the output directory,
   * before its first output (RunDirectory::after_begin).
   */
  void when_output_begins(std::function<void(RunDirectory &)> hook);

  /**
   * After run() threw: `summary.json` says `"status": "failed"` with
   * @p message if the run had begun writing its outputs (RunDirectory::fail()).
   */
  void record_failure(const std::string &message) noexcept;

  /**
   * Mark the run as a member of a suite: it writes its qualification.csv
   * but no report.html (the suite writes one for all its members).
   */
  void as_suite_member() { suite_member = true; }

  /** A warning of the run (Problem::warn()): stderr and summary.json `warnings`. */
  void warn(const std::string &message);

private:
  std::unique_ptr<Problem> problem;
  std::string output_directory;
  /** The output directory, locked and cleaned when the analysis begins. */
  std::unique_ptr<RunDirectory> run_directory;
  std::string parameter_file;
  bool suite_member = false;
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

/**
 * Read the parameter file @p file (`.prm`, with or without a UTF-8
 * byte-order mark, `.json` or `.xml`) into @p prm, whose parameters are
 * declared; a missing file, a file that is not regular (FIFO, device,
 * folder) or a syntax error is a one-line message naming the file.
 */
void read_parameter_file(ParameterHandler &prm, const std::string &file);
} // namespace hati

#endif

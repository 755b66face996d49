#include <hati/base/names.h>
#include <hati/output/run_directory.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>

#include <algorithm>
#include <filesystem>

namespace hati
{
namespace
{
/**
 * Refuse a state file inside the run's own output folder: the run takes
 * the folder over (its previous files deleted, state.bin replaced), so the
 * state it starts from would be gone before a new one replaced it.
 */
void refuse_state_in_output(const std::string &state, const std::string &folder)
{
  std::error_code e1, e2;
  const auto file = std::filesystem::weakly_canonical(state, e1);
  auto dir = std::filesystem::weakly_canonical(folder, e2);
  if (dir.filename().empty()) // a trailing '/'
    dir = dir.parent_path();
  if (e1 || e2)
    return; // unreadable paths are named by the state reader
  const auto within = std::mismatch(dir.begin(), dir.end(), file.begin(), file.end());
  AssertThrow(within.first != dir.end(),
              ExcMessage("Analysis/Initial state file = " + printable(state) +
                         ": the state is inside this run's output folder " +
                         printable(folder) +
                         ", which the run takes over (its state.bin replaced, the files "
                         "of the run that wrote it deleted): copy it elsewhere or set "
                         "another Output/Output directory"));
}
} // namespace

void run_transient_analysis(Problem &problem, RunDirectory &directory)
{
  if (problem.analysis_parameters.initial_state == "file")
    refuse_state_in_output(problem.analysis_parameters.initial_state_file,
                           directory.path());
  problem.prepare_transient();
  method_registry().get(problem.time_parameters.method).create(problem, directory);
}
} // namespace hati

/**
 * @file
 * libFuzzer harness of the command-line overrides, `hati file.prm --set
 * "Subsection/Entry=value"`: every line of the input is one `--set`
 * argument, applied in order by hati::apply_override() to a
 * ParameterHandler holding every parameter of hati at its defaults, as
 * run_command_line() does after parsing the file. An override that hati
 * refuses ends the input, as it ends the run. Checked on the way:
 *
 * - an accepted override takes effect: the entry reads back as the trimmed
 *   value (else abort(): a finding);
 * - accepted or refused, the handler is back at its top level (else abort()).
 *
 * When every line is accepted, the parameters go through the front end of
 * fuzz_front_end.h (parameter structs, model build, accelerograms,
 * decomposition). Errors thrown as exceptions are the expected outcome of
 * bad input; crashes, sanitizer reports, hangs, aborts and other exceptions
 * are findings. Run by bench/fuzz.sh from the repository root (the seeds
 * name mesh and accelerogram files relative to it); its seeds are the
 * parameter files turned into `--set` lines (bench/fuzz/prm_to_set.py).
 */
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <hati/run/simulation.h>

#include "fuzz_common.h"
#include "fuzz_front_end.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace
{
/**
 * Whether @p prm is at its top level: Model/Decomposition and Time
 * integration/HATI are found from it (relative to the current subsection;
 * an override creates the subsections it names, so one path could be
 * faked). get() cannot tell: in Release it returns "" for an entry not
 * found.
 */
bool at_top_level(const dealii::ParameterHandler &prm)
{
  return prm.subsection_path_exists({"Model", "Decomposition"}) &&
         prm.subsection_path_exists({"Time integration", "HATI"});
}

/** abort() with @p what and the assignment: a finding. */
[[noreturn]] void fail(const char *what, const std::string &assignment)
{
  std::fprintf(stderr, "fuzz_set: %s: --set '%s'\n", what, assignment.c_str());
  std::abort();
}

/**
 * Apply @p assignment as `hati --set` does and check the result; false if
 * hati refuses it.
 */
bool apply(dealii::ParameterHandler &prm, const std::string &assignment)
{
  bool accepted = true;
  try
  {
    hati::apply_override(prm, assignment);
  }
  catch (const std::exception &)
  {
    accepted = false; // a one-line error: the expected outcome of bad input
  }
  if (!at_top_level(prm))
    fail("the handler is left inside a subsection", assignment);
  if (!accepted)
    return false;

  // the entry reads back as the trimmed value
  const auto eq = assignment.find('=');
  const std::string path = dealii::Utilities::trim(assignment.substr(0, eq)),
                    value = dealii::Utilities::trim(assignment.substr(eq + 1));
  std::vector<std::string> parts;
  std::string::size_type start = 0, slash;
  while ((slash = path.find('/', start)) != std::string::npos)
  {
    parts.push_back(dealii::Utilities::trim(path.substr(start, slash - start)));
    start = slash + 1;
  }
  std::string stored;
  try
  {
    stored = prm.get(parts, dealii::Utilities::trim(path.substr(start)));
  }
  catch (...)
  {
    fail("an accepted override cannot be read back", assignment);
  }
  if (stored != value)
    fail(("an accepted override reads back as '" + stored + "'").c_str(), assignment);
  return true;
}

void run(const std::string &text)
{
  dealii::ParameterHandler prm;
  hati::Simulation::declare_parameters(prm);
  std::string::size_type start = 0;
  while (start < text.size())
  {
    const auto end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    if (!apply(prm, line))
      return; // hati stops at the first refused override
  }
  hati::fuzz::run_front_end(prm);
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  hati::fuzz::silence_stdout();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  try
  {
    run(std::string(reinterpret_cast<const char *>(data), size));
  }
  catch (const std::exception &)
  {
    // a one-line error: the expected outcome of bad input
  }
  return 0;
}

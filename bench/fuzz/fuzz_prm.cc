/**
 * @file
 * libFuzzer harness of the `.prm` front end: the input is parsed as a `.prm`
 * file by a ParameterHandler holding every parameter of hati (a UTF-8
 * byte-order mark is skipped, as `hati file.prm` does), then every parameter
 * struct is parsed as the Simulation constructor does, the model is created
 * (`Model/Type`) and built, and what Simulation::run() does before the
 * analysis follows: the accelerograms are read, the base excitation added
 * and, for `Method = HATI`, the model decomposed into its two subdomains.
 * No output directory is created (fuzz_front_end.h). Models with more than
 * 500 elements are skipped (large is slow, not wrong). Errors thrown as
 * exceptions are the expected outcome of bad input; crashes, sanitizer
 * reports, hangs and other exceptions are findings. Run by bench/fuzz.sh
 * from the repository root, so that relative mesh and accelerogram paths
 * of the seeds resolve.
 */
#include <deal.II/base/parameter_handler.h>

#include <hati/simulation.h>

#include "fuzz_common.h"
#include "fuzz_front_end.h"

#include <exception>
#include <sstream>

namespace
{
void run(const std::string &text)
{
  dealii::ParameterHandler prm;
  hati::Simulation::declare_parameters(prm);
  std::istringstream in(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text);
  prm.parse_input(in, "fuzz.prm");
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

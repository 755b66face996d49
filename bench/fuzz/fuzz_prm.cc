/**
 * @file
 * libFuzzer harness of the `.prm` front end: the input is parsed as a `.prm`
 * file by a ParameterHandler holding every parameter of hati at its
 * defaults (declared once and reset before each input: ReusedHandler; a
 * UTF-8 byte-order mark is skipped, as `hati file.prm` does), then hati's one
 * set-up path (hati::Problem) runs up to the analysis: the parameters
 * parsed, the model created (`Model/Type`) and built, the accelerograms
 * read, the base excitation added and, for `Method = HATI`, the model
 * decomposed into its two subdomains.
 * No output directory is created (fuzz_front_end.h). Models with more than
 * 500 elements are skipped (large is slow, not wrong). Errors thrown as
 * exceptions are the expected outcome of bad input; crashes, sanitizer
 * reports, hangs and other exceptions are findings. Run by bench/fuzz.sh
 * from the repository root, so that relative mesh and accelerogram paths
 * of the seeds resolve.
 */
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <hati/run/simulation.h>

#include "fuzz_common.h"
#include "fuzz_front_end.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/**
 * The ParameterHandler of every input, declared once: declaring the about
 * 140 parameters of hati was 80 % of an execution under ASan. Before each
 * input, handler() puts it back to its declared state. That is sound
 * because parse_input() changes nothing but the values of declared entries
 * (set(), which also checks the pattern) and the current subsection (left
 * inside one when it throws): it never declares or creates anything, and
 * hati declares no actions or aliases. So the state after handler() is that
 * of a new handler: every entry at its default, at the top level. With
 * HATI_FUZZ_CHECK_RESET=1 in the environment this is checked after every
 * reset against the printed parameters of the new handler (abort() if not).
 */
class ReusedHandler
{
public:
  ReusedHandler() : check(std::getenv("HATI_FUZZ_CHECK_RESET") != nullptr)
  {
    hati::Simulation::declare_parameters(prm);
    declared = printed();
    // every entry and its default, from the ShortPRM listing
    std::istringstream in(declared);
    std::vector<std::string> path;
    for (std::string line; std::getline(in, line);)
    {
      line = dealii::Utilities::trim(line);
      if (line.compare(0, 11, "subsection ") == 0)
        path.push_back(dealii::Utilities::trim(line.substr(11)));
      else if (line == "end")
        path.pop_back();
      else if (line.compare(0, 4, "set ") == 0)
      {
        const auto eq = line.find('=');
        entries.push_back({path,
                           dealii::Utilities::trim(line.substr(4, eq - 4)),
                           dealii::Utilities::trim(line.substr(eq + 1))});
      }
    }
    for (const auto &e : entries)
      if (prm.get(e.path, e.name) != e.value)
        fail("the listing of the declared parameters does not read back");
  }

  /** The handler in its declared state. */
  dealii::ParameterHandler &handler()
  {
    while (!at_top_level())
      prm.leave_subsection();
    for (const auto &e : entries)
      if (prm.get(e.path, e.name) != e.value)
      {
        for (const auto &s : e.path)
          prm.enter_subsection(s);
        prm.set(e.name, e.value);
        for (unsigned int i = 0; i < e.path.size(); ++i)
          prm.leave_subsection();
      }
    if (check && printed() != declared)
      fail("the reset handler differs from a new one");
    return prm;
  }

private:
  struct Entry
  {
    std::vector<std::string> path;
    std::string name, value;
  };

  /** The parameters with their values, as `hati --print-parameters` without comments. */
  std::string printed()
  {
    std::ostringstream out;
    prm.print_parameters(out, dealii::ParameterHandler::ShortPRM);
    return out.str();
  }

  /**
   * Whether the current subsection is the top level: Model/Decomposition is
   * found from it (relative to the current subsection; parse_input() creates
   * no subsection). get() cannot tell: in Release it returns "" for an entry
   * not found.
   */
  bool at_top_level() const
  {
    return prm.subsection_path_exists({"Model", "Decomposition"});
  }

  [[noreturn]] static void fail(const char *what)
  {
    std::fprintf(stderr, "fuzz_prm: %s\n", what);
    std::abort();
  }

  dealii::ParameterHandler prm;
  const bool check;
  std::string declared;
  std::vector<Entry> entries;
};

/** 0, or -1 (libFuzzer 15 and later: not added to the corpus) for a model skipped as too
 * large. */
int run(const std::string &text)
{
  static ReusedHandler reused;
  dealii::ParameterHandler &prm = reused.handler();
  std::istringstream in(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text);
  prm.parse_input(in, "fuzz.prm");
  return hati::fuzz::run_front_end(prm) ? 0 : -1;
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
    return run(std::string(reinterpret_cast<const char *>(data), size));
  }
  catch (const std::exception &)
  {
    // a one-line error: the expected outcome of bad input
  }
  return 0;
}

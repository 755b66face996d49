/**
 * @file
 * What the `.prm` and `--set` harnesses (fuzz_prm.cc, fuzz_set.cc) do once
 * the parameters are in a ParameterHandler: hati's one set-up path
 * (hati::Problem) up to the analysis: every parameter struct parsed, the
 * model created (`Model/Type`) and built, the accelerograms read, the base
 * excitation added and, for `Method = HATI`, the model decomposed into its
 * two subdomains. No output directory is created. Models with more than
 * max_elements elements are skipped (large is slow, not wrong).
 */
#ifndef hati_bench_fuzz_front_end_h
#define hati_bench_fuzz_front_end_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <hati/run/problem.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

namespace hati
{
namespace fuzz
{
/** Largest model (elements or cells) the harnesses build. */
constexpr double max_elements = 500.;

/** @p text as a number if it is one (strtod, whole text), else 0. */
inline double number(const std::string &text)
{
  const std::string t = dealii::Utilities::trim(text);
  char *end = nullptr;
  const double x = std::strtod(t.c_str(), &end);
  return (!t.empty() && *end == '\0') ? x : 0.;
}

/**
 * Whether the model of @p prm has more than max_elements elements (an
 * estimate from the entries, before the model's own checks).
 */
inline bool too_large(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("Model");
  const std::string type = prm.get("Type");
  double n = 0.;
  if (type == "bar")
  {
    prm.enter_subsection("Bar");
    n = number(prm.get("Number of elements"));
    prm.leave_subsection();
  }
  else if (type == "solid")
  {
    prm.enter_subsection("Solid");
    const double across = number(prm.get("Number of elements across"));
    n = 10. * number(prm.get("Number of elements")) * across * across;
    prm.leave_subsection();
  }
  else if (type == "frame")
  {
    prm.enter_subsection("Frame");
    for (const std::string &item :
         dealii::Utilities::split_string_list(prm.get("Members"), ';'))
    {
      const auto values = dealii::Utilities::split_string_list(item, ',');
      if (values.size() >= 5)
        n += std::abs(number(values[4]));
    }
    prm.leave_subsection();
  }
  else if (type == "bridge crane")
  {
    prm.enter_subsection("Bridge crane");
    const double length = 2. * std::abs(number(prm.get("Span"))) +
                          2. * std::abs(number(prm.get("End carriage wheelbase"))) +
                          2. * std::abs(number(prm.get("Girder spacing"))) +
                          4. * std::abs(number(prm.get("Trolley wheelbase")));
    const double h = std::min(std::abs(number(prm.get("Element length"))),
                              std::abs(number(prm.get("Explicit element length"))));
    n = h > 0. ? 4. * length / h : 0.;
    prm.leave_subsection();
  }
  prm.leave_subsection();
  return !(n <= max_elements); // NaN too
}

/**
 * The set-up of every run (Problem: parameters, model, discrete system,
 * loads and, for `Method = HATI`, the subdomains, with the model's default
 * decomposition) without an output directory, silent, on the parameters of
 * @p prm (at its top level). Returns false if the model is skipped
 * (too_large()); throws on bad input as hati does.
 */
inline bool run_front_end(dealii::ParameterHandler &prm)
{
  if (too_large(prm)) // before the model's own checks
    return false;
  hati::Problem problem(prm, dealii::ConditionalOStream(std::cout, false));
  problem.build_system();
  problem.add_loads();
  if (problem.time_parameters.method == "HATI")
    problem.decompose();
  return true;
}
} // namespace fuzz
} // namespace hati

#endif

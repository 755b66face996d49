/**
 * @file
 * What the `.prm` and `--set` harnesses (fuzz_prm.cc, fuzz_set.cc) do once
 * the parameters are in a ParameterHandler: every parameter struct is parsed
 * as the Simulation constructor does, the model is created (`Model/Type`)
 * and built, and what Simulation::run() does before the analysis follows:
 * the accelerograms are read, the base excitation added and, for `Method =
 * HATI`, the model decomposed into its two subdomains. No output directory
 * is created. Models with more than max_elements elements are skipped
 * (large is slow, not wrong).
 */
#ifndef hati_bench_fuzz_front_end_h
#define hati_bench_fuzz_front_end_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <hati/loading/accelerogram.h>
#include <hati/loading/base_excitation.h>
#include <hati/model/decomposition.h>
#include <hati/model/discrete_system.h>
#include <hati/model/model.h>
#include <hati/parameters/run_parameters.h>
#include <hati/simulation.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/newmark.h>
#include <hati/time/rayleigh_damping.h>

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
 * The Simulation constructor without its output directory, then
 * Simulation::run() up to the analysis, on the parameters of @p prm (at its
 * top level). Returns false if the model is skipped (too_large()); throws
 * on bad input as hati does.
 */
inline bool run_front_end(dealii::ParameterHandler &prm)
{
  hati::AnalysisParameters analysis;
  hati::TimeIntegrationParameters time;
  hati::NewmarkParameters newmark;
  hati::RayleighDamping damping;
  hati::HATIParameters coupling;
  hati::DecompositionParameters decomposition_parameters;
  hati::OutputParameters output;
  hati::CommonModelParameters common;
  analysis.parse_parameters(prm);
  time.parse_parameters(prm);
  prm.enter_subsection("Time integration");
  prm.enter_subsection("Newmark");
  newmark.parse_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Damping");
  damping.parse_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("HATI");
  coupling.parse_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  prm.enter_subsection("Model");
  prm.enter_subsection("Decomposition");
  decomposition_parameters.parse_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  output.parse_parameters(prm);
  common.parse_parameters(prm);
  if (too_large(prm))
    return false;
  const std::unique_ptr<hati::Model> model = hati::create_model(prm);

  hati::DiscreteSystem system;
  model->build(common, system);
  hati::check_finite(system);
  system.fill_default_mass_influence();
  auto acceleration = hati::base_acceleration_step(common.base_acceleration,
                                                   common.base_acceleration_start);
  for (unsigned int d = 0; d < 3; ++d)
    if (!common.accelerogram_files[d].empty())
    {
      const auto record = std::make_shared<hati::Accelerogram>(
          hati::Accelerogram::read(common.accelerogram_files[d],
                                   common.accelerogram_units,
                                   common.accelerogram_scale));
      volatile double peak = record->peak().first;
      (void)peak;
      const auto step = acceleration[d];
      acceleration[d] = [record, step](const double t)
      { return (*record)(t) + (step ? step(t) : 0.); };
    }
  hati::add_base_excitation(system, acceleration);
  if (time.method == "HATI")
  {
    hati::Decomposition decomposition;
    hati::decompose(*model, common, decomposition_parameters, decomposition);
  }
  return true;
}
} // namespace fuzz
} // namespace hati

#endif

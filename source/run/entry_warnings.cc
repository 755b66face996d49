#include <hati/run/entry_warnings.h>
#include <hati/run/problem.h>

#include <string>
#include <vector>

namespace hati
{
namespace
{
/** The value of the entry @p entry of the subsection @p path. */
std::string value(const dealii::ParameterHandler &prm,
                  const std::vector<std::string> &path,
                  const std::string &entry)
{
  return prm.get(path, entry);
}
} // namespace

void warn_inapplicable_entries(const dealii::ParameterHandler &prm, Problem &problem)
{
  const std::string &type = problem.analysis_parameters.type;
  const bool transient = type == "transient";
  const std::string method = problem.time_parameters.method;
  const std::string reduction =
      value(prm, {"Model", "Decomposition"}, "Implicit reduction");
  if (reduction != "none" && !(transient && method == "HATI"))
    problem.warn("Model/Decomposition/Implicit reduction = " + reduction +
                 " is ignored: it reduces the implicit part of a transient HATI run "
                 "(this run: " +
                 (transient ? "Method = " + method : "Analysis/Type = " + type) + ")");
  if (!transient && problem.analysis_parameters.initial_state == "file")
    problem.warn("Analysis/Initial state = file is ignored: a " + type +
                 " analysis starts from no state (Initial state file '" +
                 problem.analysis_parameters.initial_state_file + "' not read)");
  if (!transient && problem.output_parameters.state_interval > 0.)
    problem.warn("Output/State interval is ignored: a " + type +
                 " analysis writes no state file (transient runs do)");
  if (problem.qualification_parameters.enabled() && !transient &&
      type != "response spectrum")
    problem.warn("Qualification is ignored: a " + type +
                 " analysis is not checked (transient runs, suites and "
                 "response-spectrum analyses are)");
  if (value(prm, {"Model"}, "Type") == "bridge crane" &&
      value(prm, {"Model", "Bridge crane"}, "Eccentricities") == "false" &&
      dealii::Utilities::string_to_double(
          value(prm, {"Model", "Bridge crane"}, "End carriage height")) != 0.5)
    problem.warn("Model/Bridge crane/End carriage height is ignored: with "
                 "Eccentricities = false every wheel acts on the member axes");
}
} // namespace hati

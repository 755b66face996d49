#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>

namespace hati
{
void run_transient_analysis(Problem &problem, RunDirectory &directory)
{
  problem.prepare_transient();
  method_registry().get(problem.time_parameters.method).create(problem, directory);
}
} // namespace hati

#ifndef hati_run_entry_warnings_h
#define hati_run_entry_warnings_h

#include <deal.II/base/parameter_handler.h>

namespace hati
{
class Problem;

/**
 * Warn (Problem::warn(): stderr and summary.json `warnings`) of every entry
 * of @p prm set away from its default where this run does not apply it,
 * so that none is ignored silently (issue #59, finding 8):
 * `Model/Decomposition/Implicit reduction` without a transient HATI run,
 * `Analysis/Initial state = file` and `Output/State interval` in a static
 * or modal analysis, `Model/Bridge crane/End carriage height` with
 * `Eccentricities = false`.
 */
void warn_inapplicable_entries(const dealii::ParameterHandler &prm, Problem &problem);
} // namespace hati

#endif

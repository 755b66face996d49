#ifndef hati_run_suite_checks_h
#define hati_run_suite_checks_h

#include <deal.II/base/parameter_handler.h>

#include <hati/run/suite_plan.h>

#include <string>

namespace hati
{
using namespace dealii;

/**
 * The quick checks of a suite before anything runs, linear in the number
 * of values (not of members): each value of each Suite/Variations entry
 * and each file of each record applies to @p prm as an override (the entry
 * exists, the value matches its pattern; @p prm is restored afterwards),
 * and each accelerogram or mesh file a record or a variation names is a
 * regular file. Throws a one-line message naming Suite/Variations or the
 * record.
 */
void check_suite_overrides(ParameterHandler &prm, const SuiteParameters &suite);

/**
 * A digest of every input file named by @p prm (Loading/Accelerogram X, Y,
 * Z and Model/Frame/Mesh file): one line per file, `<entry> = <path>:
 * fnv1a64 <hex>, <size> bytes` (`missing` if it cannot be read). A suite
 * keeps it in a member's folder (`input_digests.txt`): a member whose
 * record or mesh changed is run again, not reused.
 */
std::string input_digests(const ParameterHandler &prm);
} // namespace hati

#endif

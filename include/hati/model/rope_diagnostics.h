#ifndef hati_model_rope_diagnostics_h
#define hati_model_rope_diagnostics_h

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <hati/model/rope.h>

#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * If the message of @p e starts with @p prefix (e.g. the static analysis'
 * singular stiffness), throw it again with the first of @p ropes that is
 * slack at @p U (shorter than its rest length) named: a rope whose rest
 * length exceeds any length it can reach holds nothing, and a part hung
 * only by it floats. Returns otherwise.
 */
void rethrow_naming_slack_rope(const ExceptionBase &e,
                               const std::string &prefix,
                               const std::vector<Rope> &ropes,
                               const Vector<double> &U);
} // namespace hati

#endif

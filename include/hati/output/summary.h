#ifndef hati_output_summary_h
#define hati_output_summary_h

#include <hati/base/summary_value.h>

#include <string>
#include <vector>

namespace hati
{
/**
 * The JSON text of @p value on one line, written with nlohmann::json (the
 * only JSON writer of hati): strings escaped (control characters too,
 * invalid UTF-8 replaced), numbers in shortest round-trip form, numbers
 * that are not finite as `null`.
 */
std::string to_json(const SummaryValue &value);

/**
 * Write `summary.json` atomically (write_file_atomically()), one top-level
 * entry per line. The entries `warnings` (the list @p warnings of the
 * run's warnings, Problem::warn(); empty if none) and `status` are added at
 * the end: `"completed"`, or `"interrupted"` after SIGINT/SIGTERM
 * (stop_requested()), then with `time_reached` (s), the value of the entry
 * `end_time`; or @p status when it is not empty (a run a result ended
 * before its End time, RunEnd: e.g. `derailed`), also with `time_reached`.
 */
void write_summary(const std::string &filename,
                   const SummaryEntries &entries,
                   const std::vector<std::string> &warnings,
                   const std::string &status = "");

/**
 * The `summary.json` of a run that failed: `warnings` (@p warnings),
 * `status` `"failed"` and @p message.
 */
std::string failed_summary(const std::string &message,
                           const std::vector<std::string> &warnings = {});
} // namespace hati

#endif

#ifndef hati_run_qualification_run_h
#define hati_run_qualification_run_h

#include <hati/base/summary_value.h>
#include <hati/output/qualification.h>

#include <string>
#include <vector>

namespace hati
{
class Problem;
class RunDirectory;

/**
 * The verdicts of a run whose Qualification asks for checks (Q1): from the
 * entries @p summary it is about to write (run_demands()), the entry
 * `qualification` added to them, `qualification.csv` and `geometry.csv`
 * written into @p directory, the rows kept in Problem::verdicts (printed at
 * the end of the run). Nothing without checks.
 */
void add_qualification(Problem &problem,
                       RunDirectory &directory,
                       SummaryEntries &summary);

/**
 * `report.html` of the run or suite in @p folder (scripts/report.py, the
 * way the suite's plots are drawn), where @p parameters ask for checks; a
 * warning (stderr) if it could not be written, never an error.
 */
void write_qualification_report(const QualificationParameters &parameters,
                                const std::string &folder);
} // namespace hati

#endif

#include <hati/output/plot_script.h>
#include <hati/output/run_directory.h>
#include <hati/output/summary.h>
#include <hati/run/problem.h>
#include <hati/run/qualification_run.h>

#include <iostream>

namespace hati
{
void add_qualification(Problem &problem, RunDirectory &directory, SummaryEntries &summary)
{
  if (!problem.qualification_parameters.enabled())
    return;
  SummaryValue all = SummaryValue::object();
  for (const auto &[key, value] : summary)
    all.set(key, value);
  const auto rows = qualify(run_demands(to_json(all)), problem.qualification_parameters);
  summary.emplace_back("qualification", qualification_json(rows));
  directory.replace("qualification.csv", qualification_csv(rows), true);
  // the drawing of the model in the report
  const std::string geometry = problem.model->geometry_csv();
  if (!geometry.empty())
    directory.replace("geometry.csv", geometry, true);
  problem.verdicts = rows;
}

void write_qualification_report(const QualificationParameters &parameters,
                                const std::string &folder)
{
  if (!parameters.enabled())
    return;
  const std::string warning = run_plot_script("report.py", folder);
  if (warning.empty())
    std::cout << "  report: " << folder << "/report.html" << std::endl;
  else
    std::cerr << "hati: warning: report.html was not written: " << warning << std::endl;
}
} // namespace hati

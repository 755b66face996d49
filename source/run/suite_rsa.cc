// A suite's comparison with the response-spectrum analysis of its model
// (issue #57; doc/user_guide.md, "Response-spectrum analysis and what the
// time history saves").

#include <deal.II/base/exceptions.h>

#include <hati/base/messages.h>
#include <hati/base/silence.h>
#include <hati/output/rsa_comparison.h>
#include <hati/output/suite_statistics.h>
#include <hati/run/simulation.h>
#include <hati/run/suite_runner.h>

#include <iostream>

namespace hati
{
void SuiteRunner::compare_with_response_spectrum(const SuiteStatistics &statistics,
                                                 SummaryEntries &extra) const
{
  const std::string dir = folder + "/response_spectrum";
  try
  {
    refuse_linked_folder(dir);
    // the directions of the records (the file's own accelerograms without Records)
    std::array<bool, 3> excited{{false, false, false}};
    for (unsigned int d = 0; d < 3; ++d)
    {
      excited[d] = suite.records.empty() && !own_accelerograms[d].empty();
      for (const auto &r : suite.records)
        excited[d] = excited[d] || !r.files[d].empty();
    }
    std::string directions;
    for (unsigned int d = 0; d < 3; ++d)
      if (excited[d])
        directions += std::string(directions.empty() ? "" : ", ") + "XYZ"[d];
    AssertThrow(!directions.empty(),
                ExcMessage("the suite's records excite no direction"));
    // the first member's model, the file's Design spectrum (a member's is reset)
    SuiteMember member = members[0];
    member.name = "response_spectrum";
    std::vector<std::string> overrides;
    for (const std::string &o : member.overrides)
      if (o.rfind("Design spectrum/", 0) != 0)
        overrides.push_back(o);
    overrides.push_back("Analysis/Type=response spectrum");
    overrides.push_back("Analysis/Initial state=given");
    overrides.push_back("Response spectrum/Directions=" + directions);
    overrides.push_back("Output/Output directory=" + dir);
    member.overrides = overrides;
    ParameterHandler prm;
    std::string text;
    member_parameters(member, prm, text);
    {
      const Silence quiet;
      Simulation simulation(prm, parameter_file);
      simulation.as_suite_member(); // the suite's report holds it
      simulation.run();
    }
    const std::vector<ComparisonRow> rows =
        rsa_comparison_rows(statistics.group_statistic(0), dir + "/summary.json");
    out.replace("rsa_comparison.csv", rsa_comparison_csv(rows), true);
    extra.emplace_back("rsa_comparison",
                       rsa_comparison_summary(rows, suite.effective_statistic(), dir));
    std::cout << rsa_comparison_table(rows, suite.effective_statistic())
              << "  (the response-spectrum analysis in " << dir << "/)" << std::endl;
  }
  catch (const std::exception &e)
  {
    std::cerr << "hati: warning: suite: the response-spectrum comparison was not made: "
              << one_line_message(e) << std::endl;
  }
}
} // namespace hati

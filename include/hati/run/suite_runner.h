#ifndef hati_run_suite_runner_h
#define hati_run_suite_runner_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hati/output/member_result.h>
#include <hati/run/suite_plan.h>

#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * A suite of member runs (doc/user_guide.md, "Qualifying a crane on a suite
 * of records"): each member is one Simulation (the one set-up path,
 * Problem) of the parameter file with the command line's overrides and the
 * member's (plan_suite()), in its own folder, its terminal output in its
 * `member.log`. A member that fails is reported and the others go on; a
 * member whose folder holds a `summary.json` with `"status": "completed"`
 * and a `parameters.prm` equal to the member's is not run again (`reused`).
 *
 * On several MPI ranks the members are handed out one at a time to the rank
 * that is free (WorkCounter: every rank, rank 0 included, runs members);
 * each member runs on its rank alone (its Trilinos objects on
 * MPI_COMM_SELF) and the results are gathered on rank 0, which writes
 * `suite.csv`, `suite_summary.json`, `suite_spectra.csv` (SuiteStatistics)
 * and draws `suite.png` and `spectra.png` (scripts/plot_suite.py).
 */
class SuiteRunner
{
public:
  /**
   * @p prm: the parameters of @p parameter_file with the command line's
   * @p overrides applied; @p suite: its subsection Suite. Checks the suite
   * (transient analysis, every override applies) with one-line errors.
   */
  SuiteRunner(ParameterHandler &prm,
              const std::string &parameter_file,
              const std::vector<std::string> &overrides,
              const SuiteParameters &suite,
              const MPI_Comm comm);

  /** Run this rank's members and, on rank 0, write the suite's files; the exit code. */
  int run();

private:
  /** Run (or reuse) @p member; never throws. */
  MemberResult run_member(const SuiteMember &member) const;
  /**
   * The member's parameters (the file, the overrides, the member's) and
   * the text of its parameters.prm; throws a one-line message.
   */
  void member_parameters(const SuiteMember &member,
                         ParameterHandler &prm,
                         std::string &text) const;
  /** Rank 0: the suite's files and plots; the exit code. */
  int finish(std::vector<MemberResult> &results, const double wall_time) const;

  const std::string parameter_file;
  const std::vector<std::string> overrides;
  const SuiteParameters suite;
  const MPI_Comm comm;
  std::string folder;
  std::vector<SuiteMember> members;
};
} // namespace hati

#endif

#ifndef hati_run_suite_runner_h
#define hati_run_suite_runner_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hati/base/summary_value.h>
#include <hati/loading/design_spectrum.h>
#include <hati/output/member_result.h>
#include <hati/output/output_file.h>
#include <hati/output/qualification.h>
#include <hati/run/suite_plan.h>

#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

class SuiteStatistics;

/**
 * A suite of member runs (doc/user_guide.md, "Qualifying a crane on a suite
 * of records"): each member is one Simulation (the one set-up path,
 * Problem) of the parameter file with the command line's overrides and the
 * member's (plan_suite()), in its own folder, its terminal output in its
 * `member.log`. A member that fails is reported and the others go on; a
 * member whose folder holds the whole outputs of a completed run
 * (member_outputs_whole()), a `parameters.prm` equal to the member's and an
 * `input_digests.txt` equal to the digests of its input files now
 * (input_digests()) is not run again (`reused`).
 *
 * Before the first member runs, everything a member needs is checked
 * (check_suite_overrides(); a dry run, Simulation::check(), of each record
 * and each variation value: check_members()), the suite's folder is locked
 * (`.hati-suite.lock`: a second suite there is refused) and its files of an earlier suite
 * (`suite.csv`, `suite_summary.json`, `suite_spectra.csv`, the plots) are
 * deleted; a link at any of them or at a member's folder is refused.
 *
 * On several MPI ranks the members are handed out one at a time to the rank
 * that is free (WorkCounter: every rank, rank 0 included, runs members);
 * each member runs on its rank alone (its Trilinos objects on
 * MPI_COMM_SELF) and the results are gathered on rank 0, which writes
 * `suite.csv`, `suite_summary.json`, `suite_spectra.csv` (SuiteStatistics)
 * and draws `suite.png` and `spectra.png` (scripts/plot_suite.py). Every
 * check and every step of rank 0 before a collective operation ends in an
 * agreement (agree()): a refused suite throws the same AgreedError on every
 * rank; any other exception on one rank aborts them all
 * (without_stray_exceptions()), so that no rank waits for ever.
 */
class SuiteRunner
{
public:
  /**
   * @p prm: the parameters of @p parameter_file with the command line's
   * @p overrides applied; @p suite: its subsection Suite. Checks the suite
   * (transient analysis, check_suite_overrides(), a record to scale) with
   * one-line errors; the same on every rank.
   */
  SuiteRunner(ParameterHandler &prm,
              const std::string &parameter_file,
              const std::vector<std::string> &overrides,
              const SuiteParameters &suite,
              const MPI_Comm comm);

  /**
   * Check the members, take the folder, run this rank's members and, on
   * rank 0, write the suite's files; the exit code. Collective.
   */
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
  /**
   * Dry runs (Simulation::check()) of each value of each variation (the
   * others at their first value) with the first record and of each other
   * record with the first variation, spread over the ranks, silent; throws the
   * one-line message of the first member refused. Agreed (collective).
   */
  void check_members() const;
  /**
   * Rank 0: open and lock the suite's folder (creating it if @p create),
   * refuse links at the suite's files and member folders, and, when
   * @p create, delete the suite's files of an earlier suite. Does nothing
   * without the folder and @p create false, and once the folder is taken.
   */
  void take_folder(const bool create);
  /** The suite's members, folder and statistic, on standard output. */
  void print_header() const;
  /** Run the members handed to this rank; collective (WorkCounter). */
  std::vector<MemberResult>
  run_members(const std::chrono::steady_clock::time_point start) const;
  /** Rank 0: the suite's files and plots; the exit code. */
  int finish(std::vector<MemberResult> &results, const double wall_time) const;
  /**
   * Rank 0, with a Design spectrum: T1 (Suite/Fundamental period, else a
   * modal analysis of the model in `<folder>/modal`, its first mode of
   * nonzero frequency) into fundamental_period.
   */
  void find_fundamental_period();
  /**
   * Rank 0, with a Design spectrum: design_spectrum_check() of the suite's
   * records (or the file's own accelerograms) at its first scale factor,
   * `design_spectrum_check.csv` written; null without a target.
   */
  SummaryValue check_design_spectrum() const;
  /**
   * Rank 0, with a Design spectrum and Suite/Response spectrum comparison:
   * the response-spectrum analysis of the first member's model in
   * `<folder>/response_spectrum` (the directions of the records) against
   * the first group's statistic of @p statistics: `rsa_comparison.csv`, the
   * table on standard output, the suite_summary.json entry
   * `rsa_comparison` in @p extra (suite_rsa.cc). A failure of the analysis
   * is a warning, not the suite's.
   */
  void compare_with_response_spectrum(const SuiteStatistics &statistics,
                                      SummaryEntries &extra) const;

  const std::string parameter_file;
  const std::vector<std::string> overrides;
  const SuiteParameters suite;
  const MPI_Comm comm;
  std::string folder;
  /** The suite's own parameters (parameters.prm of its folder, for the report). */
  std::string suite_parameters;
  std::vector<SuiteMember> members;
  /** Design spectrum (Type none: no check), Loading/Accelerogram units and X, Y, Z,
   * Loading/Accelerogram scale factor. */
  DesignSpectrumParameters design_spectrum;
  /** The checks of the suite's statistic (Qualification; none: no verdicts). */
  QualificationParameters qualification;
  std::string accelerogram_units;
  std::array<std::string, 3> own_accelerograms;
  double base_scale = 1.;
  /** T1 (s) and where it comes from. */
  double fundamental_period = 0.;
  std::string fundamental_period_source;
  /** Rank 0: the suite's folder and its lock, from take_folder() on. */
  OutputFolder out;
  OutputFile lock;
};
} // namespace hati

#endif

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <hati/base/silence.h>
#include <hati/base/version.h>
#include <hati/output/design_spectrum_check.h>
#include <hati/output/output_file.h>
#include <hati/output/plot_script.h>
#include <hati/output/run_directory.h>
#include <hati/output/suite_statistics.h>
#include <hati/run/mpi_consensus.h>
#include <hati/run/qualification_run.h>
#include <hati/run/simulation.h>
#include <hati/run/suite_checks.h>
#include <hati/run/suite_runner.h>
#include <hati/run/work_counter.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

namespace hati
{
namespace
{
double seconds_since(const std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** The whole text of @p path, empty if it cannot be read. */
std::string file_text(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  if (in)
    s << in.rdbuf();
  return s.str();
}

/**
 * A member's terminal output (std::cout) while it lives: kept in memory
 * until attach() gets its `member.log`, opened once the member's folder is
 * locked and cleaned (so that a log is never truncated in a folder another
 * run holds), then written there.
 */
class MemberLog
{
public:
  MemberLog() : old(std::cout.rdbuf(&memory)) {}
  ~MemberLog()
  {
    std::cout.rdbuf(old);
    try
    {
      if (log)
        log->close();
    }
    catch (...)
    {
    }
  }
  MemberLog(const MemberLog &) = delete;
  MemberLog &operator=(const MemberLog &) = delete;

  /** Write what was kept to @p file and send what follows there. */
  void attach(OutputFile file)
  {
    log = std::make_unique<OutputStream>(std::move(file));
    *log << memory.str();
    std::cout.rdbuf(log->rdbuf());
  }

private:
  std::stringbuf memory;
  std::streambuf *old;
  std::unique_ptr<OutputStream> log;
};

/** The suite's own files in its folder (links there refused, old ones deleted). */
const char *const suite_files[] = {"suite.csv",
                                   "design_spectrum_check.csv",
                                   "suite_summary.json",
                                   "suite_spectra.csv",
                                   "suite.png",
                                   "spectra.png",
                                   "plot_suite.log",
                                   "rsa_comparison.csv",
                                   "rsa_comparison.png",
                                   "plot_rsa_comparison.log",
                                   "qualification.csv",
                                   "report.html",
                                   "report.log",
                                   "parameters.prm"};

/** The lock of a suite's folder: a second suite there is refused. */
const char *const suite_lock_name = ".hati-suite.lock";

} // namespace

SuiteRunner::SuiteRunner(ParameterHandler &prm,
                         const std::string &parameter_file,
                         const std::vector<std::string> &overrides,
                         const SuiteParameters &suite,
                         const MPI_Comm comm)
    : parameter_file(parameter_file), overrides(overrides), suite(suite), comm(comm)
{
  AssertThrow(prm.get(std::vector<std::string>{"Analysis"}, "Type") == "transient",
              ExcMessage("Suite: a suite runs transient analyses; Analysis/Type = " +
                         prm.get(std::vector<std::string>{"Analysis"}, "Type")));
  folder = prm.get(std::vector<std::string>{"Output"}, "Output directory");
  {
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::PRM);
    suite_parameters = text.str();
  }
  if (folder.empty())
    folder = "output/" + std::filesystem::path(parameter_file).stem().string();
  check_output_directory(folder);
  // without any record every scale factor gives the same run
  bool record = !suite.records.empty();
  for (const char axis : {'X', 'Y', 'Z'})
  {
    const std::string entry = std::string("Accelerogram ") + axis;
    record =
        record ||
        !Utilities::trim(prm.get(std::vector<std::string>{"Loading"}, entry)).empty();
    for (const auto &v : suite.variations)
      record = record || v.path == "Loading/" + entry;
  }
  AssertThrow(record || (suite.scale_factors.size() == 1 && suite.scale_factors[0] == 1.),
              ExcMessage("Suite/Scale factors: the model has no record to scale "
                         "(Suite/Records and Loading/Accelerogram X, Y, Z are empty): "
                         "every factor would give the same run; give Suite/Records"));
  // every value and record file applies (linear in the values, not the members)
  check_suite_overrides(prm, suite);
  base_scale =
      prm.get_double(std::vector<std::string>{"Loading"}, "Accelerogram scale factor");
  members = plan_suite(suite, folder, base_scale);
  design_spectrum.parse_parameters(prm);
  qualification.parse_parameters(prm);
  accelerogram_units = prm.get(std::vector<std::string>{"Loading"}, "Accelerogram units");
  for (unsigned int d = 0; d < 3; ++d)
    own_accelerograms[d] = Utilities::trim(prm.get(
        std::vector<std::string>{"Loading"}, std::string("Accelerogram ") + "XYZ"[d]));
}

void SuiteRunner::find_fundamental_period()
{
  if (!design_spectrum.active())
    return;
  if (suite.fundamental_period > 0.)
  {
    fundamental_period = suite.fundamental_period;
    fundamental_period_source = "Suite/Fundamental period";
    return;
  }
  // the first member's model, analysed for its modes
  SuiteMember modal = members[0];
  modal.name = "modal";
  const std::string dir = folder + "/modal";
  refuse_linked_folder(dir);
  modal.overrides.push_back("Analysis/Type=modal");
  modal.overrides.push_back("Output/Output directory=" + dir);
  ParameterHandler prm;
  std::string text;
  member_parameters(modal, prm, text);
  {
    const Silence quiet;
    Simulation simulation(prm, parameter_file);
    simulation.as_suite_member();
    simulation.run();
  }
  std::istringstream modes(file_text(dir + "/modes.csv"));
  std::string line;
  std::getline(modes, line); // header: mode,frequency,period,...
  while (std::getline(modes, line))
  {
    const auto comma = line.find(',');
    const double f =
        comma == std::string::npos ? 0. : std::atof(line.c_str() + comma + 1);
    // rigid-body modes come out at about 0 Hz
    if (f > 1e-2)
    {
      fundamental_period = 1. / f;
      break;
    }
  }
  AssertThrow(fundamental_period > 0.,
              ExcMessage("Suite/Fundamental period: the modal analysis of the model (" +
                         dir + "/modes.csv) has no mode above 0.01 Hz; give the period"));
  fundamental_period_source = "modal analysis, " + dir + "/modes.csv";
  std::cout << "hati: suite: T1 = " << fundamental_period << " s ("
            << fundamental_period_source << ")" << std::endl;
}

SummaryValue SuiteRunner::check_design_spectrum() const
{
  if (!design_spectrum.active())
    return SummaryValue();
  std::vector<CheckedRecord> records;
  for (const auto &r : suite.records)
    records.push_back({r.name, r.files});
  if (records.empty())
    records.push_back({"base", own_accelerograms});
  std::string csv;
  const SummaryValue check = design_spectrum_check(DesignSpectrum(design_spectrum),
                                                   records,
                                                   accelerogram_units,
                                                   base_scale * suite.scale_factors[0],
                                                   fundamental_period,
                                                   fundamental_period_source,
                                                   csv,
                                                   std::cout);
  out.replace("design_spectrum_check.csv", csv, true);
  return check;
}

void SuiteRunner::member_parameters(const SuiteMember &member,
                                    ParameterHandler &prm,
                                    std::string &text) const
{
  Simulation::declare_parameters(prm);
  read_parameter_file(prm, parameter_file);
  for (const auto &o : overrides)
    apply_override(prm, o);
  try
  {
    for (const auto &o : member.overrides)
      apply_override(prm, o);
  }
  catch (const std::exception &e)
  {
    std::string message = one_line_message(e);
    const auto see = message.find(" (see hati --print-parameters)");
    if (message.rfind("--set ", 0) == 0)
      message = message.substr(6, see == std::string::npos ? std::string::npos : see - 6);
    AssertThrow(false,
                ExcMessage("Suite: member " + member.name + ": " + message +
                           " (Suite/Variations or Suite/Records)"));
  }
  std::ostringstream used;
  prm.print_parameters(used, ParameterHandler::PRM);
  text = used.str();
}

MemberResult SuiteRunner::run_member(const SuiteMember &member) const
{
  MemberResult r;
  r.index = member.index;
  r.name = member.name;
  r.record = member.record;
  r.scale = member.scale;
  r.variation = member.variation;
  r.variation_values = member.variation_values;
  const std::string dir = folder + "/" + member.name;
  const auto start = std::chrono::steady_clock::now();
  try
  {
    refuse_linked_folder(dir);
    ParameterHandler prm;
    std::string text;
    member_parameters(member, prm, text);
    // the member is its parameters and the contents of its input files
    const std::string digests = input_digests(prm);
    MemberResult earlier = r;
    if (file_text(dir + "/parameters.prm") == text &&
        file_text(dir + "/input_digests.txt") == digests && member_outputs_whole(dir) &&
        read_member_summary(dir, earlier) == "completed")
    {
      earlier.status = "reused";
      earlier.spectra = file_text(dir + "/spectra.csv");
      return earlier;
    }
    MemberLog log;
    Simulation simulation(prm, parameter_file);
    simulation.as_suite_member();
    simulation.when_output_begins(
        [&](RunDirectory &directory)
        {
          directory.replace("input_digests.txt", digests, true);
          log.attach(directory.open("member.log"));
        });
    try
    {
      simulation.run();
    }
    catch (const std::exception &e)
    {
      simulation.record_failure(one_line_message(e));
      throw;
    }
    const std::string status = read_member_summary(dir, r);
    // a member a wheel left its rail in (D2) is a result, not a failure
    r.status = stop_requested()                                ? "interrupted"
               : status == "completed" || status == "derailed" ? status
                                                               : "failed";
    if (r.status == "failed")
      r.error = "summary.json says '" + status + "'";
  }
  catch (const std::exception &e)
  {
    r.status = "failed";
    r.error = one_line_message(e);
    r.values.clear();
  }
  r.wall_time = seconds_since(start);
  if (r.usable())
    r.spectra = file_text(dir + "/spectra.csv");
  return r;
}

void SuiteRunner::check_members() const
{
  // what differs between members is the record and the variation (the
  // scale factor only scales): each value of each variation (the others at
  // their first value) with the first record, each other record with the
  // first variation; linear in the values, not the members
  const unsigned int per_record = suite.scale_factors.size() * suite.n_variations();
  std::vector<unsigned int> checked = {0};
  unsigned int stride = suite.n_variations();
  for (const auto &v : suite.variations)
  {
    stride /= v.values.size();
    for (unsigned int j = 1; j < v.values.size(); ++j)
      checked.push_back(j * stride);
  }
  for (unsigned int r = 1; r < suite.records.size(); ++r)
    checked.push_back(r * per_record);
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  std::pair<unsigned int, std::string> refused(std::numeric_limits<unsigned int>::max(),
                                               "");
  {
    const Silence quiet;
    for (unsigned int i = rank; i < checked.size(); i += n_ranks)
      try
      {
        ParameterHandler prm;
        std::string text;
        member_parameters(members[checked[i]], prm, text);
        Simulation(prm, parameter_file).check();
      }
      catch (const std::exception &e)
      {
        std::string message = one_line_message(e);
        if (message.rfind("Suite: member ", 0) != 0)
          message = "Suite: member " + members[checked[i]].name + ": " + message;
        refused = {checked[i], message};
        break;
      }
  }
  const auto all = Utilities::MPI::all_gather(comm, refused);
  const auto first = std::min_element(all.begin(), all.end());
  if (!first->second.empty())
    throw AgreedError(first->second);
}

void SuiteRunner::take_folder(const bool create)
{
  std::error_code ec;
  if (!out.is_open())
  {
    if (!create && !std::filesystem::is_directory(folder, ec))
      return;
    std::filesystem::create_directories(folder, ec);
    AssertThrow(!ec,
                ExcMessage("Output/Output directory: cannot create the suite's folder " +
                           folder + ": " + ec.message()));
    out = OutputFolder(folder);
    lock = lock_file(out,
                     suite_lock_name,
                     "the suite folder " + folder +
                         " is in use by another hati suite (it holds " +
                         out.path_of(suite_lock_name) +
                         "); wait for it to end or set another Output/Output directory");
  }
  for (const char *name : suite_files)
    out.refuse_link(name);
  for (const auto &m : members)
    refuse_linked_folder(folder + "/" + m.name);
  // the results of an earlier suite here are not this suite's
  if (create)
    for (const char *name : suite_files)
      out.remove_regular_file(name);
}

void SuiteRunner::print_header() const
{
  const unsigned int n = members.size();
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  std::cout << "hati: suite " << parameter_file << ": " << n << " members ("
            << std::max<std::size_t>(suite.records.size(), 1) << " records x "
            << suite.scale_factors.size() << " scale factors x " << suite.n_variations()
            << " variations) on " << n_ranks << (n_ranks == 1 ? " rank" : " ranks")
            << ", statistic " << suite.effective_statistic() << "\n  output: " << folder
            << "/" << std::endl;
}

std::vector<MemberResult>
SuiteRunner::run_members(const std::chrono::steady_clock::time_point start) const
{
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  const unsigned int n = members.size();
  std::vector<MemberResult> mine;
  WorkCounter counter(comm);
  while (!stop_requested())
  {
    const unsigned int k = counter.fetch_and_increment(0);
    if (k >= n)
      break;
    mine.push_back(run_member(members[k]));
    const MemberResult &r = mine.back();
    const unsigned int done = counter.fetch_and_increment(1) + 1;
    const double elapsed = seconds_since(start);
    std::ostringstream line;
    line << "hati: suite: member " << done << "/" << n << " done (" << r.name << ": "
         << r.status << ", " << std::setprecision(3) << r.wall_time << " s";
    if (n_ranks > 1)
      line << ", rank " << rank;
    if (!r.error.empty())
      line << ": " << r.error;
    line << "), ETA " << std::setprecision(3) << elapsed * (n - done) / done << " s";
    std::cout << line.str() << std::endl;
  }
  return mine; // the window is freed: every rank is done
}

int SuiteRunner::run()
{
  const auto start = std::chrono::steady_clock::now();
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n = members.size();
  // a signal before the first member stops the suite as one during a member
  catch_stop_signals();
  std::vector<std::vector<MemberResult>> gathered;
  without_stray_exceptions(comm,
                           [&]
                           {
                             // a second suite in the folder is refused at once, before
                             // the checks
                             agree(
                                 comm, [&] { take_folder(false); }, true);
                             if (rank == 0)
                               print_header();
                             check_members();
                             agree(
                                 comm, [&] { take_folder(true); }, true);
                             agree(
                                 comm, [&] { find_fundamental_period(); }, true);
                             const std::vector<MemberResult> mine = run_members(start);
                             gathered = Utilities::MPI::gather(comm, mine, 0);
                           });
  if (rank != 0)
    return stop_requested() ? 128 + stop_signal() : 0;
  std::vector<MemberResult> results(n);
  for (unsigned int k = 0; k < n; ++k)
  {
    results[k].index = k;
    results[k].name = members[k].name;
    results[k].record = members[k].record;
    results[k].scale = members[k].scale;
    results[k].variation = members[k].variation;
    results[k].variation_values = members[k].variation_values;
  }
  for (const auto &from_rank : gathered)
    for (const auto &r : from_rank)
      results[r.index] = r;
  return finish(results, seconds_since(start));
}

int SuiteRunner::finish(std::vector<MemberResult> &results, const double wall_time) const
{
  std::vector<std::string> paths;
  for (const auto &v : suite.variations)
    paths.push_back(v.path);
  const SuiteStatistics statistics(results, paths, suite.effective_statistic());
  double member_time = 0.;
  std::vector<std::string> failed;
  unsigned int not_run = 0;
  for (const auto &r : results)
  {
    member_time += r.status == "reused" ? 0. : r.wall_time;
    if (r.status == "failed")
      failed.push_back(r.name + ": " + r.error);
    not_run += r.status == "not run" || r.status == "interrupted";
  }
  std::string check_error;
  SummaryEntries extra = {{"wall_time", wall_time},
                          {"sum_member_wall_time", member_time},
                          {"git_commit", hati_git_commit()}};
  if (design_spectrum.active())
    try
    {
      extra.emplace_back("design_spectrum_check", check_design_spectrum());
    }
    catch (const std::exception &e)
    {
      check_error = one_line_message(e);
      // (the check's own messages start with its name)
      const std::string prefix = "design spectrum check: ";
      std::cerr << "hati: error: suite: "
                << (check_error.rfind(prefix, 0) == 0 ? "" : prefix) << check_error
                << std::endl;
    }
  if (design_spectrum.active() && suite.response_spectrum_comparison && !stop_requested())
    compare_with_response_spectrum(statistics, extra);
  // the verdicts of each group's statistic (Q1), each where its governing
  // member (and, with several groups, which group)
  std::vector<QualificationRow> verdicts;
  if (qualification.enabled())
  {
    for (unsigned int g = 0; g < statistics.n_groups(); ++g)
      for (QualificationRow &row :
           qualify(suite_demands(statistics.group_quantities(g)), qualification))
      {
        if (statistics.n_groups() > 1)
          row.where += " (" + statistics.group_name(g) + ")";
        verdicts.push_back(std::move(row));
      }
    // a member a wheel left its rail in fails (D2): its own run's verdict
    for (const auto &r : results)
      if (r.status == "derailed")
      {
        for (QualificationRow &row :
             qualify(run_demands(file_text(folder + "/" + r.name + "/summary.json")),
                     qualification))
          if (row.check == "derailment")
          {
            row.where = "member " + r.name + ": " + row.where;
            verdicts.push_back(std::move(row));
          }
      }
    extra.emplace_back("qualification", qualification_json(verdicts));
    out.replace("qualification.csv", qualification_csv(verdicts), true);
  }
  out.replace("parameters.prm", suite_parameters, true);
  out.replace("suite.csv", statistics.csv(), true);
  out.replace("suite_summary.json", statistics.summary_json(extra), true);
  const std::string spectra = statistics.spectra_csv();
  if (!spectra.empty())
    out.replace("suite_spectra.csv", spectra, true);
  // the ranks' time against the members' (n_ranks x wall time - their sum)
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  std::cout << "hati: suite: " << results.size() << " members in " << wall_time
            << " s on " << n_ranks << (n_ranks == 1 ? " rank" : " ranks") << " (members "
            << member_time << " s, overhead "
            << (member_time > 0.
                    ? 100. * (n_ranks * wall_time - member_time) / member_time
                    : 0.)
            << " % of the ranks' time): " << folder << "/suite.csv, suite_summary.json"
            << (spectra.empty() ? "" : ", suite_spectra.csv") << std::endl;
  if (!stop_requested())
  {
    const std::string warning = run_plot_script("plot_suite.py", folder);
    if (warning.empty())
      std::cout << "  plots: " << folder << "/suite.png"
                << (spectra.empty() ? "" : ", spectra.png") << std::endl;
    else
      std::cerr << "hati: warning: suite: the plots were not drawn: " << warning
                << std::endl;
    if (std::filesystem::is_regular_file(folder + "/rsa_comparison.csv"))
    {
      const std::string rsa_warning = run_plot_script("plot_rsa_comparison.py", folder);
      if (rsa_warning.empty())
        std::cout << "  plot: " << folder << "/rsa_comparison.png" << std::endl;
      else
        std::cerr << "hati: warning: suite: rsa_comparison.png was not drawn: "
                  << rsa_warning << std::endl;
    }
    write_qualification_report(qualification, folder);
  }
  if (qualification.enabled())
    print_qualification(verdicts, std::cout);
  if (stop_requested())
  {
    std::cerr << "hati: suite interrupted by "
              << (stop_signal() == SIGINT ? "SIGINT" : "SIGTERM") << ": " << not_run
              << " of " << results.size()
              << " members not complete; run the suite again to run only those"
              << std::endl;
    return 128 + stop_signal();
  }
  if (!failed.empty())
  {
    std::cerr << "hati: error: suite: " << failed.size() << " of " << results.size()
              << " members failed (" << failed.front()
              << (failed.size() > 1 ? "; ..." : "") << "); the others went on: see "
              << folder << "/suite.csv" << std::endl;
    return 1;
  }
  return check_error.empty() ? 0 : 1;
}
} // namespace hati

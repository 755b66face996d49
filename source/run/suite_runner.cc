#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <hati/output/output_file.h>
#include <hati/output/run_directory.h>
#include <hati/output/suite_statistics.h>
#include <hati/run/simulation.h>
#include <hati/run/suite_runner.h>
#include <hati/run/work_counter.h>

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

extern char **environ;

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

/** std::cout into a file while it lives (a member's terminal output into its member.log).
 */
class RedirectedOutput
{
public:
  explicit RedirectedOutput(const std::string &path)
      : log(create_output_file(path)), old(std::cout.rdbuf(log.rdbuf()))
  {
  }
  ~RedirectedOutput()
  {
    std::cout.rdbuf(old);
    try
    {
      log.close();
    }
    catch (...)
    {
    }
  }

private:
  OutputStream log;
  std::streambuf *old;
};

/**
 * Run `python3 scripts/plot_suite.py <folder>` (the script next to the
 * executable's build folder, else in the current directory), its output in
 * <folder>/plot_suite.log; the warning if it could not draw, empty if it did.
 */
std::string draw_plots(const std::string &folder)
{
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  std::string script = "scripts/plot_suite.py";
  if (!error && std::filesystem::exists(exe.parent_path().parent_path() / script))
    script = (exe.parent_path().parent_path() / script).string();
  const std::string log = folder + "/plot_suite.log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(
      &actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  // the system's python3 (Debian's python3-matplotlib, scripts/setup.sh) before
  // another one on the PATH, as run.sh
  std::string python =
      std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  char *argv[] = {
      python.data(), script.data(), const_cast<char *>(folder.c_str()), nullptr};
  pid_t pid = 0;
  const int spawned =
      posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  // posix_spawn reports the failed open of the log (O_NOFOLLOW) as its error
  if (spawned == ELOOP)
    return log + " is a symbolic link: refused (an output file is never written through "
                 "a link; remove the link)";
  if (spawned != 0)
    return (spawned == ENOENT
                ? "python3 was not found ("
                : "cannot start " + python + " with its log " + log + " (") +
           system_error_text(spawned) + ")";
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
    ;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
    return "";
  const std::string text = file_text(log);
  const auto last = text.find_last_not_of('\n');
  const auto line = text.rfind('\n', last);
  return python + " " + script + " failed (" +
         (last == std::string::npos
              ? std::string("no output")
              : text.substr(line == std::string::npos ? 0 : line + 1,
                            last - (line == std::string::npos ? 0 : line + 1) + 1)) +
         ")";
}
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
  if (folder.empty())
    folder = "output/" + std::filesystem::path(parameter_file).stem().string();
  check_output_directory(folder);
  members = plan_suite(
      suite,
      folder,
      prm.get_double(std::vector<std::string>{"Loading"}, "Accelerogram scale factor"));
  // every member's parameters apply (a bad variation is refused before any run)
  for (const auto &m : members)
  {
    ParameterHandler member_prm;
    std::string text;
    member_parameters(m, member_prm, text);
  }
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
    ParameterHandler prm;
    std::string text;
    member_parameters(member, prm, text);
    MemberResult earlier = r;
    if (file_text(dir + "/parameters.prm") == text &&
        read_member_summary(dir, earlier) == "completed")
    {
      earlier.status = "reused";
      earlier.spectra = file_text(dir + "/spectra.csv");
      return earlier;
    }
    std::filesystem::create_directories(dir);
    const RedirectedOutput log(dir + "/member.log");
    Simulation simulation(prm, parameter_file);
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
    r.status = stop_requested()        ? "interrupted"
               : status == "completed" ? status
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

int SuiteRunner::run()
{
  const auto start = std::chrono::steady_clock::now();
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  const unsigned int n = members.size();
  if (rank == 0)
  {
    std::filesystem::create_directories(folder);
    std::cout << "hati: suite " << parameter_file << ": " << n << " members ("
              << std::max<std::size_t>(suite.records.size(), 1) << " records x "
              << suite.scale_factors.size() << " scale factors x "
              << n / std::max<std::size_t>(suite.records.size(), 1) /
                     suite.scale_factors.size()
              << " variations) on " << n_ranks << (n_ranks == 1 ? " rank" : " ranks")
              << ", statistic " << suite.effective_statistic() << "\n  output: " << folder
              << "/" << std::endl;
  }
  std::vector<MemberResult> mine;
  {
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
  } // the window is freed: every rank is done
  const auto gathered = Utilities::MPI::gather(comm, mine, 0);
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
  const OutputFolder out(folder);
  out.replace("suite.csv", statistics.csv(), true);
  out.replace("suite_summary.json",
              statistics.summary_json(
                  {{"wall_time", wall_time}, {"sum_member_wall_time", member_time}}),
              true);
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
    const std::string warning = draw_plots(folder);
    if (warning.empty())
      std::cout << "  plots: " << folder << "/suite.png"
                << (spectra.empty() ? "" : ", spectra.png") << std::endl;
    else
      std::cerr << "hati: warning: suite: the plots were not drawn: " << warning
                << std::endl;
  }
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
  return 0;
}
} // namespace hati

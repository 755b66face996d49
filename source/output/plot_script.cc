#include <hati/output/output_file.h>
#include <hati/output/plot_script.h>
#include <hati/output/run_directory.h>

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>

extern char **environ;

namespace hati
{
namespace
{
/** The whole text of @p path, empty if it cannot be read. */
std::string file_text(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  if (in)
    s << in.rdbuf();
  return s.str();
}
} // namespace

std::string run_plot_script(const std::string &name, const std::string &folder)
{
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  std::string script = "scripts/" + name;
  if (!error && std::filesystem::exists(exe.parent_path().parent_path() / script))
    script = (exe.parent_path().parent_path() / script).string();
  const std::string log =
      folder + "/" + std::filesystem::path(name).stem().string() + ".log";
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
} // namespace hati

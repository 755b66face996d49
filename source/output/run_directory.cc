#include <deal.II/base/exceptions.h>

#include <hati/output/run_directory.h>
#include <hati/output/summary.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <sstream>
#include <sys/file.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace hati
{
using namespace dealii;

namespace
{
volatile std::sig_atomic_t stop_signal_number = 0;

extern "C" void on_stop_signal(int signal)
{
  if (stop_signal_number != 0)
  {
    // a second Ctrl-C: stop at once
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  stop_signal_number = signal;
}

} // namespace

void catch_stop_signals()
{
  struct sigaction action = {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

namespace
{

const char *const lock_name = ".hati.lock";
const char *const manifest_name = ".hati-manifest";

/** The lines of the manifest of the previous run in @p folder (none if there is none). */
std::vector<std::string> previous_manifest(const OutputFolder &folder)
{
  const OutputFile file = folder.open_existing(manifest_name);
  std::string text;
  char block[4096];
  ssize_t n = 0;
  while (file.fd >= 0 &&
         ((n = ::read(file.fd, block, sizeof(block))) > 0 || (n < 0 && errno == EINTR)))
    if (n > 0)
      text.append(block, n);
  std::vector<std::string> names;
  std::istringstream lines(text);
  for (std::string name; std::getline(lines, name);)
    names.push_back(name);
  return names;
}
} // namespace

std::string system_error_text(const int error)
{
  return std::generic_category().message(error);
}

bool stop_requested() { return stop_signal_number != 0; }

int stop_signal() { return stop_signal_number; }

void ignore_broken_pipes() { std::signal(SIGPIPE, SIG_IGN); }

void check_output_directory(const std::string &path)
{
  std::error_code ec;
  // the folder as it would be reached (symbolic links and .. resolved as far
  // as the path exists)
  const std::filesystem::path folder =
      std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  const std::string where =
      "Output/Output directory = '" + path + "' (" + folder.string() + "): ";
  AssertThrow(!ec && !folder.empty(),
              ExcMessage(where + "cannot be resolved: " + ec.message()));
  AssertThrow(folder != folder.root_path(),
              ExcMessage(where + "the root folder; give a folder of your own"));
  const std::string top = (*std::next(folder.begin())).string(); // after "/"
  const bool system_tree = top == "etc" || top == "usr" || top == "bin" ||
                           top == "sbin" || top == "boot" || top == "dev" ||
                           top == "proc" || top == "sys" || top.rfind("lib", 0) == 0;
  const bool system_folder = folder == folder.root_path() / "var";
  AssertThrow(!system_tree && !system_folder,
              ExcMessage(where + "a system folder (/etc, /usr, /bin, /sbin, /boot, /dev, "
                                 "/proc, /sys, /lib*, or /var itself); give a folder of "
                                 "your own"));
}

OutputFile
lock_file(const OutputFolder &folder, const std::string &name, const std::string &in_use)
{
  const std::string path = folder.path_of(name);
  const int fd = ::openat(
      folder.descriptor(), name.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0 && errno == ELOOP)
    folder.refuse_link(name);
  AssertThrow(fd >= 0,
              ExcMessage("cannot create the lock file " + path + ": " +
                         system_error_text(errno)));
  OutputFile held(fd, path);
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno != ENOLCK && errno != EOPNOTSUPP)
  {
    // (a file system without locks, ENOLCK/EOPNOTSUPP: run without the lock)
    const int error = errno;
    AssertThrow(false,
                ExcMessage(error == EWOULDBLOCK ? in_use
                                                : "cannot lock " + path + ": " +
                                                      system_error_text(error)));
  }
  return held;
}

RunDirectory::RunDirectory(const std::string &path, const std::string &parameters)
    : dir(path), parameters(parameters)
{
  check_output_directory(path);
}

RunDirectory::~RunDirectory() = default; // closes the lock: releases the flock

void RunDirectory::begin()
{
  if (begun())
    return;
  if (dry_run)
    throw DryRunEnd();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  AssertThrow(
      !ec, ExcMessage("cannot create the output directory " + dir + ": " + ec.message()));
  // every file from here on is opened relative to this descriptor
  folder = OutputFolder(dir);
  lock = lock_file(folder,
                   lock_name,
                   "the output directory " + dir +
                       " is in use by another hati run (it holds " +
                       folder.path_of(lock_name) +
                       "); wait for it to end or set another Output/Output directory");

  // delete exactly the files the previous run listed and their temporaries
  // (a run killed while it replaced one leaves `.<name>.tmp`), nothing else
  for (const std::string &name : previous_manifest(folder))
    if (!name.empty() && name != "." && name != ".." &&
        name.find('/') == std::string::npos && name != lock_name && name != manifest_name)
    {
      folder.remove_regular_file(name);
      folder.remove_regular_file(temporary_name(name));
    }
  // a state file's temporary whatever the manifest says (a run killed while
  // its manifest line was being written)
  folder.remove_regular_file(temporary_name("state.bin"));
  manifest = folder.create(manifest_name, O_APPEND);

  replace("parameters.prm", parameters, true);
  replace("summary.json", "{\n  \"status\": \"running\"\n}\n", true);
  catch_stop_signals();
  if (after_begin)
    after_begin(*this);
}

std::string RunDirectory::create(const std::string &name)
{
  Assert(begun(), ExcInternalError());
  if (registered.insert(name).second)
  {
    const std::string line = name + '\n';
    AssertThrow(
        write_all(manifest.fd, line.data(), line.size()),
        ExcMessage("cannot write " + manifest.path + ": " + system_error_text(errno)));
  }
  return folder.path_of(name);
}

OutputFile RunDirectory::open(const std::string &name, const int flags)
{
  create(name);
  return folder.create(name, flags);
}

void RunDirectory::replace(const std::string &name,
                           const std::string &content,
                           const bool durable)
{
  create(temporary_name(name));
  create(name);
  folder.replace(name, content, durable);
}

void RunDirectory::sync(const std::string &name) const { folder.sync(name); }

void RunDirectory::fail(const std::string &message,
                        const std::vector<std::string> &warnings) noexcept
{
  if (!begun())
    return;
  const std::string content = failed_summary(message, warnings);
  try
  {
    folder.replace("summary.json", content, true);
  }
  catch (...)
  {
    // no room for the temporary file (a full disk): the old summary.json
    // has its block already; the message is printed on stderr anyway
    folder.overwrite("summary.json", content);
  }
}
} // namespace hati

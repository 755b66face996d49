#include <deal.II/base/exceptions.h>

#include <hati/output/run_directory.h>
#include <hati/output/summary.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/file.h>
#include <system_error>
#include <unistd.h>

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

void install_stop_handlers()
{
  struct sigaction action = {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

/** Write all of @p size bytes at @p data to @p fd; false (errno set) if that fails. */
bool write_all(const int fd, const char *data, std::size_t size)
{
  while (size > 0)
  {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
    {
      if (n == 0)
        errno = ENOSPC;
      return false;
    }
    data += n;
    size -= n;
  }
  return true;
}

/**
 * Make the rename of a file in the directory of @p filename durable: fsync
 * the directory, best effort (a directory that cannot be opened or synced
 * is ignored; the file itself is complete either way).
 */
void sync_directory_of(const std::string &filename)
{
  std::string directory = std::filesystem::path(filename).parent_path().string();
  if (directory.empty())
    directory = ".";
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
    return;
  ::fsync(fd);
  ::close(fd);
}

const char *const lock_name = ".hati.lock";
const char *const manifest_name = ".hati-manifest";
} // namespace

std::string system_error_text(const int error)
{
  return std::generic_category().message(error);
}

bool stop_requested() { return stop_signal_number != 0; }

int stop_signal() { return stop_signal_number; }

void ignore_broken_pipes() { std::signal(SIGPIPE, SIG_IGN); }

std::string one_line_message(const std::exception &e)
{
  std::string text;
  if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
  {
    std::ostringstream s;
    d->print_info(s);
    text = s.str();
  }
  else
    text = e.what();
  std::string r;
  bool space = false;
  for (const char c : text)
  {
    if (std::isspace(static_cast<unsigned char>(c)))
      space = !r.empty();
    else
    {
      if (space)
        r += ' ';
      r += c;
      space = false;
    }
  }
  const std::string prefix = "Additional information: ";
  if (r.compare(0, prefix.size(), prefix) == 0)
    r = r.substr(prefix.size());
  return r;
}

std::string temporary_name(const std::string &name)
{
  const std::filesystem::path p(name);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp")).string();
}

void write_file_atomically(const std::string &filename,
                           const std::string &content,
                           const bool durable)
{
  const std::string temporary = temporary_name(filename);
  const int fd =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  AssertThrow(fd >= 0,
              ExcMessage("cannot write the output file " + filename + ": " +
                         system_error_text(errno)));
  // the content reaches the disk before the rename makes it the file: after
  // a power failure the name holds the old or the new content, never an
  // empty file (EINVAL: a file system without fsync)
  const bool written = write_all(fd, content.data(), content.size()) &&
                       (!durable || ::fsync(fd) == 0 || errno == EINVAL);
  const int error = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed || std::rename(temporary.c_str(), filename.c_str()) != 0)
  {
    const int e = !written ? error : errno;
    ::unlink(temporary.c_str());
    AssertThrow(false,
                ExcMessage("cannot write the output file " + filename + ": " +
                           system_error_text(e)));
  }
  if (durable)
    sync_directory_of(filename);
}

void sync_file(const std::string &filename)
{
  const int fd = ::open(filename.c_str(), O_RDONLY | O_CLOEXEC);
  const bool synced = fd >= 0 && (::fsync(fd) == 0 || errno == EINVAL);
  const int error = errno;
  if (fd >= 0)
    ::close(fd);
  AssertThrow(synced,
              ExcMessage("cannot write the output file " + filename + ": " +
                         system_error_text(error)));
  sync_directory_of(filename);
}

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

RunDirectory::RunDirectory(const std::string &path, const std::string &parameters)
    : dir(path), parameters(parameters)
{
  check_output_directory(path);
}

RunDirectory::~RunDirectory()
{
  if (manifest_fd >= 0)
    ::close(manifest_fd);
  if (lock_fd >= 0)
    ::close(lock_fd); // releases the flock
}

void RunDirectory::begin()
{
  if (begun())
    return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  AssertThrow(
      !ec, ExcMessage("cannot create the output directory " + dir + ": " + ec.message()));
  const std::string lock_path = dir + "/" + lock_name;
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  AssertThrow(fd >= 0,
              ExcMessage("cannot create the lock file " + lock_path + ": " +
                         system_error_text(errno)));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno != ENOLCK && errno != EOPNOTSUPP)
  {
    // (a file system without locks, ENOLCK/EOPNOTSUPP: run without the lock)
    const int error = errno;
    ::close(fd);
    AssertThrow(
        false,
        ExcMessage(error == EWOULDBLOCK
                       ? "the output directory " + dir +
                             " is in use by another hati run (it holds " + lock_path +
                             "); wait for it to end or set another "
                             "Output/Output directory"
                       : "cannot lock " + lock_path + ": " + system_error_text(error)));
  }
  lock_fd = fd;

  // delete exactly the files the previous run listed, nothing else
  const std::string manifest = dir + "/" + manifest_name;
  {
    std::ifstream previous(manifest);
    std::string name;
    while (std::getline(previous, name))
    {
      if (name.empty() || name == "." || name == ".." ||
          name.find('/') != std::string::npos || name == lock_name ||
          name == manifest_name)
        continue;
      const std::string file = dir + "/" + name;
      if (std::filesystem::is_regular_file(std::filesystem::symlink_status(file, ec)))
        AssertThrow(std::filesystem::remove(file, ec) || !ec,
                    ExcMessage("cannot delete " + file +
                               " (a file of the previous run): " + ec.message()));
    }
  }
  manifest_fd =
      ::open(manifest.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  AssertThrow(manifest_fd >= 0,
              ExcMessage("cannot write " + manifest + ": " + system_error_text(errno)));

  for (const std::string name : {"parameters.prm", "summary.json"})
    create(temporary_name(name));
  write_file_atomically(create("parameters.prm"), parameters);
  write_file_atomically(create("summary.json"), "{\n  \"status\": \"running\"\n}\n");
  install_stop_handlers();
}

std::string RunDirectory::create(const std::string &name)
{
  Assert(begun(), ExcInternalError());
  if (registered.insert(name).second)
  {
    const std::string line = name + '\n';
    AssertThrow(write_all(manifest_fd, line.data(), line.size()),
                ExcMessage("cannot write " + dir + "/" + manifest_name + ": " +
                           system_error_text(errno)));
  }
  return dir + "/" + name;
}

void RunDirectory::fail(const std::string &message,
                        const std::vector<std::string> &warnings) noexcept
{
  if (!begun())
    return;
  try
  {
    write_file_atomically(dir + "/summary.json", failed_summary(message, warnings));
  }
  catch (...)
  {
    // the message is printed on stderr anyway
  }
}
} // namespace hati

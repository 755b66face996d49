#include <deal.II/base/exceptions.h>

#include <hati/output/output_file.h>
#include <hati/output/run_directory.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <memory>
#include <pthread.h>
#include <sched.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>

namespace hati
{
using namespace dealii;

namespace
{
[[noreturn]] void throw_cannot_write(const std::string &path, const int error)
{
  AssertThrow(false,
              ExcMessage("cannot write the output file " + path + ": " +
                         system_error_text(error)));
  std::abort(); // not reached
}

[[noreturn]] void throw_link(const std::string &path)
{
  AssertThrow(false,
              ExcMessage(path + " is a symbolic link: refused (an output file is never "
                                "written through a link; remove the link)"));
  std::abort(); // not reached
}

bool is_link(const int folder, const std::string &name)
{
  struct stat s;
  return ::fstatat(folder, name.c_str(), &s, AT_SYMLINK_NOFOLLOW) == 0 &&
         S_ISLNK(s.st_mode);
}

/** fsync the folder @p fd, best effort (makes a rename in it durable). */
void sync_folder(const int fd) { ::fsync(fd); }

/** The folder and the name of the path @p filename. */
std::pair<std::string, std::string> split_path(const std::string &filename)
{
  const std::filesystem::path p(filename);
  std::string folder = p.parent_path().string();
  return {folder.empty() ? std::string(".") : folder, p.filename().string()};
}

/**
 * The folder of the path @p filename, opened; a folder that cannot be
 * opened is reported naming the file.
 */
OutputFolder folder_of(const std::string &filename)
{
  const std::string folder = split_path(filename).first;
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
    throw_cannot_write(filename, errno);
  ::close(fd);
  return OutputFolder(folder);
}

/** One append of whole rows, done by the child of append_whole_rows(). */
struct RowsWrite
{
  int fd;
  off_t start;
  const char *data;
  std::size_t size;
  std::size_t written;
  int error;
};

/**
 * Write what is left of @p w; after a failed write cut the file back to
 * the last whole row written. Only system calls: also runs in the child.
 */
void write_rows(RowsWrite &w)
{
  while (w.written < w.size && w.error == 0)
  {
    const ssize_t n = ::write(w.fd, w.data + w.written, w.size - w.written);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      w.error = n < 0 ? errno : ENOSPC;
    else
      w.written += n;
  }
  if (w.error != 0 && w.start >= 0)
  {
    std::size_t keep = w.written;
    while (keep > 0 && w.data[keep - 1] != '\n')
      --keep;
    if (keep < w.written && ::ftruncate(w.fd, w.start + keep) == 0 &&
        ::lseek(w.fd, w.start + keep, SEEK_SET) >= 0)
      w.written = keep;
  }
}

extern "C" int rows_child(void *argument)
{
  // out of the run's process group and session first: a kill of the group
  // (a job scheduler's or a terminal's, `kill -9 -<pgid>`) then no longer
  // reaches the child, which finishes the append; a kill that comes before
  // this finds nothing written yet
  ::setsid();
  write_rows(*static_cast<RowsWrite *>(argument));
  return 0;
}
} // namespace

// --- OutputFile ---

OutputFile::~OutputFile()
{
  if (fd >= 0)
    ::close(fd);
}

OutputFile::OutputFile(OutputFile &&other) noexcept
    : fd(other.release()), path(std::move(other.path))
{
}

OutputFile &OutputFile::operator=(OutputFile &&other) noexcept
{
  if (this != &other)
  {
    if (fd >= 0)
      ::close(fd);
    fd = other.release();
    path = std::move(other.path);
  }
  return *this;
}

int OutputFile::release() { return std::exchange(fd, -1); }

// --- OutputFolder ---

OutputFolder::OutputFolder(const std::string &path)
    : fd(::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)), dir(path)
{
  AssertThrow(fd >= 0,
              ExcMessage("cannot open the output directory " + path + ": " +
                         system_error_text(errno)));
}

OutputFolder::~OutputFolder()
{
  if (fd >= 0)
    ::close(fd);
}

OutputFolder::OutputFolder(OutputFolder &&other) noexcept
    : fd(std::exchange(other.fd, -1)), dir(std::move(other.dir))
{
}

OutputFolder &OutputFolder::operator=(OutputFolder &&other) noexcept
{
  if (this != &other)
  {
    if (fd >= 0)
      ::close(fd);
    fd = std::exchange(other.fd, -1);
    dir = std::move(other.dir);
  }
  return *this;
}

std::string OutputFolder::path_of(const std::string &name) const
{
  return dir + "/" + name;
}

void OutputFolder::refuse_link(const std::string &name) const
{
  if (is_link(fd, name))
    throw_link(path_of(name));
}

OutputFile OutputFolder::create(const std::string &name, const int flags) const
{
  // O_NONBLOCK: a FIFO without a reader fails (ENXIO) instead of blocking
  const int file =
      ::openat(fd,
               name.c_str(),
               O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | flags,
               0644);
  if (file < 0 && errno == ELOOP)
    throw_link(path_of(name));
  if (file < 0)
    throw_cannot_write(path_of(name), errno);
  ::fcntl(file, F_SETFL, ::fcntl(file, F_GETFL) & ~O_NONBLOCK);
  return OutputFile(file, path_of(name));
}

OutputFile OutputFolder::open_existing(const std::string &name) const
{
  const int file = ::openat(fd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (file < 0 && errno == ELOOP)
    throw_link(path_of(name));
  AssertThrow(
      file >= 0 || errno == ENOENT,
      ExcMessage("cannot read " + path_of(name) + ": " + system_error_text(errno)));
  return OutputFile(file, path_of(name));
}

void OutputFolder::replace(const std::string &name,
                           const std::string &content,
                           const bool durable) const
{
  refuse_link(name);
  const std::string temporary = temporary_name(name);
  const auto open_temporary = [&]()
  {
    return ::openat(fd,
                    temporary.c_str(),
                    O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                    0644);
  };
  int file = open_temporary();
  if (file < 0 && errno == EEXIST)
  {
    // a temporary left by a killed run (never a link: refused)
    refuse_link(temporary);
    if (::unlinkat(fd, temporary.c_str(), 0) == 0)
      file = open_temporary();
  }
  if (file < 0)
    throw_cannot_write(path_of(name), errno);
  // the content reaches the disk before the rename makes it the file: after
  // a power failure the name holds the old or the new content, never an
  // empty file (EINVAL: a file system without fsync)
  const bool written = write_all(file, content.data(), content.size()) &&
                       (!durable || ::fsync(file) == 0 || errno == EINVAL);
  const int error = errno;
  const bool closed = ::close(file) == 0;
  if (!written || !closed || ::renameat(fd, temporary.c_str(), fd, name.c_str()) != 0)
  {
    const int e = !written ? error : errno;
    ::unlinkat(fd, temporary.c_str(), 0);
    throw_cannot_write(path_of(name), e);
  }
  if (durable)
    sync_folder(fd);
}

bool OutputFolder::overwrite(const std::string &name,
                             const std::string &content) const noexcept
{
  const int file = ::openat(fd, name.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC);
  if (file < 0)
    return false;
  struct stat s;
  const bool done = ::fstat(file, &s) == 0 && S_ISREG(s.st_mode) &&
                    write_all(file, content.data(), content.size()) &&
                    ::ftruncate(file, content.size()) == 0;
  ::fsync(file);
  return ::close(file) == 0 && done;
}

void OutputFolder::sync(const std::string &name) const
{
  const int file = ::openat(fd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  const bool synced = file >= 0 && (::fsync(file) == 0 || errno == EINVAL);
  const int error = errno;
  if (file >= 0)
    ::close(file);
  if (!synced && error == ELOOP)
    throw_link(path_of(name));
  if (!synced)
    throw_cannot_write(path_of(name), error);
  sync_folder(fd);
}

void OutputFolder::remove_regular_file(const std::string &name) const
{
  struct stat s;
  if (::fstatat(fd, name.c_str(), &s, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(s.st_mode))
    return;
  AssertThrow(::unlinkat(fd, name.c_str(), 0) == 0 || errno == ENOENT,
              ExcMessage("cannot delete " + path_of(name) +
                         " (a file of the previous run): " + system_error_text(errno)));
}

// --- path-based helpers ---

OutputFile create_output_file(const std::string &filename)
{
  return folder_of(filename).create(split_path(filename).second);
}

std::string temporary_name(const std::string &name)
{
  const std::filesystem::path p(name);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp")).string();
}

void refuse_linked_folder(const std::string &path)
{
  struct stat status;
  AssertThrow(::lstat(path.c_str(), &status) != 0 || !S_ISLNK(status.st_mode),
              ExcMessage(path + " is a symbolic link: refused (a folder hati creates is "
                                "never followed; remove the link)"));
}

void write_file_atomically(const std::string &filename,
                           const std::string &content,
                           const bool durable)
{
  folder_of(filename).replace(split_path(filename).second, content, durable);
}

void sync_file(const std::string &filename)
{
  folder_of(filename).sync(split_path(filename).second);
}

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

int append_whole_rows(const int fd, const char *data, const std::size_t size)
{
  RowsWrite w{fd, ::lseek(fd, 0, SEEK_CUR), data, size, 0, 0};
  if (w.start >= 0 && w.start % 4096 + size <= 4096)
  {
    // within one page of the file: Linux copies it in one step, after the
    // check for a kill (a write is cut only between two pages), so no
    // child is needed (most appends of a run with frequent snapshots)
    write_rows(w);
    return w.error;
  }
  // the child inherits the blocked signals: only SIGKILL stops it; signals
  // that arrive meanwhile reach this thread when the mask is restored
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
  constexpr std::size_t stack_size = 1 << 16;
  const std::unique_ptr<char[]> stack(new (std::nothrow) char[stack_size]);
  // CLONE_VFORK: this thread waits until the child has exited
  const pid_t child = stack ? ::clone(rows_child,
                                      stack.get() + stack_size,
                                      CLONE_VM | CLONE_VFORK | SIGCHLD,
                                      &w)
                            : -1;
  if (child > 0)
    while (::waitpid(child, nullptr, 0) < 0 && errno == EINTR)
    {
    }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (child > 0 && w.error == 0 && w.written < size && w.start >= 0)
  {
    // a child killed on its own: what it wrote is where the shared file
    // offset is (a write() cut by the kill was not counted)
    const off_t end = ::lseek(fd, 0, SEEK_CUR);
    if (end >= w.start)
      w.written = std::min<std::size_t>(size, end - w.start);
  }
  // no child (a process limit), or a child killed on its own: write the rest here
  write_rows(w);
  return w.error;
}

// --- OutputStream ---

OutputStream::Buffer::Buffer(const int fd) : fd(fd), data(1 << 16)
{
  setp(data.data(), data.data() + data.size());
}

bool OutputStream::Buffer::write_buffered()
{
  if (error == 0 && !write_all(fd, pbase(), pptr() - pbase()))
    error = errno;
  setp(data.data(), data.data() + data.size());
  return error == 0;
}

OutputStream::Buffer::int_type OutputStream::Buffer::overflow(int_type c)
{
  if (!write_buffered())
    return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof()))
  {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int OutputStream::Buffer::sync() { return write_buffered() ? 0 : -1; }

OutputStream::OutputStream(OutputFile f)
    : std::ostream(nullptr), file(std::move(f)), buffer(file.fd)
{
  rdbuf(&buffer);
}

OutputStream::~OutputStream() = default;

void OutputStream::close()
{
  if (file.fd < 0)
    return;
  const bool written = buffer.write_buffered();
  const int error = buffer.error;
  const int fd = file.release();
  const bool closed = ::close(fd) == 0;
  if (!written)
    throw_cannot_write(file.path, error);
  if (!closed)
    throw_cannot_write(file.path, errno);
}
} // namespace hati

#ifndef hati_output_output_file_h
#define hati_output_output_file_h

#include <cstddef>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace hati
{
/**
 * An output file open for writing: its descriptor (owned, closed by the
 * destructor) and its path (for the messages).
 */
class OutputFile
{
public:
  OutputFile() = default;
  OutputFile(const int fd, const std::string &path) : fd(fd), path(path) {}
  ~OutputFile();
  OutputFile(OutputFile &&other) noexcept;
  OutputFile &operator=(OutputFile &&other) noexcept;
  OutputFile(const OutputFile &) = delete;
  OutputFile &operator=(const OutputFile &) = delete;

  /** Give the descriptor up (the caller closes it). */
  int release();

  int fd = -1;
  std::string path;
};

/**
 * A folder that output files are written into, held open (a directory
 * descriptor): every file is opened relative to it (`openat`), so a folder
 * renamed or replaced during the run does not redirect the writes, and no
 * output file is ever opened through a symbolic link (`O_NOFOLLOW`): a link
 * where a file would go is refused with the one-line message
 * `<path> is a symbolic link: refused (an output file is never written
 * through a link; remove the link)`. The folder itself may be a link.
 */
class OutputFolder
{
public:
  OutputFolder() = default;
  /** Open the folder @p path; throws naming it if that fails. */
  explicit OutputFolder(const std::string &path);
  ~OutputFolder();
  OutputFolder(OutputFolder &&other) noexcept;
  OutputFolder &operator=(OutputFolder &&other) noexcept;
  OutputFolder(const OutputFolder &) = delete;
  OutputFolder &operator=(const OutputFolder &) = delete;

  bool is_open() const { return fd >= 0; }
  const std::string &path() const { return dir; }
  /** `folder/name`, for the messages. */
  std::string path_of(const std::string &name) const;

  /**
   * Create or truncate the file @p name (no `/`) for writing, never through
   * a symbolic link (`O_NOFOLLOW`) nor blocking on a FIFO; @p flags are
   * added to the open flags (e.g. `O_APPEND`). Throws a one-line message
   * naming the file.
   */
  OutputFile create(const std::string &name, const int flags = 0) const;

  /**
   * Open the existing file @p name for reading, not through a link; an
   * empty OutputFile (fd < 0) if there is no such file.
   */
  OutputFile open_existing(const std::string &name) const;

  /**
   * Replace @p name by a file holding @p content atomically: the content
   * goes to the temporary `.<name>.tmp`, created exclusively (`O_EXCL`; a
   * stale temporary is removed first, a link there is refused), and is
   * then renamed (`renameat`) over @p name, which must not be a link. If
   * @p durable, the temporary is fsync'ed before the rename and the folder
   * after it. Throws a one-line message naming the file and the system
   * error.
   */
  void
  replace(const std::string &name, const std::string &content, const bool durable) const;

  /**
   * Overwrite the existing file @p name in place with @p content (written
   * from its start, then cut to its length), without creating anything:
   * for `summary.json` when a full disk has no room for the temporary of
   * replace(). Returns false if that fails.
   */
  bool overwrite(const std::string &name, const std::string &content) const noexcept;

  /** fsync @p name, then the folder (best effort); throws naming the file. */
  void sync(const std::string &name) const;

  /** Throw the one-line message of the class if @p name is a symbolic link. */
  void refuse_link(const std::string &name) const;

  /** Remove @p name if it is a regular file (not through a link). */
  void remove_regular_file(const std::string &name) const;

  /** The descriptor of the folder. */
  int descriptor() const { return fd; }

private:
  int fd = -1;
  std::string dir;
};

/**
 * Open the output file @p filename (a path) as OutputFolder::create() does,
 * in the folder of the path.
 */
OutputFile create_output_file(const std::string &filename);

/**
 * Replace @p filename by a file holding @p content atomically, in the
 * folder of the path, as OutputFolder::replace() does: a reader or a run
 * killed at any instant sees the old or the new file, never a part. If
 * @p durable, the temporary file is fsync'ed before the rename and the
 * directory after it (best effort), so that a power failure too leaves the
 * old or the new file (about 1 ms per call on ext4, more when the disk is
 * busy: a file replaced often makes only some replacements durable and the
 * last one with sync_file()). Throws a one-line message naming the file and
 * the system error.
 */
void write_file_atomically(const std::string &filename,
                           const std::string &content,
                           const bool durable = true);

/**
 * Make @p filename durable as write_file_atomically() with `durable` does:
 * fsync the file, then its directory (best effort). Throws a one-line
 * message naming the file and the system error if the file cannot be
 * synced.
 */
void sync_file(const std::string &filename);

/** The name of the temporary file of write_file_atomically() for @p name. */
std::string temporary_name(const std::string &name);

/**
 * Throw the one-line refusal `<path> is a symbolic link: refused (...)` if
 * @p path, a folder hati creates inside an output folder (a suite member's,
 * `modal/`, `records/`), is a symbolic link: its target is never written.
 */
void refuse_linked_folder(const std::string &path);

/** Write all of @p size bytes at @p data to @p fd; false (errno set) if that fails. */
bool write_all(const int fd, const char *data, std::size_t size);

/**
 * Append @p size bytes of whole rows (@p data ends with a newline) to the
 * file @p fd, so that the file ends on a whole row whatever happens:
 *
 * - Linux copies a buffered `write()` to a regular file one page (folio)
 *   at a time and checks for a fatal signal before each: a process killed
 *   during a `write()` of several pages leaves the pages copied so far, a
 *   line cut at a 4 KiB boundary (measured: 7 % of `kill -9` during a run
 *   writing 50 MB/s), while a `write()` within one page of the file is
 *   done whole or not at all. So an append that lies within one 4 KiB page
 *   of the file is written by the run itself (most appends of a run with
 *   frequent snapshots).
 * - A longer append is written by a short-lived child process sharing the
 *   memory (`clone` with `CLONE_VM | CLONE_VFORK`, all signals blocked),
 *   which first leaves the run's process group and session (`setsid`):
 *   a SIGKILL of the run or of its whole process group (a job scheduler's
 *   hard kill, `kill -9 -<pgid>`) then does not reach it, and it finishes
 *   the append (a group kill before its `setsid` finds nothing written).
 *   The child holds the run's descriptors, the lock of RunDirectory too,
 *   until it is done. If no child can be started, the run writes itself.
 *   A kill that also reaches the child (a kill of every process of a
 *   control group or of the machine, the OOM killer, which kills every
 *   process sharing the memory) can still cut the last line of such an
 *   append at a 4 KiB boundary: no append of several pages can be made
 *   atomic with `write()`.
 * - A write that fails (e.g. a full disk) after a part was written is cut
 *   back to the last whole row (`ftruncate`).
 *
 * Returns 0, or the errno of the failed write.
 */
int append_whole_rows(const int fd, const char *data, const std::size_t size);

/**
 * A `std::ostream` into an OutputFile (VTU files): buffered, every write
 * checked; close() throws a one-line message naming the file and the
 * system error if any write failed.
 */
class OutputStream : public std::ostream
{
public:
  explicit OutputStream(OutputFile file);
  ~OutputStream() override;

  /** Flush and close; throws naming the file if a write or the close failed. */
  void close();

private:
  class Buffer : public std::streambuf
  {
  public:
    explicit Buffer(const int fd);
    /** Write the buffered bytes; false once a write failed (errno in error). */
    bool write_buffered();
    int fd;
    int error = 0;

  protected:
    int_type overflow(int_type c) override;
    int sync() override;

  private:
    std::vector<char> data;
  };

  OutputFile file;
  Buffer buffer;
};
} // namespace hati

#endif

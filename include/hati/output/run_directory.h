#ifndef hati_output_run_directory_h
#define hati_output_run_directory_h

#include <exception>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
/**
 * The output directory of one run (doc/user_guide.md, section 6):
 * nothing in it is touched until begin(), which the analyses call once the
 * model is built, every input file read and the time step checked. begin()
 *
 * - creates the directory and takes an exclusive `flock` on its
 *   `.hati.lock` (a second run into the same directory is refused),
 * - deletes exactly the files listed in the manifest `.hati-manifest` of the
 *   previous run there (a user's file is never deleted),
 * - writes `parameters.prm` and `summary.json` with `"status": "running"`,
 * - installs the SIGINT/SIGTERM handlers of stop_requested().
 *
 * Every file of the run is listed in the manifest (create()) before it is
 * opened, so that a killed run is cleaned up by the next one as well.
 */
class RunDirectory
{
public:
  /**
   * @p path: the directory; @p parameters: the text of `parameters.prm`.
   * Touches nothing; refuses a system folder (check_output_directory()).
   */
  RunDirectory(const std::string &path, const std::string &parameters);
  /** Releases the lock. */
  ~RunDirectory();
  RunDirectory(const RunDirectory &) = delete;
  RunDirectory &operator=(const RunDirectory &) = delete;

  /** Take the directory over as described above; does nothing the second time. */
  void begin();
  /** Whether begin() succeeded (the lock is held). */
  bool begun() const { return lock_fd >= 0; }
  const std::string &path() const { return dir; }

  /**
   * Register @p name (a file name inside the directory, no `/`) in the
   * manifest and return its path `directory/name`.
   */
  std::string create(const std::string &name);

  /**
   * Record a failure: `summary.json` becomes `{"warnings": @p warnings,
   * "status": "failed", "message": @p message}` (failed_summary()). Only
   * after begin() (a refused run never writes into the directory of
   * another); never throws.
   */
  void fail(const std::string &message,
            const std::vector<std::string> &warnings = {}) noexcept;

private:
  const std::string dir, parameters;
  int lock_fd = -1;
  int manifest_fd = -1;
  std::set<std::string> registered;
};

/**
 * Refuse (one-line message naming `Output/Output directory`) an output
 * folder that is the root folder, lies in /etc, /usr, /bin, /sbin, /boot,
 * /dev, /proc, /sys or /lib*, or is /var itself (symbolic links resolved as
 * far as the path exists): hati usually runs as root here, and a run
 * writes about ten files into its folder.
 */
void check_output_directory(const std::string &path);

/**
 * Replace @p filename by a file holding @p content atomically: the content
 * goes to `.<name>.tmp` in the same directory, which is then renamed; a
 * reader or a run killed at any instant sees the old or the new file, never
 * a part. If @p durable, the temporary file is fsync'ed before the rename and
 * the directory after it (best effort), so that a power failure too leaves
 * the old or the new file (about 1 ms per call on ext4, more when the disk
 * is busy: a file replaced often makes only some replacements durable and
 * the last one with sync_file()). Throws a one-line message naming the file
 * and the system error.
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
 * Whether SIGINT or SIGTERM arrived since RunDirectory::begin() installed
 * the handlers: the time loops then finish the current step, flush the
 * outputs and write `summary.json` with `"status": "interrupted"`.
 */
bool stop_requested();
/** The signal that asked to stop (SIGINT or SIGTERM), 0 if none. */
int stop_signal();
/** Ignore SIGPIPE: a closed standard output does not kill the run. */
void ignore_broken_pipes();

/** The message of an exception on one line, without deal.II's banner. */
std::string one_line_message(const std::exception &e);

/** The system error text of errno, e.g. "No space left on device". */
std::string system_error_text(const int error);
} // namespace hati

#endif

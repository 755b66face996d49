#ifndef hati_output_run_directory_h
#define hati_output_run_directory_h

#include <hati/base/messages.h>
#include <hati/output/output_file.h>

#include <exception>
#include <functional>
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
 * opened, so that a killed run is cleaned up by the next one as well. Every
 * file is opened relative to the directory opened by begin() and never
 * through a symbolic link (OutputFolder): a link where a file of the run,
 * the lock or the manifest would go is refused in one line naming it.
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

  /**
   * Take the directory over as described above, then call after_begin if
   * set; does nothing the second time. In a dry run (dry_run), throws
   * DryRunEnd instead, touching nothing.
   */
  void begin();

  /** What begin() throws in a dry run: every check before the outputs passed. */
  struct DryRunEnd
  {
  };
  /** A check of the run without it (Simulation::check()): begin() throws DryRunEnd. */
  bool dry_run = false;
  /** Called by begin() once the directory is locked and cleaned (a suite's member.log).
   */
  std::function<void(RunDirectory &)> after_begin;
  /** Whether begin() succeeded (the lock is held). */
  bool begun() const { return lock.fd >= 0; }
  const std::string &path() const { return dir; }

  /**
   * Register @p name (a file name inside the directory, no `/`) in the
   * manifest and return its path `directory/name`.
   */
  std::string create(const std::string &name);

  /** create() @p name and open it for writing (OutputFolder::create()). */
  OutputFile open(const std::string &name, const int flags = 0);

  /**
   * create() @p name and its temporary file and replace @p name by
   * @p content atomically (OutputFolder::replace()).
   */
  void replace(const std::string &name, const std::string &content, const bool durable);

  /** fsync @p name and the directory (OutputFolder::sync()). */
  void sync(const std::string &name) const;

  /**
   * Record a failure: `summary.json` becomes `{"warnings": @p warnings,
   * "status": "failed", "message": @p message}` (failed_summary()). Only
   * after begin() (a refused run never writes into the directory of
   * another); never throws. If the atomic replacement fails (a full disk
   * has no room for its temporary file), `summary.json` is overwritten in
   * place.
   */
  void fail(const std::string &message,
            const std::vector<std::string> &warnings = {}) noexcept;

private:
  const std::string dir, parameters;
  OutputFolder folder;
  OutputFile lock, manifest;
  std::set<std::string> registered;
};

/**
 * Take an exclusive `flock` on the file @p name in @p folder (created if
 * missing, never through a link) and return it open (the lock lasts while
 * it is open). Throws the one-line message @p in_use if another process
 * holds it, naming the file if it cannot be created; on a file system
 * without locks returns it unlocked.
 */
OutputFile
lock_file(const OutputFolder &folder, const std::string &name, const std::string &in_use);

/**
 * Install the SIGINT/SIGTERM handlers of stop_requested() (RunDirectory::
 * begin() does; a suite from its start, so that a signal before its first
 * member stops it the same way).
 */
void catch_stop_signals();

/**
 * Refuse (one-line message naming `Output/Output directory`) an output
 * folder that is the root folder, lies in /etc, /usr, /bin, /sbin, /boot,
 * /dev, /proc, /sys or /lib*, or is /var itself (symbolic links resolved as
 * far as the path exists): hati usually runs as root here, and a run
 * writes about ten files into its folder.
 */
void check_output_directory(const std::string &path);

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

/** The system error text of errno, e.g. "No space left on device". */
std::string system_error_text(const int error);
} // namespace hati

#endif

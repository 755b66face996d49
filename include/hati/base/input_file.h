#ifndef hati_base_input_file_h
#define hati_base_input_file_h

#include <deal.II/base/exceptions.h>

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace hati
{
/** The largest count or tag accepted from a mesh file (Gmsh): a guard
 * against absurd values, which are refused with the entry named. */
constexpr long max_file_count = 1000000000000L;
/** The largest coordinate accepted from a mesh file (m): a structure is
 * smaller than 1000 km; beyond, the geometry's round-off would make its
 * matrices singular, so it is refused as out of range with file and line. */
constexpr double max_file_coordinate = 1e6;

/**
 * Check, with stat() and without opening it, that @p path names a regular
 * file (or a symbolic link to one) before an input file is read: opening a
 * FIFO blocks until a writer comes, and a device such as /dev/zero never
 * ends. Throws one line starting with @p entry (the parameter that named
 * the file, e.g. `Loading/Accelerogram X`; nothing if empty):
 * `<entry>: cannot open the <kind> file '<path>': <reason>` if it cannot be
 * stat'ed, `<entry>: '<path>' is not a regular file (a FIFO): a regular
 * <kind> file is expected` (or a directory, a character device, a block
 * device, a socket) otherwise.
 */
inline void require_regular_file(const std::string &path,
                                 const std::string &entry,
                                 const std::string &kind)
{
  const std::string prefix = entry.empty() ? "" : entry + ": ";
  struct stat status;
  if (::stat(path.c_str(), &status) != 0)
  {
    const int error = errno;
    AssertThrow(false,
                dealii::ExcMessage(prefix + "cannot open the " + kind + " file '" + path +
                                   "': " + std::strerror(error)));
  }
  if (S_ISREG(status.st_mode))
    return;
  const char *what = S_ISFIFO(status.st_mode)   ? "a FIFO"
                     : S_ISDIR(status.st_mode)  ? "a directory"
                     : S_ISCHR(status.st_mode)  ? "a character device"
                     : S_ISBLK(status.st_mode)  ? "a block device"
                     : S_ISSOCK(status.st_mode) ? "a socket"
                                                : "of an unknown kind";
  AssertThrow(false,
              dealii::ExcMessage(prefix + "'" + path + "' is not a regular file (" +
                                 what + "): a regular " + kind + " file is expected"));
}
} // namespace hati

#endif

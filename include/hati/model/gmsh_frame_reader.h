#ifndef hati_model_gmsh_frame_reader_h
#define hati_model_gmsh_frame_reader_h

#include <deal.II/base/point.h>

#include <map>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The line elements of a Gmsh mesh, grouped into frame members by their
 * physical groups.
 *
 * - `nodes`: every node used by a line element or a named physical point,
 *   named by its physical point name if it has one, `@<node tag>` otherwise;
 * - `members`: for every named physical curve (dimension 1), the ordered
 *   chain of node names from one end of the member to the other.
 */
struct GmshFrame
{
  std::map<std::string, Point<3>> nodes;
  std::map<std::string, std::vector<std::string>> members;
};

/**
 * Read a Gmsh ASCII mesh (format 2.2 or 4.1) of 2-node line elements (type 1;
 * points, type 15, name nodes; other element types are ignored). Every
 * physical curve must have a name (`Physical Curve("girder") = {...};`) and
 * form a simple open chain; a branching or closed group is an error that
 * asks to split it. Errors start with @p entry (the parameter that names
 * the file, e.g. `Model/Frame/Mesh file`; nothing if empty) and name the
 * file and, where it applies, the line. The path must be a regular file
 * (checked with stat() before opening: a FIFO or a device is refused at
 * once), and a file without an $Elements section (cut short) is refused.
 */
GmshFrame read_gmsh_frame(const std::string &filename, const std::string &entry = "");
} // namespace hati

#endif

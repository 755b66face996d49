#ifndef hati_model_gmsh_solid_reader_h
#define hati_model_gmsh_solid_reader_h

#include <deal.II/grid/tria.h>

#include <string>

namespace hati
{
using namespace dealii;

/**
 * Read the 8-node hexahedra (Gmsh element type 5) of a Gmsh ASCII mesh,
 * format 4.1 or 2.2, into @p triangulation (empty). Points, lines,
 * triangles and quadrilaterals (types 15, 1, 2, 3: the boundary entities
 * Gmsh saves with the volume) are skipped; any other element (a
 * tetrahedron, a prism, a pyramid, a second-order element) is an error, and
 * so is a file with no hexahedron. Every count, tag and coordinate is
 * checked as it is read (deal.II's GridIn::read_msh() trusts the counts of
 * the file in a release build), an element's node must be in `$Nodes`, and
 * a hexahedron must have a positive Jacobian at its eight corners (once
 * turned inside out if needed): a collapsed or twisted one is an error.
 * Errors are one line, start with @p where (e.g. `Model/Frame/Solids:
 * solid 'block'`) and name the file and, where it applies, the line.
 */
void read_gmsh_hexahedra(const std::string &filename,
                         const std::string &where,
                         Triangulation<3> &triangulation);
} // namespace hati

#endif

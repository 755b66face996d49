#ifndef hati_model_solid_mesh_h
#define hati_model_solid_mesh_h

#include <deal.II/grid/tria.h>

#include <hati/model/solid_description.h>

namespace hati
{
using namespace dealii;

/**
 * The mesh of the solids of @p description in one `Triangulation<3>`
 * (@p triangulation, empty before): each solid's cells carry its index in
 * `description.solids` as material id. Solids that share vertices are
 * joined there. A `box` is a block of nx x ny x nz hexahedra; a `box
 * girder` four plates one element thick around a hollow (and the
 * diaphragms), built in the local axes of a frame member between its two
 * axis points (frame_rotation()) and moved there; a `mesh` is read from a
 * Gmsh file (hexahedra only). Throws one-line errors naming
 * `Model/Frame/Solids` and the solid.
 */
void create_solid_mesh(const SolidDescription &description,
                       Triangulation<3> &triangulation);
} // namespace hati

#endif

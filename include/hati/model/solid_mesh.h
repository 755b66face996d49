#ifndef hati_model_solid_mesh_h
#define hati_model_solid_mesh_h

#include <deal.II/base/tensor.h>
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

/**
 * The rotation R from global to the local axes of the solid @p solid (rows:
 * the local axes in global components): for a `box girder`, those of a
 * frame member between its two axis points with the default section
 * orientation (x along the girder, y its width, z its height); the identity
 * for a `box` or a `mesh`.
 */
Tensor<2, 3> solid_local_axes(const SolidDescription::Solid &solid);

/**
 * Whether @p x lies inside the hollow of the box girder @p solid, off its
 * walls: `|y| < width/2 - web thickness` and `|z| < height/2 - flange
 * thickness` in its local axes, by more than @p tolerance (m). The outer
 * face of an end diaphragm lies there, the end faces of the webs and
 * flanges do not.
 */
bool in_box_girder_hollow(const SolidDescription::Solid &solid,
                          const Point<3> &x,
                          const double tolerance);
} // namespace hati

#endif

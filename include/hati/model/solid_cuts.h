#ifndef hati_model_solid_cuts_h
#define hati_model_solid_cuts_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <hati/model/solid_description.h>

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

class FrameSolids;
class FrameSectionForces;

/**
 * The section forces of the cross-section cuts of the solids
 * (`Model/Frame/Solid cuts`, doc/theory.md 11.4): for each cut, the plane
 * `axis = value` in the solid's local axes (solid_local_axes()), the
 * resultants N, Vy, Vz, T, My, Mz of the traction `sigma n`, n the unit
 * normal along +axis (the force of the part at larger coordinate on the
 * part at smaller coordinate, the beam's convention of theory 5.6), about
 * the centroid of the cut's area, in the right-handed triad of local axes
 * (axis, axis + 1, axis + 2) cyclically: for an x cut, N along x, Vy along
 * y, Vz along z.
 *
 * The traction is integrated by Gauss quadrature of the solid's degree
 * (degree + 1 points along each direction) on the cut: over the cell faces
 * on the plane (the mean of the two sides' stresses when cells of the
 * solid lie on both), or over the plane inside the cells it crosses, mapped
 * to a plane of reference coordinates (cells that are parallelepipeds with
 * an edge direction along the axis). The section forces are linear in the
 * displacement: each cut holds them as six rows over its cells' DoFs,
 * built once.
 */
class SolidCuts
{
public:
  /**
   * The cuts of @p description over the solids @p solids (whose DoFs are
   * distributed). Throws one-line errors naming `Model/Frame/Solid cuts`
   * and the cut: a plane outside the solid, a cut that crosses a cell
   * obliquely or a cell that is not a parallelepiped, no cell cut.
   */
  SolidCuts(const FrameSolids &solids, const SolidDescription &description);

  /** Number of cuts. */
  unsigned int size() const { return cuts.size(); }

  /** The names of the cuts, in order (the `member` of their rows). */
  std::vector<std::string> names() const;

  /**
   * The section forces (N, Vy, Vz in N; T, My, Mz in N m) of every cut for
   * the displacement @p U (the frame's global numbering, constraints
   * distributed, m).
   */
  std::vector<std::array<double, 6>> section_forces(const Vector<double> &U) const;

  /**
   * Their rows of `section_forces.csv` at time @p time (s) to @p out
   * unless it is null (element 0, x = the plane's coordinate, m), and the
   * envelope of @p output updated (FrameSectionForces::add_row()).
   */
  void write(std::ostream *out,
             const double time,
             const Vector<double> &U,
             FrameSectionForces &output) const;

  /** The area (m^2) of cut @p c. */
  double area(const unsigned int c) const { return cuts[c].area; }
  /** The centroid (m, global axes) of cut @p c. */
  const Point<3> &centroid(const unsigned int c) const { return cuts[c].centroid; }

private:
  /** One cut and its six rows. */
  struct Cut
  {
    SolidDescription::Cut cut;
    double area = 0.; ///< m^2
    Point<3> centroid;
    /** The global DoFs the rows touch. */
    std::vector<types::global_dof_index> dofs;
    /** Per DoF: its coefficients in N, Vy, Vz (N/m) and T, My, Mz (N). */
    std::vector<std::array<double, 6>> coefficients;
  };

  std::vector<Cut> cuts;
};
} // namespace hati

#endif

#ifndef hati_model_solid_cuts_h
#define hati_model_solid_cuts_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <hati/contact/sparse_rows.h>
#include <hati/model/solid_description.h>

#include <array>
#include <ostream>
#include <string>
#include <utility>
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
 * The area and the centroid are Gauss quadratures of the solid's degree
 * (degree + 1 points along each direction) on the plane: over the cell
 * faces on it, or over the plane inside the cells it crosses, mapped to a
 * plane of reference coordinates. The resultants are the equivalent
 * domain integral of the stresses over the layer of cells at the plane
 * (volume Gauss quadrature): with a test function q that rises linearly
 * from 0 to 1 across each layer cell and is 1 beyond, `F = int sigma grad q
 * dV`, `M = int r x sigma grad q dV`, minus the layer's own weight that q
 * counts beyond the plane: exact in statics (the discrete equilibrium),
 * where the traction on the plane alone carries the element's stress error
 * (a shear force 1 to 80 % off on coarse meshes, theory 11.4). The layer
 * cells must be parallelepipeds with one edge direction across the plane
 * (the cells of a generated box or box girder). The section forces are
 * linear in the displacement: each cut holds them as six rows over its
 * layer's DoFs, built once.
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
   * distributed, m) under @p gravity (m/s^2, the solid's weight). With
   * @p row_values, the values of rows() for that displacement (6 per cut),
   * @p U is not read.
   */
  std::vector<std::array<double, 6>>
  section_forces(const Vector<double> &U,
                 const Tensor<1, 3> &gravity,
                 const double *row_values = nullptr) const;

  /**
   * The cuts' section forces as rows over the global DoFs, six per cut in
   * the order N, Vy, Vz, T, My, Mz: section_forces() is their product with
   * `U` less the layers' weight (doc/theory.md 11.4).
   */
  std::vector<SparseRow> rows() const;

  /**
   * Their rows of `section_forces.csv` at time @p time (s) to @p out
   * unless it is null (element 0, x = the plane's coordinate, m), and the
   * envelope of @p output updated (FrameSectionForces::add_row()).
   */
  void write(std::ostream *out,
             const double time,
             const Vector<double> &U,
             const Tensor<1, 3> &gravity,
             FrameSectionForces &output,
             const double *row_values = nullptr) const;

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
    /** Rows: the cut's axis and the next two local axes (global components). */
    Tensor<2, 3> triad;
    /** The global DoFs the rows touch. */
    std::vector<types::global_dof_index> dofs;
    /** Per DoF: its coefficients in N, Vy, Vz (N/m) and T, My, Mz (N). */
    std::vector<std::array<double, 6>> coefficients;
    /**
     * The layer's mass (kg) and first moment about the centroid (kg m)
     * that the test function counts beyond the plane and the plane does
     * not: `int rho (q - H) dV`, `int rho (q - H) r dV`.
     */
    double weight_mass = 0.;
    Tensor<1, 3> weight_moment;
  };

  /**
   * The rows of @p cut: the equivalent domain integral over the cells of
   * @p layer (each with its edge vector across the plane, m) with the
   * triad @p triad, and the layer's weight terms.
   */
  static void add_layer(
      const FrameSolids &solids,
      const Tensor<2, 3> &triad,
      const std::vector<std::pair<DoFHandler<3>::active_cell_iterator, Tensor<1, 3>>>
          &layer,
      Cut &cut);

  std::vector<Cut> cuts;
};
} // namespace hati

#endif

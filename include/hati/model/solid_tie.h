#ifndef hati_model_solid_tie_h
#define hati_model_solid_tie_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <hati/model/discrete_system.h>
#include <hati/model/solid_description.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/** Six rows, one per DoF of a node: DoF c `= sum_j rows[c][j].second
 * u_{rows[c][j].first}`. */
using NodeRows = std::array<std::vector<std::pair<types::global_dof_index, double>>, 6>;

/** The six DoFs of a node (a tied node, a slave) as functions of other DoFs. */
struct LinkRows
{
  /** The tie's or the rigid link's name. */
  std::string name;
  std::array<types::global_dof_index, 6> slave;
  NodeRows rows;
};

/**
 * The area moments of a face of a solid's boundary (spec B1, doc/theory.md
 * B1): `S = sum a_i`, the centroid `G`, `I_G = int (|r|^2 1 - r (x) r) dS`,
 * and per face DoF (translation component `c_i` of a node) the weights
 * `a_i = int N_i dS` and `b_i = int N_i (x - G) dS` from the face's own
 * quadrature.
 */
struct FaceMoments
{
  double area = 0.;
  Point<3> centroid;
  Tensor<2, 3> inertia;
  /** The face's DoFs (numbering of the DoFHandler plus the offset given). */
  std::vector<types::global_dof_index> dofs;
  /** The translation component (0, 1, 2) of each DoF. */
  std::vector<unsigned int> components;
  std::vector<double> a;
  std::vector<Tensor<1, 3>> b;
  /** Number of cell faces integrated. */
  unsigned int n_faces = 0;
};

/**
 * The boundary faces of the cells with material id @p solid whose vertices
 * all lie on the plane `x_axis = value` of @p plane (within @p tolerance,
 * m), and, with a radius, whose centre lies within it of @p centre (m);
 * their DoFs and moments (FaceMoments), the DoFs numbered from @p offset.
 * With @p skip, the faces whose centre it holds true for are left out (a box
 * girder's diaphragm faces for a plane's `walls`).
 */
FaceMoments face_moments(const DoFHandler<3> &dof_handler,
                         const unsigned int solid,
                         const SolidDescription::FacePlane &plane,
                         const Point<3> &centre,
                         const double tolerance,
                         const types::global_dof_index offset,
                         const std::function<bool(const Point<3> &)> &skip = {});

/**
 * The six rows of a beam node at @p node tied to the face @p face (B1): beam
 * DoF c (ux, uy, uz, rx, ry, rz) `= sum_j rows[c][j].second u_{rows[c][j].first}`,
 * the area-weighted rigid fit `U_G = sum a_i u_i / S`,
 * `theta = I_G^-1 sum b_i x u_i`, carried rigidly to the node,
 * `U_P = U_G - theta x (G - P)`. Throws a one-line error starting with
 * @p where if the face has no area or is a line (I_G singular).
 */
NodeRows
tie_rows(const FaceMoments &face, const Point<3> &node, const std::string &where);

/**
 * The rows of a rigid link: slave DoF c `= sum rows[c]` of the master's
 * DoFs, `u_s = u_m + theta_m x (x_s - x_m)`, `theta_s = theta_m`.
 */
NodeRows rigid_link_rows(const std::array<types::global_dof_index, 6> &master,
                         const Point<3> &x_master,
                         const Point<3> &x_slave);

/**
 * Add the six lines `slave[c] = rows[c]` of @p link to @p constraints (slave
 * DoFs not yet constrained).
 */
void add_constraint_lines(const LinkRows &link, AffineConstraints<double> &constraints);

/**
 * The six bilateral constraint rows `slave_c - sum rows[c] = 0` of @p link
 * (ContactRow::constraint, named after the link) appended to @p rows; the
 * DoFs flagged in @p fixed (supported) are left out of them.
 */
void add_link_rows(const LinkRows &link,
                   const std::vector<bool> &fixed,
                   std::vector<ContactRow> &rows);
} // namespace hati

#endif

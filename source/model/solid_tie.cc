#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <hati/model/solid_tie.h>

#include <cmath>
#include <map>

namespace hati
{
namespace
{
/** Whether every vertex of @p face lies on @p plane (within @p tolerance). */
template <class FaceIterator>
bool on_plane(const FaceIterator &face,
              const SolidDescription::FacePlane &plane,
              const double tolerance)
{
  for (unsigned int v = 0; v < face->n_vertices(); ++v)
    if (std::abs(face->vertex(v)[plane.axis] - plane.value) > tolerance)
      return false;
  return true;
}

/** The distance of @p x from @p centre within the plane (the axis left out). */
double
in_plane_distance(const Point<3> &x, const Point<3> &centre, const unsigned int axis)
{
  double d2 = 0.;
  for (unsigned int k = 0; k < 3; ++k)
    if (k != axis)
      d2 += (x[k] - centre[k]) * (x[k] - centre[k]);
  return std::sqrt(d2);
}
} // namespace

FaceMoments face_moments(const DoFHandler<3> &dof_handler,
                         const unsigned int solid,
                         const SolidDescription::FacePlane &plane,
                         const Point<3> &centre,
                         const double tolerance,
                         const types::global_dof_index offset,
                         const std::function<bool(const Point<3> &)> &skip)
{
  const auto &fe = dof_handler.get_fe();
  const QGauss<2> quadrature(fe.degree + 1);
  FEFaceValues<3> values(
      fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  // per DoF: a_i, int N_i x dS and its component; the face's S, int x, int x (x) x
  struct Weight
  {
    double a = 0.;
    Tensor<1, 3> x;
    unsigned int component = 0;
  };
  std::map<types::global_dof_index, Weight> weights;
  FaceMoments m;
  Tensor<1, 3> first;
  Tensor<2, 3> second;
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    if (cell->material_id() != solid)
      continue;
    for (const unsigned int f : cell->face_indices())
    {
      const auto face = cell->face(f);
      if (!face->at_boundary() || !on_plane(face, plane, tolerance))
        continue;
      if (plane.radius > 0. &&
          in_plane_distance(face->center(), centre, plane.axis) > plane.radius)
        continue;
      if (skip && skip(face->center()))
        continue;
      ++m.n_faces;
      values.reinit(cell, f);
      cell->get_dof_indices(cell_dofs);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const Point<3> &x = values.quadrature_point(q);
        const double w = values.JxW(q);
        m.area += w;
        first += w * x;
        second += w * outer_product(x, x);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          if (!fe.has_support_on_face(i, f))
            continue;
          const double N = values.shape_value(i, q);
          Weight &weight = weights[cell_dofs[i]];
          weight.a += N * w;
          weight.x += N * w * x;
          weight.component = fe.system_to_component_index(i).first;
        }
      }
    }
  }
  if (m.area <= 0.)
    return m;
  m.centroid = Point<3>(first / m.area);
  const Tensor<1, 3> G = m.centroid;
  // int r (x) r dS with r = x - G, then I_G = tr(.) 1 - (.)
  const Tensor<2, 3> rr = second - m.area * outer_product(G, G);
  m.inertia = -rr;
  for (unsigned int k = 0; k < 3; ++k)
    m.inertia[k][k] += trace(rr);
  for (const auto &[dof, w] : weights)
  {
    m.dofs.push_back(dof + offset);
    m.components.push_back(w.component);
    m.a.push_back(w.a);
    m.b.push_back(w.x - w.a * G);
  }
  return m;
}

NodeRows tie_rows(const FaceMoments &face, const Point<3> &node, const std::string &where)
{
  AssertThrow(face.n_faces > 0 && face.area > 0.,
              ExcMessage(where + ": no face of the solid's boundary lies on that plane "
                                 "(within the radius): no solid node to tie to"));
  // I_G of a line or a point is singular: compare with the polar moment S^2
  const double scale = face.area * face.area;
  AssertThrow(std::abs(determinant(face.inertia)) > 1e-12 * scale * scale * scale,
              ExcMessage(where + ": the face is a line or a point (its second moment "
                                 "I_G is singular): it cannot carry a moment"));
  const Tensor<2, 3> J_inverse = invert(face.inertia);
  const Tensor<1, 3> arm = face.centroid - node;
  NodeRows rows;
  for (unsigned int j = 0; j < face.dofs.size(); ++j)
  {
    Tensor<1, 3> e;
    e[face.components[j]] = 1.;
    const Tensor<1, 3> theta = J_inverse * cross_product_3d(face.b[j], e);
    const Tensor<1, 3> u = face.a[j] / face.area * e - cross_product_3d(theta, arm);
    for (unsigned int c = 0; c < 3; ++c)
    {
      if (u[c] != 0.)
        rows[c].emplace_back(face.dofs[j], u[c]);
      if (theta[c] != 0.)
        rows[3 + c].emplace_back(face.dofs[j], theta[c]);
    }
  }
  return rows;
}

NodeRows rigid_link_rows(const std::array<types::global_dof_index, 6> &master,
                         const Point<3> &x_master,
                         const Point<3> &x_slave)
{
  const Tensor<1, 3> d = x_slave - x_master;
  NodeRows rows;
  for (unsigned int c = 0; c < 3; ++c)
  {
    rows[c].emplace_back(master[c], 1.);
    rows[3 + c].emplace_back(master[3 + c], 1.);
    // (theta x d)_c = theta_{c+1} d_{c+2} - theta_{c+2} d_{c+1}
    const unsigned int p = (c + 1) % 3, q = (c + 2) % 3;
    if (d[q] != 0.)
      rows[c].emplace_back(master[3 + p], d[q]);
    if (d[p] != 0.)
      rows[c].emplace_back(master[3 + q], -d[p]);
  }
  return rows;
}

void add_constraint_lines(const LinkRows &link, AffineConstraints<double> &constraints)
{
  for (unsigned int c = 0; c < 6; ++c)
  {
    constraints.add_line(link.slave[c]);
    constraints.add_entries(link.slave[c], link.rows[c]);
  }
}

void add_link_rows(const LinkRows &link,
                   const std::vector<bool> &fixed,
                   std::vector<ContactRow> &rows)
{
  for (unsigned int c = 0; c < 6; ++c)
  {
    ContactRow row;
    row.name = link.name;
    row.bilateral = true;
    row.constraint = true;
    if (!fixed[link.slave[c]])
    {
      row.dofs.push_back(link.slave[c]);
      row.coefficients.push_back(1.);
    }
    for (const auto &[j, a] : link.rows[c])
      if (!fixed[j])
      {
        row.dofs.push_back(j);
        row.coefficients.push_back(-a);
      }
    if (!row.dofs.empty())
      rows.push_back(row);
  }
}
} // namespace hati

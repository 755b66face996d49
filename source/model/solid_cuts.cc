#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <hati/model/frame_section_forces.h>
#include <hati/model/frame_solids.h>
#include <hati/model/solid_cuts.h>
#include <hati/model/solid_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace hati
{
namespace
{
using CellIterator = DoFHandler<3>::active_cell_iterator;

/** A quadrature point of the cut's plane: its place and area weight (m^2). */
struct PlanePoint
{
  Point<3> x;
  double area = 0.;
};

/** "Model/Frame/Solid cuts: cut '<name>': <what>" unless @p ok. */
void require(const bool ok, const SolidDescription::Cut &cut, const std::string &what)
{
  AssertThrow(ok, ExcMessage("Model/Frame/Solid cuts: cut '" + cut.name + "': " + what));
}

std::string plane_text(const SolidDescription::Cut &cut)
{
  std::ostringstream s;
  s << char('x' + cut.axis) << " = " << cut.value << " m";
  return s.str();
}

std::string centre_text(const CellIterator &cell)
{
  std::ostringstream s;
  s << "(centre " << cell->center()[0] << ", " << cell->center()[1] << ", "
    << cell->center()[2] << " m)";
  return s.str();
}

/**
 * The edge vector D of @p cell along which the coordinate `normal . x`
 * grows (its other two edge vectors parallel to the plane): the cell must
 * be a parallelepiped with one edge direction across the plane, else a
 * one-line error naming the cut.
 */
Tensor<1, 3> edge_across(const SolidDescription::Cut &cut,
                         const CellIterator &cell,
                         const Tensor<1, 3> &normal,
                         const double tolerance)
{
  const Point<3> v0 = cell->vertex(0);
  std::array<Tensor<1, 3>, 3> J;
  for (unsigned int j = 0; j < 3; ++j)
    J[j] = cell->vertex(1u << j) - v0;
  for (unsigned int v = 0; v < 8; ++v)
  {
    Point<3> affine = v0;
    for (unsigned int j = 0; j < 3; ++j)
      if (v & (1u << j))
        affine += J[j];
    require(affine.distance(cell->vertex(v)) <= tolerance,
            cut,
            "the plane " + plane_text(cut) +
                " cuts a cell that is not a parallelepiped " + centre_text(cell) +
                ": a cut needs cells with edges along its axis");
  }
  unsigned int along = 3, n_along = 0;
  for (unsigned int j = 0; j < 3; ++j)
    if (std::abs(normal * J[j]) > tolerance)
    {
      along = j;
      ++n_along;
    }
  require(n_along == 1,
          cut,
          "the plane " + plane_text(cut) + " cuts a cell obliquely " + centre_text(cell) +
              ": a cut needs cells with edges along its axis; put it where the cells "
              "are aligned");
  return normal * J[along] > 0. ? J[along] : -J[along];
}

/**
 * The plane's quadrature points in a cell it crosses strictly inside (a
 * plane of constant reference coordinate, the cell a parallelepiped with
 * the edge @p D across it): the 2D Gauss rule of @p degree + 1 points.
 */
void cross_cell(const CellIterator &cell,
                const Tensor<1, 3> &normal,
                const Tensor<1, 3> &D,
                const double value,
                const unsigned int degree,
                std::vector<PlanePoint> &points)
{
  // the cell as x = v0 + sum_j xi_j J_j, xi in [0, 1]^3
  const Point<3> v0 = cell->vertex(0);
  unsigned int along = 0;
  std::array<Tensor<1, 3>, 3> J;
  for (unsigned int j = 0; j < 3; ++j)
  {
    J[j] = cell->vertex(1u << j) - v0;
    if (std::abs(std::abs(J[j] * normal) - D * normal) <= 1e-12 * D.norm())
      along = j;
  }
  const double xi = (value - normal * v0) / (normal * J[along]);
  const unsigned int j1 = (along + 1) % 3, j2 = (along + 2) % 3;
  const double jacobian = cross_product_3d(J[j1], J[j2]).norm();
  const QGauss<2> plane(degree + 1);
  for (unsigned int q = 0; q < plane.size(); ++q)
  {
    Point<3> x = v0 + xi * J[along];
    x += plane.point(q)[0] * J[j1] + plane.point(q)[1] * J[j2];
    points.push_back({x, plane.weight(q) * jacobian});
  }
}

/**
 * The plane's quadrature points on the faces of @p cell that lie on it
 * (half weight where a cell of the same solid lies on the other side);
 * whether it has one.
 */
bool face_on_plane(const CellIterator &cell,
                   const Tensor<1, 3> &normal,
                   const double value,
                   const double tolerance,
                   std::vector<PlanePoint> &points)
{
  const auto &fe = cell->get_fe();
  const QGauss<2> plane(fe.degree + 1);
  bool found = false;
  for (const unsigned int f : cell->face_indices())
  {
    bool on = true;
    for (const unsigned int v : cell->face(f)->vertex_indices())
      on = on && std::abs(normal * cell->face(f)->vertex(v) - value) <= tolerance;
    if (!on)
      continue;
    found = true;
    const bool two_sided =
        !cell->at_boundary(f) && cell->neighbor(f)->material_id() == cell->material_id();
    FEFaceValues<3> values(fe, plane, update_quadrature_points | update_JxW_values);
    values.reinit(cell, f);
    for (unsigned int q = 0; q < plane.size(); ++q)
      points.push_back(
          {values.quadrature_point(q), (two_sided ? 0.5 : 1.) * values.JxW(q)});
  }
  return found;
}

} // namespace

void SolidCuts::add_layer(const FrameSolids &solids,
                          const Tensor<2, 3> &triad,
                          const std::vector<std::pair<CellIterator, Tensor<1, 3>>> &layer,
                          Cut &cut)
{
  const auto &fe = solids.dofs().get_fe();
  const QGauss<3> quadrature(fe.degree + 1);
  FEValues<3> values(
      fe, quadrature, update_gradients | update_quadrature_points | update_JxW_values);
  const Tensor<1, 3> normal = triad[0];
  const unsigned int n = fe.n_dofs_per_cell();
  std::vector<types::global_dof_index> dofs(n);
  std::map<types::global_dof_index, std::array<double, 6>> rows;
  for (const auto &[cell, D] : layer)
  {
    values.reinit(cell);
    cell->get_dof_indices(dofs);
    const unsigned int solid = cell->material_id();
    // the test function q, 0 on the cell's face at smaller coordinate and
    // 1 on the other, grad q = normal / h
    const double h = D * normal;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const Tensor<1, 3> r = values.quadrature_point(q) - cut.centroid;
      for (unsigned int i = 0; i < n; ++i)
      {
        Tensor<2, 3> grad;
        grad[fe.system_to_component_index(i).first] = values.shape_grad(i, q);
        const Tensor<1, 3> t =
            values.JxW(q) / h * (solids.stress(solid, symmetrize(grad)) * normal);
        const Tensor<1, 3> force = triad * t, moment = triad * cross_product_3d(r, t);
        auto &row = rows.try_emplace(dofs[i] + solids.offset(), std::array<double, 6>{})
                        .first->second;
        for (unsigned int k = 0; k < 3; ++k)
        {
          row[k] += force[k];
          row[3 + k] += moment[k];
        }
      }
    }
    // the weight of the layer counted as beyond the plane by q but not by
    // the step H (m_eff, r_eff: int rho (q - H) (1, r) dV, exact for the
    // parallelepiped with s = (a - a0) / h, s_c at the plane)
    const double volume = cell->measure(), rho = solids.density(solid);
    const double a0 = normal * cell->center() - 0.5 * h;
    const double sc = std::clamp((cut.cut.value - a0) / h, 0., 1.);
    cut.weight_mass += rho * volume * (sc - 0.5);
    cut.weight_moment += rho * volume *
                         ((sc - 0.5) * (cell->center() - cut.centroid) +
                          (1. / 12. - 0.5 * sc * (1. - sc)) * D);
  }
  for (const auto &[dof, row] : rows)
  {
    cut.dofs.push_back(dof);
    cut.coefficients.push_back(row);
  }
}

SolidCuts::SolidCuts(const FrameSolids &solids, const SolidDescription &description)
{
  const double tolerance = 1e-9 * std::max(solids.size(), 1.);
  const auto &dof_handler = solids.dofs();
  for (const auto &c : description.cuts)
  {
    unsigned int solid = 0;
    while (description.solids[solid].name != c.solid)
      ++solid;
    const Tensor<2, 3> R = solid_local_axes(description.solids[solid]);
    const Tensor<1, 3> normal = R[c.axis];
    // the solid's extent along the axis: the plane must lie within it
    double low = std::numeric_limits<double>::max(), high = -low;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->material_id() == solid)
        for (const unsigned int v : cell->vertex_indices())
        {
          low = std::min(low, normal * cell->vertex(v));
          high = std::max(high, normal * cell->vertex(v));
        }
    require(c.value >= low - tolerance && c.value <= high + tolerance,
            c,
            "the plane " + plane_text(c) + " lies outside solid '" + c.solid + "' (" +
                char('x' + c.axis) + " from " + Utilities::to_string(low) + " to " +
                Utilities::to_string(high) + " m in its local axes)");
    // the plane's points (area, centroid) and the layer of cells the
    // forces are integrated over: the cells the plane crosses and those
    // whose face at larger coordinate lies on it (below), or without
    // those the cells whose face at smaller coordinate does (above)
    std::vector<PlanePoint> points;
    std::vector<std::pair<CellIterator, Tensor<1, 3>>> below, above;
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (cell->material_id() != solid)
        continue;
      double a = std::numeric_limits<double>::max(), b = -a;
      for (const unsigned int v : cell->vertex_indices())
      {
        a = std::min(a, normal * cell->vertex(v));
        b = std::max(b, normal * cell->vertex(v));
      }
      if (c.value < a - tolerance || c.value > b + tolerance)
        continue;
      if (face_on_plane(cell, normal, c.value, tolerance, points))
      {
        const Tensor<1, 3> D = edge_across(c, cell, normal, tolerance);
        (std::abs(c.value - b) <= tolerance ? below : above).emplace_back(cell, D);
      }
      else if (c.value > a + tolerance && c.value < b - tolerance)
      {
        const Tensor<1, 3> D = edge_across(c, cell, normal, tolerance);
        cross_cell(cell, normal, D, c.value, dof_handler.get_fe().degree, points);
        below.emplace_back(cell, D);
      }
      // else the plane touches the cell at an edge or a vertex only
    }
    Cut cut;
    cut.cut = c;
    for (const auto &p : points)
    {
      cut.area += p.area;
      cut.centroid += p.area * p.x;
    }
    require(cut.area > 0.,
            c,
            "no cell of solid '" + c.solid + "' is cut by the plane " + plane_text(c) +
                " (it touches the solid at edges or vertices only)");
    cut.centroid /= cut.area;
    // forces and moments about the centroid in the triad (axis, axis + 1,
    // axis + 2) of the local axes
    for (unsigned int k = 0; k < 3; ++k)
      cut.triad[k] = R[(c.axis + k) % 3];
    add_layer(solids, cut.triad, below.empty() ? above : below, cut);
    cuts.push_back(std::move(cut));
  }
}

std::vector<std::string> SolidCuts::names() const
{
  std::vector<std::string> n;
  for (const auto &c : cuts)
    n.push_back(c.cut.name);
  return n;
}

std::vector<std::array<double, 6>> SolidCuts::section_forces(
    const Vector<double> &U, const Tensor<1, 3> &gravity, const double *row_values) const
{
  std::vector<std::array<double, 6>> s(cuts.size(), std::array<double, 6>{});
  for (unsigned int c = 0; c < cuts.size(); ++c)
  {
    const Cut &cut = cuts[c];
    if (row_values != nullptr)
      for (unsigned int k = 0; k < 6; ++k)
        s[c][k] = row_values[6 * c + k];
    else
      for (unsigned int i = 0; i < cut.dofs.size(); ++i)
        for (unsigned int k = 0; k < 6; ++k)
          s[c][k] += cut.coefficients[i][k] * U[cut.dofs[i]];
    // the layer's weight beyond the plane by q but not by the step H
    // (theory 11.4): taken off, so that self-weight gives exact values
    const Tensor<1, 3> force = cut.triad * (cut.weight_mass * gravity),
                       moment = cut.triad * cross_product_3d(cut.weight_moment, gravity);
    for (unsigned int k = 0; k < 3; ++k)
    {
      s[c][k] -= force[k];
      s[c][3 + k] -= moment[k];
    }
  }
  return s;
}

std::vector<SparseRow> SolidCuts::rows() const
{
  std::vector<SparseRow> r(6 * cuts.size());
  for (unsigned int c = 0; c < cuts.size(); ++c)
    for (unsigned int k = 0; k < 6; ++k)
    {
      SparseRow &row = r[6 * c + k];
      row.dofs = cuts[c].dofs;
      for (const auto &coefficients : cuts[c].coefficients)
        row.coefficients.push_back(coefficients[k]);
    }
  return r;
}

void SolidCuts::write(std::ostream *out,
                      const double time,
                      const Vector<double> &U,
                      const Tensor<1, 3> &gravity,
                      FrameSectionForces &output,
                      const double *row_values) const
{
  const auto s = section_forces(U, gravity, row_values);
  for (unsigned int c = 0; c < cuts.size(); ++c)
    output.add_row(out, time, cuts[c].cut.name, 0, cuts[c].cut.value, s[c]);
}
} // namespace hati

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

/** The traction of every shape function at one quadrature point of a cut. */
struct CutPoint
{
  Point<3> x;
  /** Area weight (m^2). */
  double area = 0.;
  /** The global DoFs of the cell and the traction (Pa per m) of each. */
  std::vector<types::global_dof_index> dofs;
  std::vector<Tensor<1, 3>> traction;
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

/**
 * The points of @p values (reinitialised on a cell of solid @p solid) as
 * cut points: the traction sigma(grad phi_i) n of every shape function,
 * weighted by @p area[q] (m^2).
 */
void add_points(const FrameSolids &solids,
                const unsigned int solid,
                const FEValuesBase<3> &values,
                const std::vector<types::global_dof_index> &dofs,
                const std::vector<double> &area,
                const Tensor<1, 3> &normal,
                std::vector<CutPoint> &points)
{
  const auto &fe = values.get_fe();
  for (unsigned int q = 0; q < area.size(); ++q)
  {
    CutPoint p;
    p.x = values.quadrature_point(q);
    p.area = area[q];
    p.dofs = dofs;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
    {
      Tensor<2, 3> grad;
      grad[fe.system_to_component_index(i).first] = values.shape_grad(i, q);
      p.traction.push_back(solids.stress(solid, symmetrize(grad)) * normal);
    }
    points.push_back(std::move(p));
  }
}

/**
 * The cut points of a cell crossed by the plane `normal . x = value`
 * strictly inside it: the cell must be a parallelepiped with one edge
 * direction along the normal's axis (the plane a plane of constant
 * reference coordinate), else a one-line error.
 */
void cross_cell(const FrameSolids &solids,
                const SolidDescription::Cut &cut,
                const CellIterator &cell,
                const Tensor<1, 3> &normal,
                const double tolerance,
                const std::vector<types::global_dof_index> &dofs,
                std::vector<CutPoint> &points)
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
                " crosses a cell that is not a parallelepiped (centre " +
                Utilities::to_string(cell->center()[0]) + ", " +
                Utilities::to_string(cell->center()[1]) + ", " +
                Utilities::to_string(cell->center()[2]) +
                " m): a cut crosses only cells with edges along its axis");
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
          "the plane " + plane_text(cut) + " crosses a cell obliquely (centre " +
              Utilities::to_string(cell->center()[0]) + ", " +
              Utilities::to_string(cell->center()[1]) + ", " +
              Utilities::to_string(cell->center()[2]) +
              " m): a cut crosses only cells with edges along its axis; put the cut "
              "on an element face or where the cells are aligned");
  const double c = (cut.value - normal * v0) / (normal * J[along]);
  const unsigned int j1 = (along + 1) % 3, j2 = (along + 2) % 3;
  const double jacobian = cross_product_3d(J[j1], J[j2]).norm();
  const auto &fe = solids.dofs().get_fe();
  const QGauss<2> plane(fe.degree + 1);
  std::vector<Point<3>> reference(plane.size());
  std::vector<double> area(plane.size());
  for (unsigned int q = 0; q < plane.size(); ++q)
  {
    reference[q][along] = c;
    reference[q][j1] = plane.point(q)[0];
    reference[q][j2] = plane.point(q)[1];
    area[q] = plane.weight(q) * jacobian;
  }
  FEValues<3> values(fe,
                     Quadrature<3>(reference, std::vector<double>(plane.size(), 0.)),
                     update_gradients | update_quadrature_points);
  values.reinit(cell);
  add_points(solids, cell->material_id(), values, dofs, area, normal, points);
}

/**
 * The cut points of the faces of @p cell on the plane `normal . x =
 * value` (half weight where a cell of the same solid lies on the other
 * side: the mean of the two sides' stresses); whether it has one.
 */
bool face_on_plane(const FrameSolids &solids,
                   const SolidDescription::Cut &cut,
                   const CellIterator &cell,
                   const Tensor<1, 3> &normal,
                   const double tolerance,
                   const std::vector<types::global_dof_index> &dofs,
                   std::vector<CutPoint> &points)
{
  const auto &fe = solids.dofs().get_fe();
  const QGauss<2> plane(fe.degree + 1);
  bool found = false;
  for (const unsigned int f : cell->face_indices())
  {
    bool on = true;
    for (const unsigned int v : cell->face(f)->vertex_indices())
      on = on && std::abs(normal * cell->face(f)->vertex(v) - cut.value) <= tolerance;
    if (!on)
      continue;
    found = true;
    const bool two_sided =
        !cell->at_boundary(f) && cell->neighbor(f)->material_id() == cell->material_id();
    FEFaceValues<3> values(
        fe, plane, update_gradients | update_quadrature_points | update_JxW_values);
    values.reinit(cell, f);
    std::vector<double> area(plane.size());
    for (unsigned int q = 0; q < plane.size(); ++q)
      area[q] = (two_sided ? 0.5 : 1.) * values.JxW(q);
    add_points(solids, cell->material_id(), values, dofs, area, normal, points);
  }
  return found;
}
} // namespace

SolidCuts::SolidCuts(const FrameSolids &solids, const SolidDescription &description)
{
  const double tolerance = 1e-9 * std::max(solids.size(), 1.);
  const auto &dof_handler = solids.dofs();
  std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
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
    std::vector<CutPoint> points;
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
      cell->get_dof_indices(dofs);
      for (auto &d : dofs)
        d += solids.offset();
      // on a face, or touching the cell at an edge or a vertex only (no
      // area), or crossing it
      if (face_on_plane(solids, c, cell, normal, tolerance, dofs, points) ||
          c.value <= a + tolerance || c.value >= b - tolerance)
        continue;
      cross_cell(solids, c, cell, normal, tolerance, dofs, points);
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
    // the rows: forces and moments about the centroid in the triad
    // (axis, axis + 1, axis + 2) of the local axes
    Tensor<2, 3> triad;
    for (unsigned int k = 0; k < 3; ++k)
      triad[k] = R[(c.axis + k) % 3];
    std::map<types::global_dof_index, std::array<double, 6>> rows;
    for (const auto &p : points)
    {
      const Tensor<1, 3> r = p.x - cut.centroid;
      for (unsigned int i = 0; i < p.dofs.size(); ++i)
      {
        const Tensor<1, 3> t = p.area * p.traction[i];
        const Tensor<1, 3> force = triad * t, moment = triad * cross_product_3d(r, t);
        auto &row = rows.try_emplace(p.dofs[i], std::array<double, 6>{}).first->second;
        for (unsigned int k = 0; k < 3; ++k)
        {
          row[k] += force[k];
          row[3 + k] += moment[k];
        }
      }
    }
    for (const auto &[dof, row] : rows)
    {
      cut.dofs.push_back(dof);
      cut.coefficients.push_back(row);
    }
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

std::vector<std::array<double, 6>>
SolidCuts::section_forces(const Vector<double> &U) const
{
  std::vector<std::array<double, 6>> s(cuts.size(), std::array<double, 6>{});
  for (unsigned int c = 0; c < cuts.size(); ++c)
    for (unsigned int i = 0; i < cuts[c].dofs.size(); ++i)
      for (unsigned int k = 0; k < 6; ++k)
        s[c][k] += cuts[c].coefficients[i][k] * U[cuts[c].dofs[i]];
  return s;
}

void SolidCuts::write(std::ostream *out,
                      const double time,
                      const Vector<double> &U,
                      FrameSectionForces &output) const
{
  const auto s = section_forces(U);
  for (unsigned int c = 0; c < cuts.size(); ++c)
    output.add_row(out, time, cuts[c].cut.name, 0, cuts[c].cut.value, s[c]);
}
} // namespace hati

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <hati/model/frame_element.h>
#include <hati/model/gmsh_solid_reader.h>
#include <hati/model/memory_estimate.h>
#include <hati/model/solid_mesh.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace hati
{
namespace
{
using SolidItem = SolidDescription::Solid;

std::string where(const SolidItem &s)
{
  return "Model/Frame/Solids: solid '" + s.name + "'";
}

/** @p n equal steps of the interval of length @p length. */
void add_steps(std::vector<double> &steps, const double length, const double size)
{
  const unsigned int n = std::max(1L, std::lround(length / size));
  for (unsigned int i = 0; i < n; ++i)
    steps.push_back(length / n);
}

/** The cell sizes along the girder's axis and which slabs are diaphragms. */
void axial_steps(const SolidItem &s,
                 const double length,
                 std::vector<double> &steps,
                 std::vector<bool> &diaphragm)
{
  // the diaphragm slabs [a, b], in order
  std::vector<std::pair<double, double>> slabs;
  const double t = s.web_thickness;
  if (s.diaphragm_spacing > 0.)
  {
    slabs.emplace_back(0., t);
    for (double c = s.diaphragm_spacing; c + 0.5 * t < length - t;
         c += s.diaphragm_spacing)
      if (c - 0.5 * t > t)
        slabs.emplace_back(c - 0.5 * t, c + 0.5 * t);
    slabs.emplace_back(length - t, length);
  }
  double x = 0.;
  for (const auto &[a, b] : slabs)
  {
    if (a > x)
    {
      add_steps(steps, a - x, s.element_size);
      diaphragm.resize(steps.size(), false);
    }
    steps.push_back(b - a);
    diaphragm.push_back(true);
    x = b;
  }
  if (x < length)
  {
    add_steps(steps, length - x, s.element_size);
    diaphragm.resize(steps.size(), false);
  }
}

/**
 * Refuse a solid of @p n_cells cells of @p size (DoFs, nonzeros) at degree
 * @p degree that would not fit in memory with its factorisation.
 */
void check_solid_memory(const SolidItem &s,
                        const double n_cells,
                        const HexahedraSize &size,
                        const unsigned int degree)
{
  check_memory_estimate(where(s),
                        n_cells,
                        size.n_dofs,
                        size.n_nonzeros,
                        factorization_memory(size.n_dofs, degree),
                        "its cells or their degree (now " + std::to_string(degree) +
                            ": Model/Frame/Solid element degree, the crane's Girder "
                            "element size and Girder element degree)");
}

void create_box(const SolidItem &s, const unsigned int degree, Triangulation<3> &t)
{
  check_solid_memory(
      s,
      double(s.cells[0]) * s.cells[1] * s.cells[2],
      box_size({{double(s.cells[0]), double(s.cells[1]), double(s.cells[2])}}, degree),
      degree);
  GridGenerator::subdivided_hyper_rectangle(
      t, std::vector<unsigned int>(s.cells.begin(), s.cells.end()), s.x0, s.x1);
}

/**
 * An upper bound of the number of cells of the girder from its dimensions
 * alone (the cross-section's counts exact, the axial count bounded by the
 * diaphragms' number): checked against the memory before any step is
 * built, since a tiny element size or diaphragm spacing would fill the
 * memory with steps first.
 */
double girder_cells_bound(const SolidItem &s, const double length)
{
  const auto across = [&](const double inner)
  { return 2. + std::max(1., std::round(inner / s.element_size)); };
  const double n_slabs =
      s.diaphragm_spacing > 0. ? length / s.diaphragm_spacing + 2. : 0.;
  return (length / s.element_size + 2. * n_slabs + 1.) *
         across(s.width - 2. * s.web_thickness) *
         across(s.height - 2. * s.flange_thickness);
}

void create_box_girder(const SolidItem &s, const unsigned int degree, Triangulation<3> &t)
{
  const double length = s.x0.distance(s.x1);
  const double bound = girder_cells_bound(s, length);
  check_solid_memory(s, bound, hexahedra_size(bound, degree), degree);
  std::vector<std::vector<double>> steps(3);
  std::vector<bool> diaphragm;
  axial_steps(s, length, steps[0], diaphragm);
  const double tw = s.web_thickness, tf = s.flange_thickness;
  steps[1].push_back(tw);
  add_steps(steps[1], s.width - 2. * tw, s.element_size);
  steps[1].push_back(tw);
  steps[2].push_back(tf);
  add_steps(steps[2], s.height - 2. * tf, s.element_size);
  steps[2].push_back(tf);
  const double n_cells = double(steps[0].size()) * steps[1].size() * steps[2].size();
  check_solid_memory(s, n_cells, hexahedra_size(n_cells, degree), degree);

  Triangulation<3> block;
  GridGenerator::subdivided_hyper_rectangle(
      block,
      steps,
      Point<3>(0., -0.5 * s.width, -0.5 * s.height),
      Point<3>(length, 0.5 * s.width, 0.5 * s.height));
  // remove the hollow: cells inside the walls that are not in a diaphragm
  // slab (the slab from the cell centre's position along the axis)
  std::vector<double> slab_end(steps[0].size());
  double x = 0.;
  for (unsigned int i = 0; i < steps[0].size(); ++i)
    slab_end[i] = (x += steps[0][i]);
  std::set<Triangulation<3>::active_cell_iterator> removed;
  for (const auto &cell : block.active_cell_iterators())
  {
    const Point<3> c = cell->center();
    const bool inside =
        std::abs(c[1]) < 0.5 * s.width - tw && std::abs(c[2]) < 0.5 * s.height - tf;
    const unsigned int slab =
        std::lower_bound(slab_end.begin(), slab_end.end(), c[0]) - slab_end.begin();
    if (inside && !(slab < diaphragm.size() && diaphragm[slab]))
      removed.insert(cell);
  }
  GridGenerator::create_triangulation_with_removed_cells(block, removed, t);
  // to the member's local axes: x = x0 + R^T p
  const Tensor<2, 3> R = solid_local_axes(s);
  GridTools::transform(
      [&](const Point<3> &p)
      {
        Point<3> y = s.x0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int k = 0; k < 3; ++k)
            y[i] += R[k][i] * p[k];
        return y;
      },
      t);
}

} // namespace

Tensor<2, 3> solid_local_axes(const SolidItem &s)
{
  if (s.kind != "box girder")
  {
    Tensor<2, 3> identity;
    for (unsigned int d = 0; d < 3; ++d)
      identity[d][d] = 1.;
    return identity;
  }
  // the default section orientation of a frame member (global Y, or X for
  // a member along Y)
  const Tensor<1, 3> axis = s.x1 - s.x0;
  Tensor<1, 3> y_reference({0., 1., 0.});
  if (std::abs(axis[1]) > (1. - 1e-9) * axis.norm())
    y_reference = Tensor<1, 3>({1., 0., 0.});
  return frame_rotation(s.x0, s.x1, y_reference);
}

bool in_box_girder_hollow(const SolidItem &s, const Point<3> &x, const double tolerance)
{
  const Tensor<1, 3> local = solid_local_axes(s) * (x - s.x0);
  return std::abs(local[1]) < 0.5 * s.width - s.web_thickness - tolerance &&
         std::abs(local[2]) < 0.5 * s.height - s.flange_thickness - tolerance;
}

namespace
{
/**
 * Refuse the solid @p s (its mesh @p part) if a cell of it overlaps a cell
 * of the solids before it (@p earlier): a cell centre of one strictly
 * inside a cell of the other. Solids that only touch (a shared face) pass.
 */
void refuse_overlap(const SolidDescription &description,
                    const Triangulation<3> &earlier,
                    const Triangulation<3> &part,
                    const SolidItem &s)
{
  const auto a = GridTools::compute_bounding_box(earlier),
             b = GridTools::compute_bounding_box(part);
  const double size = std::max(a.side_length(0) + a.side_length(1) + a.side_length(2),
                               b.side_length(0) + b.side_length(1) + b.side_length(2));
  for (unsigned int d = 0; d < 3; ++d)
    if (std::min(a.get_boundary_points().second[d], b.get_boundary_points().second[d]) -
            std::max(a.get_boundary_points().first[d],
                     b.get_boundary_points().first[d]) <=
        1e-9 * size)
      return; // bounding boxes that at most touch
  const auto inside = [](const Triangulation<3> &t, const Point<3> &x)
  {
    for (const auto &cell : t.active_cell_iterators())
      if (cell->bounding_box().point_inside(x) && cell->point_inside(x))
        return cell->material_id();
    return numbers::invalid_material_id;
  };
  const auto report = [&](const types::material_id other)
  {
    AssertThrow(other == numbers::invalid_material_id,
                ExcMessage(where(s) + " overlaps solid '" +
                           description.solids[other].name +
                           "': solids may touch (a tie joins them), never share volume"));
  };
  for (const auto &cell : part.active_cell_iterators())
    report(inside(earlier, cell->center()));
  for (const auto &cell : earlier.active_cell_iterators())
    if (inside(part, cell->center()) != numbers::invalid_material_id)
      report(cell->material_id());
}
} // namespace

void create_solid_mesh(const SolidDescription &description,
                       Triangulation<3> &triangulation)
{
  for (unsigned int k = 0; k < description.solids.size(); ++k)
  {
    const SolidItem &s = description.solids[k];
    Triangulation<3> part;
    if (s.kind == "box")
      create_box(s, description.degree, part);
    else if (s.kind == "box girder")
      create_box_girder(s, description.degree, part);
    else
    {
      read_gmsh_hexahedra(s.file, where(s), part);
      const double n = part.n_active_cells();
      check_solid_memory(s, n, hexahedra_size(n, description.degree), description.degree);
    }
    for (const auto &cell : part.active_cell_iterators())
      cell->set_material_id(k);
    if (triangulation.n_active_cells() == 0)
      triangulation.copy_triangulation(part);
    else
    {
      refuse_overlap(description, triangulation, part, s);
      // solids stay apart: coincident vertices of two solids are not merged
      // (a tie joins them, never their mesh), so each keeps its own DoFs
      Triangulation<3> merged;
      GridGenerator::merge_triangulations(triangulation, part, merged, 0.);
      triangulation.clear();
      triangulation.copy_triangulation(merged);
    }
  }
}
} // namespace hati

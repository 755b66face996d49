#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <hati/model/frame_solids.h>
#include <hati/model/solid_cuts.h>
#include <hati/model/solid_mesh.h>
#include <hati/model/solid_stress_output.h>
#include <hati/model/solid_tie.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

namespace hati
{
namespace
{
/** The global DoFs of @p cell: its DoFHandler's plus @p offset. */
void global_dofs(const DoFHandler<3>::active_cell_iterator &cell,
                 const types::global_dof_index offset,
                 std::vector<types::global_dof_index> &dofs)
{
  cell->get_dof_indices(dofs);
  for (auto &d : dofs)
    d += offset;
}

/**
 * A key of a cell's shape (vertex offsets from its first vertex, rounded to
 * 1e-9 of its size) and material: equal keys have equal element matrices.
 */
std::vector<long long> shape_key(const DoFHandler<3>::active_cell_iterator &cell)
{
  const double h = cell->diameter();
  std::vector<long long> key{static_cast<long long>(cell->material_id())};
  for (unsigned int v = 1; v < cell->n_vertices(); ++v)
    for (unsigned int k = 0; k < 3; ++k)
      key.push_back(std::llround((cell->vertex(v)[k] - cell->vertex(0)[k]) / h * 1e9));
  key.push_back(std::llround(std::log(h) * 1e9));
  return key;
}

/**
 * The node of solid @p solid (material id) nearest to @p point among the
 * support points of @p dof_handler's cells: its translations' DoFs (plus
 * @p offset) and its place.
 */
FrameSolids::MonitorNode nearest_node(const DoFHandler<3> &dof_handler,
                                      const unsigned int solid,
                                      const Point<3> &point,
                                      const types::global_dof_index offset)
{
  const auto &fe = dof_handler.get_fe();
  const auto &unit = fe.base_element(0).get_unit_support_points();
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  FrameSolids::MonitorNode best;
  best.distance = std::numeric_limits<double>::max();
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    if (cell->material_id() != solid)
      continue;
    best.cell_size = std::max(best.cell_size, cell->diameter());
    cell->get_dof_indices(dofs);
    for (unsigned int k = 0; k < unit.size(); ++k)
    {
      // the cells are mapped by their vertices (MappingQ1)
      Point<3> x;
      for (const unsigned int v : cell->vertex_indices())
        x += GeometryInfo<3>::d_linear_shape_function(unit[k], v) * cell->vertex(v);
      const double d = x.distance(point);
      if (d < best.distance)
      {
        best.distance = d;
        best.node = x;
        for (unsigned int c = 0; c < 3; ++c)
          best.dofs[c] = dofs[fe.component_to_system_index(c, k)] + offset;
      }
    }
  }
  return best;
}

/**
 * The faces a plane's `walls` leaves out: those inside the box girder's
 * hollow (in_box_girder_hollow()); none without `walls`. Throws a one-line
 * error starting with @p where if the solid is not a box girder.
 */
std::function<bool(const Point<3> &)>
skipped_faces(const SolidDescription::FacePlane &plane,
              const SolidDescription::Solid &solid,
              const double tolerance,
              const std::string &where)
{
  if (!plane.walls)
    return {};
  AssertThrow(solid.kind == "box girder",
              ExcMessage(where + ": 'walls' needs a box girder solid ('" + solid.name +
                         "' is a " + solid.kind + ")"));
  return [&solid, tolerance](const Point<3> &x)
  { return in_box_girder_hollow(solid, x, tolerance); };
}

/** The index of every solid by name. */
std::map<std::string, unsigned int> solid_index(const SolidDescription &d)
{
  std::map<std::string, unsigned int> index;
  for (unsigned int k = 0; k < d.solids.size(); ++k)
    index[d.solids[k].name] = k;
  return index;
}
} // namespace

FrameSolids::FrameSolids(const FrameDescription &frame,
                         const types::global_dof_index offset)
    : frame(frame), fe(FE_Q<3>(frame.solids.degree), 3), first_dof(offset)
{
  for (const auto &s : frame.solids.solids)
  {
    const FrameMaterial &m = frame.materials.at(s.material);
    const double nu = m.E / (2. * m.G) - 1.;
    materials.push_back({m.E * nu / ((1. + nu) * (1. - 2. * nu)), m.G, m.rho});
  }
  create_solid_mesh(frame.solids, triangulation);
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(fe);
  const auto index = solid_index(frame.solids);
  for (const auto &m : frame.solids.monitors)
  {
    monitors.push_back(nearest_node(dof_handler, index.at(m.solid), m.point, offset));
    monitors.back().name = m.name;
  }
  output = std::make_unique<SolidStressOutput>(*this);
  cut_output = std::make_unique<SolidCuts>(*this, frame.solids);
}

FrameSolids::~FrameSolids() = default;

void FrameSolids::add_supports(AffineConstraints<double> &constraints) const
{
  const double tolerance = 1e-9 * std::max(size(), 1.);
  const auto index = solid_index(frame.solids);
  // every translation of the face's DoFs
  for (const auto &plane : frame.solids.supports)
  {
    const std::string where = "Model/Frame/Solid supports: solid '" + plane.solid + "'";
    SolidDescription::FacePlane whole = plane;
    whole.radius = -1.;
    const unsigned int solid = index.at(plane.solid);
    const auto skip = skipped_faces(plane, frame.solids.solids[solid], tolerance, where);
    const FaceMoments all =
        face_moments(dof_handler, solid, whole, Point<3>(), tolerance, 0, skip);
    const FaceMoments face =
        face_moments(dof_handler, solid, plane, all.centroid, tolerance, first_dof, skip);
    AssertThrow(face.n_faces > 0,
                ExcMessage(where + ": no face of the solid's boundary lies on that plane "
                                   "(within the radius)"));
    for (const auto dof : face.dofs)
      if (!constraints.is_constrained(dof))
        constraints.add_line(dof);
  }
}

std::vector<LinkRows> FrameSolids::ties(
    const std::map<std::string, std::array<types::global_dof_index, 6>> &node_dofs) const
{
  const double tolerance = 1e-9 * std::max(size(), 1.);
  const auto index = solid_index(frame.solids);
  std::vector<LinkRows> links;
  for (const auto &tie : frame.solids.ties)
  {
    const std::string where = "Model/Frame/Ties: tie '" + tie.name + "'";
    const Point<3> &x = frame.nodes.at(tie.node);
    Point<3> projection = x;
    projection[tie.face.axis] = tie.face.value;
    const unsigned int solid = index.at(tie.face.solid);
    const FaceMoments face = face_moments(
        dof_handler,
        solid,
        tie.face,
        projection,
        tolerance,
        first_dof,
        skipped_faces(tie.face, frame.solids.solids[solid], tolerance, where));
    links.push_back({tie.name, node_dofs.at(tie.node), tie_rows(face, x, where)});
  }
  return links;
}

void FrameSolids::add_pattern(const AffineConstraints<double> &constraints,
                              DynamicSparsityPattern &pattern) const
{
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    global_dofs(cell, first_dof, dofs);
    constraints.add_entries_local_to_global(dofs, pattern, false);
  }
}

void FrameSolids::assemble(const AffineConstraints<double> &constraints,
                           DiscreteSystem &system,
                           double &omega2,
                           double &mass,
                           const std::vector<bool> &owned) const
{
  const QGauss<3> quadrature(fe.degree + 1);
  FEValues<3> values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
  const unsigned int n = fe.n_dofs_per_cell();
  FullMatrix<double> ke(n, n), me(n, n);
  Vector<double> lumped(n), influence(n);
  std::vector<types::global_dof_index> dofs(n);
  std::vector<unsigned int> component(n);
  for (unsigned int i = 0; i < n; ++i)
    component[i] = fe.system_to_component_index(i).first;
  std::map<std::vector<long long>, double> bounds;
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    if (!owned.empty() && !owned[cell->active_cell_index()])
      continue;
    const Material &m = materials[cell->material_id()];
    values.reinit(cell);
    ke = 0.;
    me = 0.;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const double w = values.JxW(q);
      for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int ci = component[i];
        const Tensor<1, 3> gi = values.shape_grad(i, q);
        for (unsigned int j = 0; j < n; ++j)
        {
          const unsigned int cj = component[j];
          const Tensor<1, 3> gj = values.shape_grad(j, q);
          // step-8: lambda div div + mu (grad_i . grad_j delta + transposed)
          double k = m.lambda * gi[ci] * gj[cj] + m.mu * gi[cj] * gj[ci];
          if (ci == cj)
          {
            k += m.mu * (gi * gj);
            me(i, j) += m.rho * values.shape_value(i, q) * values.shape_value(j, q) * w;
          }
          ke(i, j) += k * w;
        }
      }
    }
    for (unsigned int i = 0; i < n; ++i)
    {
      lumped[i] = 0.;
      for (unsigned int j = 0; j < n; ++j)
        lumped[i] += me(i, j);
      mass += component[i] == 0 ? lumped[i] : 0.;
    }
    global_dofs(cell, first_dof, dofs);
    constraints.distribute_local_to_global(ke, dofs, system.stiffness);
    constraints.distribute_local_to_global(me, dofs, system.consistent_mass);
    constraints.distribute_local_to_global(lumped, dofs, system.lumped_mass);
    // M r_d element by element (the inertia coupled to supported DoFs kept)
    for (unsigned int d = 0; d < 3; ++d)
    {
      for (unsigned int i = 0; i < n; ++i)
      {
        influence[i] = 0.;
        for (unsigned int j = 0; j < n; ++j)
          if (component[j] == d)
            influence[i] += me(i, j);
      }
      constraints.distribute_local_to_global(influence, dofs, system.mass_influence[d]);
    }
    // the element bound of omega^2, once per cell shape
    const auto key = shape_key(cell);
    auto known = bounds.find(key);
    if (known == bounds.end())
      known = bounds
                  .emplace(key,
                           element_omega_squared(
                               ke, std::vector<double>(lumped.begin(), lumped.end())))
                  .first;
    omega2 = std::max(omega2, known->second);
  }
}

void FrameSolids::add_influence(const std::vector<bool> &fixed,
                                std::array<Vector<double>, 3> &influence) const
{
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    global_dofs(cell, first_dof, dofs);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (!fixed[dofs[i]])
        influence[fe.system_to_component_index(i).first][dofs[i]] = 1.;
  }
}

void FrameSolids::stresses(const Vector<double> &U,
                           std::vector<SymmetricTensor<2, 3>> &stress,
                           std::vector<Point<3>> &points) const
{
  // the geometry is fixed: every cell's DoFs and the inverse Jacobians and
  // points of its quadrature points are kept from the first call; the
  // displacement gradient is summed on the reference cell (the scalar shape
  // gradients of FE_Q(p) are the same for every cell), then mapped,
  // grad u = (sum_b u_b grad_ref phi_b) J^-1 (the stress envelope of the 3D
  // crane's 1530 cells at every section-force row)
  const QGauss<3> quadrature(fe.degree + 1);
  const unsigned int n = fe.n_dofs_per_cell(), n_q = quadrature.size();
  const unsigned int n_b = n / 3; // scalar shape functions (FE_Q(p)^3)
  StressPoints &cache = stress_points;
  if (cache.points.empty())
    fill_stress_points(quadrature);
  // per cell: u by component and scalar shape function, then at each point
  // the nine sums over the scalar functions b, in registers. Each sum runs
  // over b in the order of the system's DoFs from 0, as the sum over the
  // cell's DoFs did: the same results, bitwise
  std::vector<double> u(3 * n_b);
  stress.resize(cache.points.size());
  points = cache.points;
  const unsigned int n_cells = cache.dofs.size() / n;
  for (unsigned int cell = 0; cell < n_cells; ++cell)
  {
    const types::global_dof_index *const dofs = &cache.dofs[std::size_t(cell) * n];
    for (unsigned int i = 0; i < n; ++i)
      u[cache.components[i] * n_b + cache.scalar_index[i]] = U[dofs[i]];
    const double *const u0 = u.data(), *const u1 = u0 + n_b, *const u2 = u1 + n_b;
    const unsigned int first = cell * n_q;
    for (unsigned int q = 0; q < n_q; ++q)
    {
      double s[3][3] = {};
      const double *const phi = &cache.reference_gradients[q * n_b * 3];
      for (unsigned int b = 0; b < n_b; ++b)
      {
        const double p0 = phi[3 * b], p1 = phi[3 * b + 1], p2 = phi[3 * b + 2];
        const double a0 = u0[b], a1 = u1[b], a2 = u2[b];
        s[0][0] += a0 * p0, s[0][1] += a0 * p1, s[0][2] += a0 * p2;
        s[1][0] += a1 * p0, s[1][1] += a1 * p1, s[1][2] += a1 * p2;
        s[2][0] += a2 * p0, s[2][1] += a2 * p1, s[2][2] += a2 * p2;
      }
      Tensor<2, 3> reference_grad;
      for (unsigned int c = 0; c < 3; ++c)
        for (unsigned int d = 0; d < 3; ++d)
          reference_grad[c][d] = s[c][d];
      stress[first + q] =
          this->stress(cache.materials[cell],
                       symmetrize(reference_grad * cache.inverse_jacobians[first + q]));
    }
  }
}

void FrameSolids::fill_stress_points(const Quadrature<3> &quadrature) const
{
  StressPoints &cache = stress_points;
  const unsigned int n = fe.n_dofs_per_cell(), n_q = quadrature.size();
  FEValues<3> values(fe, quadrature, update_inverse_jacobians | update_quadrature_points);
  std::vector<types::global_dof_index> dofs(n);
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    AssertThrow(cell->active_cell_index() * n == cache.dofs.size(), ExcInternalError());
    values.reinit(cell);
    for (unsigned int q = 0; q < n_q; ++q)
    {
      cache.points.push_back(values.quadrature_point(q));
      cache.inverse_jacobians.push_back(Tensor<2, 3>(values.inverse_jacobian(q)));
    }
    global_dofs(cell, first_dof, dofs);
    cache.dofs.insert(cache.dofs.end(), dofs.begin(), dofs.end());
    cache.materials.push_back(cell->material_id());
  }
  const FiniteElement<3> &scalar = fe.base_element(0);
  AssertThrow(fe.n_base_elements() == 1 && fe.element_multiplicity(0) == 3 &&
                  scalar.n_dofs_per_cell() * 3 == n,
              ExcInternalError());
  const unsigned int n_b = scalar.n_dofs_per_cell();
  cache.components.resize(n);
  cache.scalar_index.resize(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    cache.components[i] = fe.system_to_component_index(i).first;
    cache.scalar_index[i] = fe.system_to_component_index(i).second;
  }
  cache.reference_gradients.resize(n_b * 3 * n_q);
  for (unsigned int b = 0; b < n_b; ++b)
    for (unsigned int q = 0; q < n_q; ++q)
    {
      const Tensor<1, 3> g = scalar.shape_grad(b, quadrature.point(q));
      for (unsigned int d = 0; d < 3; ++d)
        cache.reference_gradients[(q * n_b + b) * 3 + d] = g[d];
    }
}

std::vector<Point<3>> FrameSolids::cell_centres() const
{
  std::vector<Point<3>> centres(triangulation.n_active_cells());
  for (const auto &cell : triangulation.active_cell_iterators())
    centres[cell->active_cell_index()] = cell->center();
  return centres;
}

std::vector<unsigned int> FrameSolids::cell_solids() const
{
  std::vector<unsigned int> solid(triangulation.n_active_cells());
  for (const auto &cell : triangulation.active_cell_iterators())
    solid[cell->active_cell_index()] = cell->material_id();
  return solid;
}

double FrameSolids::size() const
{
  const auto box = GridTools::compute_bounding_box(triangulation);
  return box.get_boundary_points().first.distance(box.get_boundary_points().second);
}

std::string FrameSolids::description() const
{
  std::ostringstream s;
  s << frame.solids.solids.size()
    << (frame.solids.solids.size() == 1 ? " solid: " : " solids: ")
    << triangulation.n_active_cells() << " hexahedra of degree " << fe.degree << ", "
    << dof_handler.n_dofs() << " DoFs";
  for (unsigned int k = 0; k < monitors.size(); ++k)
  {
    const auto &m = monitors[k];
    s << ", monitor '" << m.name << "' at the node (" << m.node[0] << ", " << m.node[1]
      << ", " << m.node[2] << ") m, " << m.distance << " m from ("
      << frame.solids.monitors[k].point[0] << ", " << frame.solids.monitors[k].point[1]
      << ", " << frame.solids.monitors[k].point[2] << ")";
  }
  return s.str();
}
} // namespace hati

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>

#include <hati/model/continuum.h>
#include <hati/model/memory_estimate.h>

#include <cmath>
#include <sstream>

namespace hati
{
namespace
{
/** Read the entries that `Model/Bar` and `Model/Solid` both have. */
template <int dim>
void parse_shared_entries(ParameterHandler &prm, ContinuumParameters<dim> &parameters)
{
  parameters.length = prm.get_double("Length");
  parameters.young_modulus = prm.get_double("Young's modulus");
  parameters.density = prm.get_double("Density");
  parameters.initial_velocity = prm.get_double("Initial velocity");
}
} // namespace

void ContinuumParameters<1>::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Length", "1", Patterns::Double(0.), "Bar length L (m), > 0.");
  prm.declare_entry(
      "Cross-section area", "1e-4", Patterns::Double(0.), "Area A (m^2), > 0.");
  prm.declare_entry("Young's modulus", "2e11", Patterns::Double(0.), "E (Pa), > 0.");
  prm.declare_entry("Density", "7800", Patterns::Double(0.), "rho (kg/m^3), > 0.");
  prm.declare_entry("Number of elements",
                    "100",
                    Patterns::Integer(1),
                    "Number of linear elements along the bar (-).");
  prm.declare_entry(
      "Initial velocity",
      "1",
      Patterns::Double(),
      "Uniform velocity v0 at t = 0 (m/s), positive towards the wall (+x).");
  prm.declare_entry("Left end",
                    "free",
                    Patterns::Selection("free|fixed"),
                    "The end x = 0: free, or fixed (clamped: u = 0).");
  prm.declare_entry("End force",
                    "0",
                    Patterns::Double(),
                    "Constant force at the end x = L along +x, applied from t = 0 (N); "
                    "0: none.");
  prm.declare_entry("Wall",
                    "true",
                    Patterns::Bool(),
                    "Whether the rigid wall at x = L + Contact/Initial gap exists (the "
                    "contact of the bar-impact benchmark); false: no contact.");
}

void ContinuumParameters<1>::parse_parameters(ParameterHandler &prm)
{
  parse_shared_entries(prm, *this);
  area = prm.get_double("Cross-section area");
  const long elements = prm.get_integer("Number of elements");
  AssertThrow(elements >= 1 && elements <= 100000000,
              ExcMessage("Model/Bar/Number of elements must be from 1 to 1e8, got " +
                         std::to_string(elements)));
  n_elements = elements;
  left_end = prm.get("Left end");
  end_force = prm.get_double("End force");
  wall = prm.get_bool("Wall");
  AssertThrow(length > 0. && area > 0. && young_modulus > 0. && density > 0.,
              ExcMessage("Model/Bar: Length, Cross-section area, Young's modulus and "
                         "Density must all be > 0."));
}

void ContinuumParameters<3>::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Length", "0.2", Patterns::Double(0.), "Length L along x (m), > 0.");
  prm.declare_entry("Width", "0.02", Patterns::Double(0.), "Width b along y (m), > 0.");
  prm.declare_entry("Height", "0.02", Patterns::Double(0.), "Height h along z (m), > 0.");
  prm.declare_entry("Young's modulus", "2e11", Patterns::Double(0.), "E (Pa), > 0.");
  prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(0., 0.499), "nu (-).");
  prm.declare_entry("Density", "8000", Patterns::Double(0.), "rho (kg/m^3), > 0.");
  prm.declare_entry("Number of elements",
                    "40",
                    Patterns::Integer(1),
                    "Number of trilinear elements along the length (-).");
  prm.declare_entry("Number of elements across",
                    "2",
                    Patterns::Integer(1),
                    "Number of elements along the width and along the height (-).");
  prm.declare_entry("Lateral constraint",
                    "true",
                    Patterns::Bool(),
                    "Fix the normal displacement of the four lateral faces (sliding "
                    "supports): uniaxial strain, waves at the P-wave speed "
                    "sqrt(E (1-nu) / (rho (1+nu) (1-2 nu))). false: free lateral faces, "
                    "long waves at the bar speed sqrt(E / rho) with lateral inertia.");
  prm.declare_entry(
      "Initial velocity",
      "100",
      Patterns::Double(),
      "Uniform velocity v0 at t = 0 (m/s), positive towards the wall (+x).");
}

void ContinuumParameters<3>::parse_parameters(ParameterHandler &prm)
{
  parse_shared_entries(prm, *this);
  width = prm.get_double("Width");
  height = prm.get_double("Height");
  poisson_ratio = prm.get_double("Poisson's ratio");
  const long along = prm.get_integer("Number of elements"),
             across = prm.get_integer("Number of elements across");
  AssertThrow(along >= 1 && across >= 1 && double(along) * across * across <= 1e7,
              ExcMessage("Model/Solid: Number of elements (" + std::to_string(along) +
                         ") times Number of elements across squared (" +
                         std::to_string(across) + "^2) must be from 1 to 1e7 cells"));
  n_elements = along;
  n_elements_across = across;
  lateral_constraint = prm.get_bool("Lateral constraint");
  AssertThrow(
      length > 0. && width > 0. && height > 0. && young_modulus > 0. && density > 0.,
      ExcMessage("Model/Solid: Length, Width, Height, Young's modulus and Density "
                 "must all be > 0."));
}

template <int dim>
Continuum<dim>::Continuum(const Parameters &parameters)
    : parameters(parameters), fe(FE_Q<dim>(1), dim)
{
}

template <> void Continuum<1>::make_grid()
{
  // refuse before allocating: n + 1 DoFs, 3 nonzeros per row
  const double n = parameters.n_elements;
  check_memory_estimate("Model/Bar/Number of elements", n, n + 1., 3. * (n + 1.));
  GridGenerator::subdivided_hyper_cube(
      triangulation, parameters.n_elements, 0., parameters.length);
}

template <> void Continuum<3>::make_grid()
{
  const double L = parameters.length, b = parameters.width, h = parameters.height;
  const unsigned int na = parameters.n_elements_across;
  // refuse before allocating: nx x na x na cells, 3 DoFs per vertex, and
  // each vertex couples with the 3 x 3 x 3 (fewer on the boundary) vertices
  // of its cells: (3 nx + 1)(3 na + 1)^2 vertex pairs of 3 x 3 nonzeros
  const double nx = parameters.n_elements, n_across = na;
  check_memory_estimate("Model/Solid/Number of elements and Number of elements across",
                        nx * n_across * n_across,
                        3. * (nx + 1.) * (n_across + 1.) * (n_across + 1.),
                        9. * (3. * nx + 1.) * (3. * n_across + 1.) *
                            (3. * n_across + 1.));
  // colorized boundary ids: 0 x = 0, 1 x = L, 2/3 y = -+b/2, 4/5 z = -+h/2
  GridGenerator::subdivided_hyper_rectangle(triangulation,
                                            {parameters.n_elements, na, na},
                                            Point<3>(0., -b / 2, -h / 2),
                                            Point<3>(L, b / 2, h / 2),
                                            true);
}

template <>
void Continuum<1>::assemble(const CommonModelParameters &common,
                            DiscreteSystem &system) const
{
  const double EA = parameters.young_modulus * parameters.area;
  const double rhoA = parameters.density * parameters.area;
  assemble_cells(
      common,
      rhoA,
      [EA](const Tensor<1, 1> &gi,
           const Tensor<1, 1> &gj,
           const unsigned int,
           const unsigned int) { return EA * gi[0] * gj[0]; },
      system);
}

template <>
void Continuum<3>::assemble(const CommonModelParameters &common,
                            DiscreteSystem &system) const
{
  const double E = parameters.young_modulus, nu = parameters.poisson_ratio;
  const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu)), mu = E / (2. * (1. + nu));
  // linear elasticity (step-8): lambda div div + mu (grad + grad^T)
  assemble_cells(
      common,
      parameters.density,
      [lambda, mu](const Tensor<1, 3> &gi,
                   const Tensor<1, 3> &gj,
                   const unsigned int ci,
                   const unsigned int cj)
      {
        return lambda * gi[ci] * gj[cj] + mu * gi[cj] * gj[ci] +
               (ci == cj ? mu * (gi * gj) : 0.);
      },
      system);
}

template <int dim>
template <typename StiffnessIntegrand>
void Continuum<dim>::assemble_cells(const CommonModelParameters &common,
                                    const double mass_density,
                                    const StiffnessIntegrand &stiffness,
                                    DiscreteSystem &system) const
{
  const QGauss<dim> quadrature(2);
  FEValues<dim> fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
  const unsigned int dpc = fe.n_dofs_per_cell();
  FullMatrix<double> ke(dpc, dpc), mc(dpc, dpc);
  std::vector<double> me(dpc);
  std::vector<types::global_dof_index> dofs(dpc);
  double omega2 = 0.;
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    if (!cell_selected(cell->active_cell_index()))
      continue;
    fe_values.reinit(cell);
    ke = 0.;
    mc = 0.;
    std::fill(me.begin(), me.end(), 0.);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < dpc; ++i)
      {
        const unsigned int ci = fe.system_to_component_index(i).first;
        for (unsigned int j = 0; j < dpc; ++j)
        {
          const unsigned int cj = fe.system_to_component_index(j).first;
          ke(i, j) +=
              stiffness(fe_values.shape_grad(i, q), fe_values.shape_grad(j, q), ci, cj) *
              fe_values.JxW(q);
          if (ci == cj) // lumped mass: row sums of the consistent mass
          {
            const double m = mass_density * fe_values.shape_value(i, q) *
                             fe_values.shape_value(j, q) * fe_values.JxW(q);
            mc(i, j) += m;
            me[i] += m;
          }
        }
      }
    cell->get_dof_indices(dofs);
    system.stiffness.add(dofs, ke);
    system.consistent_mass.add(dofs, mc);
    for (unsigned int i = 0; i < dpc; ++i)
    {
      system.lumped_mass[dofs[i]] += me[i];
      system.constant_force[dofs[i]] +=
          me[i] * common.gravity[fe.system_to_component_index(i).first]; // F = M g
    }
    omega2 = std::max(omega2, element_omega_squared(ke, me));
  }
  system.omega_max_bound = std::sqrt(omega2);
}

template <int dim>
typename Continuum<dim>::EndNodes
Continuum<dim>::find_end_nodes(DiscreteSystem &system) const
{
  const double L = parameters.length;
  Point<dim> left_centre, right_centre, best_left, best_right;
  right_centre[0] = L;
  for (unsigned int d = 0; d < dim; ++d)
    best_left[d] = best_right[d] = 1e300;
  EndNodes ends;
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
    {
      const Point<dim> &x = cell->vertex(v);
      const auto ix = cell->vertex_dof_index(v, 0);
      system.initial_velocity[ix] = parameters.initial_velocity;
      if (x.distance(left_centre) < best_left.distance(left_centre))
      {
        best_left = x;
        for (unsigned int c = 0; c < dim; ++c)
          ends.left[c] = cell->vertex_dof_index(v, c);
      }
      if (x.distance(right_centre) < best_right.distance(right_centre))
      {
        best_right = x;
        for (unsigned int c = 0; c < dim; ++c)
          ends.right[c] = cell->vertex_dof_index(v, c);
      }
      if (std::abs(x[0] - L) < 1e-12 * L)
        ends.face_cells[ix].push_back(cell->active_cell_index());
    }
  return ends;
}

template <>
void Continuum<1>::fix_supports(const EndNodes &ends, DiscreteSystem &system) const
{
  if (parameters.left_end == "fixed")
  {
    const auto left = ends.left[0];
    system.fixed[left] = true;
    system.initial_velocity[left] = 0.;
    system.constant_force[left] = 0.;
  }
}

template <>
void Continuum<3>::fix_supports(const EndNodes &, DiscreteSystem &system) const
{
  if (parameters.lateral_constraint)
  {
    const auto fixed_y = DoFTools::extract_boundary_dofs(
        dof_handler, ComponentMask({false, true, false}), {2, 3});
    const auto fixed_z = DoFTools::extract_boundary_dofs(
        dof_handler, ComponentMask({false, false, true}), {4, 5});
    for (const auto i : fixed_y)
      system.fixed[i] = true;
    for (const auto i : fixed_z)
      system.fixed[i] = true;
  }

  // M r_c with r_c = 1 on every DoF of component c, supported ones included,
  // so that the inertia coupled to the lateral supports is kept
  const unsigned int n = dof_handler.n_dofs();
  for (unsigned int c = 0; c < 3; ++c)
  {
    Vector<double> r(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        r[cell->vertex_dof_index(v, c)] = 1.;
    system.mass_influence[c].reinit(n);
    system.consistent_mass.vmult(system.mass_influence[c], r);
    for (unsigned int i = 0; i < n; ++i)
      if (system.fixed[i])
        system.mass_influence[c][i] = 0.;
  }
}

template <int dim>
void Continuum<dim>::build(const CommonModelParameters &common, DiscreteSystem &system)
{
  if (triangulation.n_active_cells() == 0)
  {
    make_grid();
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
  }
  const unsigned int n = dof_handler.n_dofs();
  system.reinit(n);

  DynamicSparsityPattern dsp(n, n);
  DoFTools::make_sparsity_pattern(dof_handler, dsp);
  system.stiffness_pattern.copy_from(dsp);
  system.stiffness.reinit(system.stiffness_pattern);
  system.consistent_mass.reinit(system.stiffness_pattern);
  assemble(common, system);

  const EndNodes ends = find_end_nodes(system);
  fix_supports(ends, system);
  for (unsigned int c = 0; c < dim; ++c)
    system.influence[c].reinit(n);
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      for (unsigned int c = 0; c < dim; ++c)
      {
        const auto i = cell->vertex_dof_index(v, c);
        system.influence[c][i] = system.fixed[i] ? 0. : 1.;
      }

  // the nodes of the end x = L, each on the side that owns it: the bar's
  // end force, and one contact row per node with the wall, g = g0 - u_x
  for (const auto &[ix, cells] : ends.face_cells)
    if (owns_node(cells))
    {
      if constexpr (dim == 1)
      {
        system.constant_force[ix] += parameters.end_force;
        if (!parameters.wall)
          continue;
      }
      ContactRow wall;
      wall.name = common.contact_name;
      wall.dofs = {ix};
      wall.coefficients = {-1.};
      wall.initial_gap = common.initial_gap;
      wall.restitution = common.restitution;
      system.contacts.push_back(wall);
    }

  const std::vector<std::string> axes{"x", "y", "z"};
  const std::vector<std::string> labels(axes.begin(), axes.begin() + dim);
  using Dofs = std::vector<types::global_dof_index>;
  system.monitors.push_back(
      {"impact_end", labels, Dofs(ends.right.begin(), ends.right.end()), {}});
  system.monitors.push_back(
      {"free_end", labels, Dofs(ends.left.begin(), ends.left.end()), {}});
}

template <int dim>
void Continuum<dim>::write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const
{
  const auto &[fields, time, cycle] = snapshot;
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler);
  // the components of a field form a vector (a scalar in 1D)
  const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     dim == 1 ? DataComponentInterpretation::component_is_scalar
                              : DataComponentInterpretation::component_is_part_of_vector);
  for (const auto &f : fields)
    data_out.add_data_vector(*f.second,
                             std::vector<std::string>(dim, f.first),
                             DataOut<dim>::type_dof_data,
                             interpretation);
  const Vector<float> subdomain = subdomain_field();
  if (subdomain.size() > 0)
    data_out.add_data_vector(subdomain, "subdomain", DataOut<dim>::type_cell_data);
  data_out.build_patches();
  data_out.set_flags(DataOutBase::VtkFlags(time, cycle));
  data_out.write_vtu(out);
}

template <int dim> std::vector<Point<3>> Continuum<dim>::cell_centres() const
{
  std::vector<Point<3>> centres(triangulation.n_active_cells());
  for (const auto &cell : triangulation.active_cell_iterators())
  {
    const Point<dim> centre = cell->center();
    for (unsigned int d = 0; d < dim; ++d)
      centres[cell->active_cell_index()][d] = centre[d];
  }
  return centres;
}

template <int dim> double Continuum<dim>::size() const
{
  const auto box = GridTools::compute_bounding_box(triangulation);
  return box.get_boundary_points().first.distance(box.get_boundary_points().second);
}

template <int dim>
DofDescription Continuum<dim>::describe_dof(const types::global_dof_index dof) const
{
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      for (unsigned int c = 0; c < dim; ++c)
        if (cell->vertex_dof_index(v, c) == dof)
        {
          std::ostringstream where;
          where << "the node " << (dim == 1 ? "x = " : "(");
          for (unsigned int d = 0; d < dim; ++d)
            where << (d > 0 ? ", " : "") << cell->vertex(v)[d];
          where << (dim == 1 ? " m" : ") m");
          return {std::string("u") + "xyz"[c], where.str(), false};
        }
  return {};
}

template <> std::string Continuum<1>::description() const
{
  std::ostringstream s;
  s << "1D elastic bar L = " << parameters.length << " m, " << parameters.n_elements
    << " linear elements, c = "
    << std::sqrt(parameters.young_modulus / parameters.density) << " m/s";
  return s.str();
}

template <> std::string Continuum<3>::description() const
{
  const double E = parameters.young_modulus, nu = parameters.poisson_ratio;
  std::ostringstream s;
  s << "3D elastic prism " << parameters.length << " x " << parameters.width << " x "
    << parameters.height << " m, " << parameters.n_elements << " x "
    << parameters.n_elements_across << " x " << parameters.n_elements_across
    << " trilinear elements, c_bar = " << std::sqrt(E / parameters.density)
    << " m/s, c_P = "
    << std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * parameters.density)) << " m/s"
    << (parameters.lateral_constraint ? ", laterally constrained" : "");
  return s.str();
}

template class Continuum<1>;
template class Continuum<3>;
} // namespace hati

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>

#include <hati/model/memory_estimate.h>
#include <hati/model/solid.h>

#include <cmath>
#include <sstream>

namespace hati
{
void Solid::Parameters::declare_parameters(ParameterHandler &prm)
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

void Solid::Parameters::parse_parameters(ParameterHandler &prm)
{
  length = prm.get_double("Length");
  width = prm.get_double("Width");
  height = prm.get_double("Height");
  young_modulus = prm.get_double("Young's modulus");
  poisson_ratio = prm.get_double("Poisson's ratio");
  density = prm.get_double("Density");
  const long along = prm.get_integer("Number of elements"),
             across = prm.get_integer("Number of elements across");
  AssertThrow(along >= 1 && across >= 1 && double(along) * across * across <= 1e7,
              ExcMessage("Model/Solid: Number of elements (" + std::to_string(along) +
                         ") times Number of elements across squared (" +
                         std::to_string(across) + "^2) must be from 1 to 1e7 cells"));
  n_elements = along;
  n_elements_across = across;
  lateral_constraint = prm.get_bool("Lateral constraint");
  initial_velocity = prm.get_double("Initial velocity");
  AssertThrow(
      length > 0. && width > 0. && height > 0. && young_modulus > 0. && density > 0.,
      ExcMessage("Model/Solid: Length, Width, Height, Young's modulus and Density "
                 "must all be > 0."));
}

Solid::Solid(const Parameters &parameters) : parameters(parameters), fe(FE_Q<3>(1), 3) {}

void Solid::build(const CommonModelParameters &common, DiscreteSystem &system)
{
  const double L = parameters.length, b = parameters.width, h = parameters.height;
  const unsigned int na = parameters.n_elements_across;
  // colorized boundary ids: 0 x = 0, 1 x = L, 2/3 y = -+b/2, 4/5 z = -+h/2
  if (triangulation.n_active_cells() == 0)
  {
    // refuse before allocating: nx x na x na cells, 3 DoFs per vertex, and
    // each vertex couples with the 3 x 3 x 3 (fewer on the boundary) vertices
    // of its cells: (3 nx + 1)(3 na + 1)^2 vertex pairs of 3 x 3 nonzeros
    const double nx = parameters.n_elements, n_across = na;
    check_memory_estimate("Model/Solid/Number of elements and Number of elements across",
                          nx * n_across * n_across,
                          3. * (nx + 1.) * (n_across + 1.) * (n_across + 1.),
                          9. * (3. * nx + 1.) * (3. * n_across + 1.) *
                              (3. * n_across + 1.));
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {parameters.n_elements, na, na},
                                              Point<3>(0., -b / 2, -h / 2),
                                              Point<3>(L, b / 2, h / 2),
                                              true);
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

  const double E = parameters.young_modulus, nu = parameters.poisson_ratio;
  const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu)), mu = E / (2. * (1. + nu));
  const double rho = parameters.density;

  const QGauss<3> quadrature(2);
  FEValues<3> fe_values(
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
          const Tensor<1, 3> gi = fe_values.shape_grad(i, q),
                             gj = fe_values.shape_grad(j, q);
          // linear elasticity (step-8): lambda div div + mu (grad + grad^T)
          ke(i, j) += (lambda * gi[ci] * gj[cj] + mu * gi[cj] * gj[ci] +
                       (ci == cj ? mu * (gi * gj) : 0.)) *
                      fe_values.JxW(q);
          if (ci == cj) // lumped mass: row sums of the consistent mass
          {
            const double m = rho * fe_values.shape_value(i, q) *
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
  for (unsigned int c = 0; c < 3; ++c)
    system.influence[c].reinit(n);
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      for (unsigned int c = 0; c < 3; ++c)
      {
        const auto i = cell->vertex_dof_index(v, c);
        system.influence[c][i] = system.fixed[i] ? 0. : 1.;
      }

  // initial velocity along x on every node; the cells touching each node of
  // the face x = L (the owner of its contact row)
  std::vector<std::vector<unsigned int>> face_cells(n);
  Point<3> best_left(1e300, 1e300, 1e300), best_right(1e300, 1e300, 1e300);
  std::array<types::global_dof_index, 3> left{{0, 0, 0}}, right{{0, 0, 0}};
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
    {
      const Point<3> &x = cell->vertex(v);
      const auto ix = cell->vertex_dof_index(v, 0);
      system.initial_velocity[ix] = parameters.initial_velocity;
      if (x.distance(Point<3>(0, 0, 0)) < best_left.distance(Point<3>(0, 0, 0)))
      {
        best_left = x;
        for (unsigned int c = 0; c < 3; ++c)
          left[c] = cell->vertex_dof_index(v, c);
      }
      if (x.distance(Point<3>(L, 0, 0)) < best_right.distance(Point<3>(L, 0, 0)))
      {
        best_right = x;
        for (unsigned int c = 0; c < 3; ++c)
          right[c] = cell->vertex_dof_index(v, c);
      }
      if (std::abs(x[0] - L) < 1e-12 * L)
        face_cells[ix].push_back(cell->active_cell_index());
    }
  // one contact row per node of the face x = L: g = g0 - u_x
  for (unsigned int ix = 0; ix < n; ++ix)
    if (!face_cells[ix].empty() && owns_node(face_cells[ix]))
    {
      ContactRow wall;
      wall.name = common.contact_name;
      wall.dofs = {static_cast<types::global_dof_index>(ix)};
      wall.coefficients = {-1.};
      wall.initial_gap = common.initial_gap;
      wall.restitution = common.restitution;
      system.contacts.push_back(wall);
    }
  system.monitors.push_back(
      {"impact_end", {"x", "y", "z"}, {right[0], right[1], right[2]}});
  system.monitors.push_back({"free_end", {"x", "y", "z"}, {left[0], left[1], left[2]}});
}

void Solid::write_vtu(std::ostream &out,
                      const std::vector<NamedVector> &fields,
                      const double time,
                      const unsigned int cycle) const
{
  DataOut<3> data_out;
  data_out.attach_dof_handler(dof_handler);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
      3, DataComponentInterpretation::component_is_part_of_vector);
  for (const auto &f : fields)
    data_out.add_data_vector(*f.second,
                             std::vector<std::string>(3, f.first),
                             DataOut<3>::type_dof_data,
                             vector);
  const Vector<float> subdomain = subdomain_field();
  if (subdomain.size() > 0)
    data_out.add_data_vector(subdomain, "subdomain", DataOut<3>::type_cell_data);
  data_out.build_patches();
  data_out.set_flags(DataOutBase::VtkFlags(time, cycle));
  data_out.write_vtu(out);
}

std::vector<Point<3>> Solid::cell_centres() const
{
  std::vector<Point<3>> centres(triangulation.n_active_cells());
  for (const auto &cell : triangulation.active_cell_iterators())
    centres[cell->active_cell_index()] = cell->center();
  return centres;
}

std::string Solid::description() const
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
} // namespace hati

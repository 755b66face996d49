#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>

#include <hati/model/bar.h>
#include <hati/model/memory_estimate.h>

#include <cmath>
#include <sstream>

namespace hati
{
void Bar::Parameters::declare_parameters(ParameterHandler &prm)
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

void Bar::Parameters::parse_parameters(ParameterHandler &prm)
{
  length = prm.get_double("Length");
  area = prm.get_double("Cross-section area");
  young_modulus = prm.get_double("Young's modulus");
  density = prm.get_double("Density");
  const long elements = prm.get_integer("Number of elements");
  AssertThrow(elements >= 1 && elements <= 100000000,
              ExcMessage("Model/Bar/Number of elements must be from 1 to 1e8, got " +
                         std::to_string(elements)));
  n_elements = elements;
  initial_velocity = prm.get_double("Initial velocity");
  left_end = prm.get("Left end");
  end_force = prm.get_double("End force");
  wall = prm.get_bool("Wall");
  AssertThrow(length > 0. && area > 0. && young_modulus > 0. && density > 0.,
              ExcMessage("Model/Bar: Length, Cross-section area, Young's modulus and "
                         "Density must all be > 0."));
}

Bar::Bar(const Parameters &parameters) : parameters(parameters), fe(1) {}

void Bar::build(const CommonModelParameters &common, DiscreteSystem &system)
{
  if (triangulation.n_active_cells() == 0)
  {
    // refuse before allocating: n + 1 DoFs, 3 nonzeros per row
    const double n = parameters.n_elements;
    check_memory_estimate("Model/Bar/Number of elements", n, n + 1., 3. * (n + 1.));
    GridGenerator::subdivided_hyper_cube(
        triangulation, parameters.n_elements, 0., parameters.length);
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

  const QGauss<1> quadrature(2);
  FEValues<1> fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
  const unsigned int dpc = fe.n_dofs_per_cell();
  FullMatrix<double> ke(dpc, dpc), mc(dpc, dpc);
  std::vector<double> me(dpc);
  std::vector<types::global_dof_index> dofs(dpc);
  const double EA = parameters.young_modulus * parameters.area;
  const double rhoA = parameters.density * parameters.area;
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
        for (unsigned int j = 0; j < dpc; ++j)
        {
          ke(i, j) += EA * fe_values.shape_grad(i, q)[0] * fe_values.shape_grad(j, q)[0] *
                      fe_values.JxW(q);
          mc(i, j) += rhoA * fe_values.shape_value(i, q) * fe_values.shape_value(j, q) *
                      fe_values.JxW(q);
          // lumped mass: row sums of the consistent mass
          me[i] += rhoA * fe_values.shape_value(i, q) * fe_values.shape_value(j, q) *
                   fe_values.JxW(q);
        }
    cell->get_dof_indices(dofs);
    system.stiffness.add(dofs, ke);
    system.consistent_mass.add(dofs, mc);
    for (unsigned int i = 0; i < dpc; ++i)
    {
      system.lumped_mass[dofs[i]] += me[i];
      system.constant_force[dofs[i]] += me[i] * common.gravity[0]; // F = M g
    }
    omega2 = std::max(omega2, element_omega_squared(ke, me));
  }
  system.omega_max_bound = std::sqrt(omega2);

  // end nodes and the cells that touch them
  types::global_dof_index left = 0, right = 0;
  std::vector<unsigned int> right_cells;
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (unsigned int v = 0; v < 2; ++v)
    {
      if (std::abs(cell->vertex(v)[0]) < 1e-12 * parameters.length)
      {
        left = cell->vertex_dof_index(v, 0);
      }
      if (std::abs(cell->vertex(v)[0] - parameters.length) < 1e-12 * parameters.length)
      {
        right = cell->vertex_dof_index(v, 0);
        right_cells.push_back(cell->active_cell_index());
      }
    }

  system.influence[0].reinit(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    system.initial_velocity[i] = parameters.initial_velocity;
    system.influence[0][i] = 1.;
  }
  if (parameters.left_end == "fixed")
  {
    system.fixed[left] = true;
    system.influence[0][left] = 0.;
    system.initial_velocity[left] = 0.;
    system.constant_force[left] = 0.;
  }

  if (owns_node(right_cells))
  {
    system.constant_force[right] += parameters.end_force;
    if (parameters.wall)
    {
      ContactRow wall;
      wall.name = common.contact_name;
      wall.dofs = {right};
      wall.coefficients = {-1.}; // g = g0 - u(L)
      wall.initial_gap = common.initial_gap;
      wall.restitution = common.restitution;
      system.contacts.push_back(wall);
    }
  }

  system.monitors.push_back({"impact_end", {"x"}, {right}});
  system.monitors.push_back({"free_end", {"x"}, {left}});
}

void Bar::write_vtu(std::ostream &out,
                    const std::vector<NamedVector> &fields,
                    const double time,
                    const unsigned int cycle) const
{
  DataOut<1> data_out;
  data_out.attach_dof_handler(dof_handler);
  for (const auto &f : fields)
    data_out.add_data_vector(*f.second, f.first);
  const Vector<float> subdomain = subdomain_field();
  if (subdomain.size() > 0)
    data_out.add_data_vector(subdomain, "subdomain", DataOut<1>::type_cell_data);
  data_out.build_patches();
  data_out.set_flags(DataOutBase::VtkFlags(time, cycle));
  data_out.write_vtu(out);
}

std::vector<Point<3>> Bar::cell_centres() const
{
  std::vector<Point<3>> centres(triangulation.n_active_cells());
  for (const auto &cell : triangulation.active_cell_iterators())
    centres[cell->active_cell_index()] = Point<3>(cell->center()[0], 0., 0.);
  return centres;
}

std::string Bar::description() const
{
  std::ostringstream s;
  s << "1D elastic bar L = " << parameters.length << " m, " << parameters.n_elements
    << " linear elements, c = "
    << std::sqrt(parameters.young_modulus / parameters.density) << " m/s";
  return s.str();
}
} // namespace hati

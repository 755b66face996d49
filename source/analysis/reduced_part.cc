// The implicit subdomain of HATI in Craig-Bampton coordinates (C1,
// doc/theory.md 12.1; modal damping 12.3).

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hati/analysis/reduced_part.h>

#include <algorithm>
#include <cmath>

namespace hati
{
namespace
{
/** A load acting on at most this many DoFs is a point load (a node's 6). */
constexpr unsigned int point_load_dofs = 6;
/**
 * The constant force less gravity (`f - sum_d g_d M r_d`) is a point load
 * on the DoFs where it exceeds this fraction of the largest constant force
 * (round-off of the gravity part), if they are at most
 * max_constant_load_dofs; more are a distributed load, projected.
 */
constexpr double constant_load_tolerance = 1e-9;
constexpr unsigned int max_constant_load_dofs = 60;

} // namespace

std::vector<SparseRow>
ReducedImplicitPart::boundary_rows(const DiscreteSystem &full,
                                   const std::vector<SparseRow> &interface,
                                   unsigned int &n_load_rows)
{
  std::vector<SparseRow> boundary = interface;
  // DoFs already a boundary row of their own (a Boolean interface DoF)
  std::vector<bool> held(full.n_dofs(), false);
  for (const SparseRow &row : interface)
    if (row.dofs.size() == 1)
      held[row.dofs[0]] = true;
  n_load_rows = 0;
  auto add_dofs = [&](const std::vector<unsigned int> &dofs)
  {
    for (const unsigned int i : dofs)
      if (!held[i])
      {
        held[i] = true;
        boundary.push_back(unit_rows({i})[0]);
        ++n_load_rows;
      }
  };
  // constant point loads: the constant force less its gravity part
  if (full.constant_force.size() == full.n_dofs())
  {
    Vector<double> point(full.constant_force);
    for (unsigned int d = 0; d < 3; ++d)
      if (full.gravity[d] != 0. && full.mass_influence[d].size() == full.n_dofs())
        point.add(-full.gravity[d], full.mass_influence[d]);
    const double scale = full.constant_force.linfty_norm();
    std::vector<unsigned int> dofs;
    for (unsigned int i = 0; i < point.size(); ++i)
      if (!full.fixed[i] && std::abs(point[i]) > constant_load_tolerance * scale)
        dofs.push_back(i);
    if (dofs.size() <= max_constant_load_dofs)
      add_dofs(dofs);
  }
  for (const TimeDependentLoad &load : full.time_dependent_loads)
  {
    if (load.acceleration_direction >= 0)
      continue;
    std::vector<unsigned int> dofs;
    for (unsigned int i = 0; i < load.shape.size(); ++i)
      if (load.shape[i] != 0. && !full.fixed[i])
        dofs.push_back(i);
    if (dofs.size() <= point_load_dofs) // else distributed: projected as T^T f
      add_dofs(dofs);
  }
  return boundary;
}

ReducedImplicitPart::ReducedImplicitPart(const DiscreteSystem &full,
                                         const std::vector<SparseRow> &interface_rows,
                                         const CraigBamptonSettings &settings)
    : basis(full, boundary_rows(full, interface_rows, n_load_rows), settings)
{
  const unsigned int nb = basis.n_boundary(), nm = basis.n_modes(), n = full.n_dofs();
  mass_modes.assign(nm, Vector<double>(n));
  FullMatrix<double> modal_mass(nm, nm);
  Vector<double> mode(n);
  for (unsigned int a = 0; a < nm; ++a)
  {
    const ArrayView<const double> t = basis.column(nb + a);
    std::copy(t.begin(), t.end(), mode.begin());
    reduction_mass_vmult(full, mode, mass_modes[a]);
    for (unsigned int b = 0; b < nm; ++b)
      modal_mass(a, b) = basis.mass()(nb + a, nb + b);
  }
  modal_mass_inverse.reinit(nm, nm);
  if (nm > 0)
    modal_mass_inverse.invert(modal_mass);
  build_system(full);
  // the interface rows are the first boundary coordinates, with coefficient 1
  rows = unit_rows(
      [&]
      {
        std::vector<unsigned int> k(interface_rows.size());
        for (unsigned int i = 0; i < k.size(); ++i)
          k[i] = i;
        return k;
      }());
}

void ReducedImplicitPart::coordinates(const Vector<double> &u, Vector<double> &q) const
{
  const unsigned int nb = basis.n_boundary(), nm = basis.n_modes();
  q.reinit(basis.size());
  Vector<double> interior(u);
  for (unsigned int k = 0; k < nb; ++k)
  {
    q[k] = basis.boundary_rows()[k].apply(u);
    const ArrayView<const double> t = basis.column(k);
    for (unsigned int i = 0; i < interior.size(); ++i)
      interior[i] -= q[k] * t[i];
  }
  Vector<double> p(nm), eta(nm);
  for (unsigned int a = 0; a < nm; ++a)
    p[a] = mass_modes[a] * interior;
  modal_mass_inverse.vmult(eta, p);
  for (unsigned int a = 0; a < nm; ++a)
    q[nb + a] = eta[a];
}

void ReducedImplicitPart::set_modal_damping(const double ratio)
{
  AssertThrow(ratio >= 0. && ratio < 1.,
              ExcMessage("Reduction modal damping ratio must be >= 0 and < 1"));
  const unsigned int r = reduced.n_dofs();
  std::vector<double> omega_squared;
  std::vector<Vector<double>> Z;
  basis.free_interface_modes(omega_squared, Z);
  // M Z_k, then C = sum_k 2 zeta omega_k (M Z_k)(M Z_k)^T
  std::vector<Vector<double>> MZ(r, Vector<double>(r));
  for (unsigned int k = 0; k < r; ++k)
    basis.mass().vmult(MZ[k], Z[k]);
  FullMatrix<double> C(r, r);
  for (unsigned int k = 0; k < r; ++k)
  {
    const double c = 2. * ratio * std::sqrt(std::max(omega_squared[k], 0.));
    if (c == 0.)
      continue;
    for (unsigned int i = 0; i < r; ++i)
      for (unsigned int j = 0; j < r; ++j)
        C(i, j) += c * MZ[k][i] * MZ[k][j];
  }
  reduced.damping_matrix.reinit(reduced.stiffness_pattern);
  for (unsigned int i = 0; i < r; ++i)
    for (unsigned int j = 0; j < r; ++j)
      reduced.damping_matrix.set(i, j, 0.5 * (C(i, j) + C(j, i)));
}

void ReducedImplicitPart::build_system(const DiscreteSystem &full)
{
  const unsigned int r = basis.size();
  reduced.reinit(r);
  DynamicSparsityPattern dsp(r, r);
  for (unsigned int i = 0; i < r; ++i)
    for (unsigned int j = 0; j < r; ++j)
      dsp.add(i, j);
  reduced.stiffness_pattern.copy_from(dsp);
  reduced.stiffness.reinit(reduced.stiffness_pattern);
  reduced.consistent_mass.reinit(reduced.stiffness_pattern);
  for (unsigned int i = 0; i < r; ++i)
  {
    for (unsigned int j = 0; j < r; ++j)
    {
      reduced.stiffness.set(i, j, basis.stiffness()(i, j));
      reduced.consistent_mass.set(i, j, basis.mass()(i, j));
    }
    reduced.lumped_mass[i] = basis.mass()(i, i);
  }
  reduced.fixed.assign(r, false);
  reduced.lumped_mass_refusal =
      "a Craig-Bampton reduced implicit part (Model/Decomposition/Implicit reduction) "
      "has no lumped mass: use Time integration/Newmark/Mass = consistent";
  auto project = [&](const Vector<double> &f, Vector<double> &reduced_f)
  {
    if (f.size() == full.n_dofs())
      basis.project(f, reduced_f);
    else
      reduced_f.reinit(0);
  };
  project(full.constant_force, reduced.constant_force);
  reduced.gravity = full.gravity;
  for (unsigned int d = 0; d < 3; ++d)
  {
    if (full.influence[d].size() == full.n_dofs())
      coordinates(full.influence[d], reduced.influence[d]);
    project(full.mass_influence[d], reduced.mass_influence[d]);
    project(full.excited_mass_influence[d], reduced.excited_mass_influence[d]);
  }
  for (const TimeDependentLoad &load : full.time_dependent_loads)
  {
    TimeDependentLoad l;
    basis.project(load.shape, l.shape);
    l.amplitude = load.amplitude;
    l.acceleration_direction = load.acceleration_direction;
    reduced.time_dependent_loads.push_back(std::move(l));
  }
  if (full.initial_displacement.size() == full.n_dofs())
    coordinates(full.initial_displacement, reduced.initial_displacement);
  if (full.initial_velocity.size() == full.n_dofs())
    coordinates(full.initial_velocity, reduced.initial_velocity);
  reduced.start_time = full.start_time;
}

const DiscreteSystem &implicit_system(const Decomposition &decomposition)
{
  return decomposition.reduced ? decomposition.reduced->system()
                               : decomposition.parts[1].system;
}

const std::vector<SparseRow> &implicit_rows(const Decomposition &decomposition)
{
  return decomposition.reduced ? decomposition.reduced->interface_rows()
                               : decomposition.rows[1];
}
} // namespace hati

#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/base/cpu_clones.h>
#include <hati/model/discrete_system.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hati
{
void DiscreteSystem::reinit(const unsigned int n)
{
  lumped_mass.reinit(n);
  fixed.assign(n, false);
  constant_force.reinit(n);
  initial_displacement.reinit(n);
  initial_velocity.reinit(n);
  time_dependent_loads.clear();
  for (auto &r : influence)
    r.reinit(0);
  for (auto &r : mass_influence)
    r.reinit(0);
  for (auto &r : excited_mass_influence)
    r.reinit(0);
  excited_lumped_mass.reinit(0);
  gravity = Tensor<1, 3>();
  contacts.clear();
  ropes.clear();
  law_data.clear();
  monitors.clear();
}

HATI_AVX2_CLONES void DiscreteSystem::external_force(const double t,
                                                     Vector<double> &f) const
{
  // f = F_0 + sum_k a_k(t) f_k, summed in the order of the loads, in one
  // serial pass (the same sums as f = F_0, then f.add(a_k, f_k) for each k,
  // without the task scheduler of each deal.II vector operation)
  if (f.size() != constant_force.size())
    f.reinit(constant_force.size(), true);
  const unsigned int n = f.size(), n_loads = time_dependent_loads.size();
  double *__restrict out = f.data();
  const double *__restrict f0 = constant_force.data();
  if (n_loads == 0)
  {
    std::copy(f0, f0 + n, out);
    return;
  }
  thread_local std::vector<double> amplitude;
  thread_local std::vector<const double *> shape;
  amplitude.resize(n_loads);
  shape.resize(n_loads);
  for (unsigned int k = 0; k < n_loads; ++k)
  {
    amplitude[k] = time_dependent_loads[k].amplitude(t);
    shape[k] = time_dependent_loads[k].shape.data();
  }
  for (unsigned int i = 0; i < n; ++i)
  {
    double x = f0[i];
    for (unsigned int k = 0; k < n_loads; ++k)
      x += amplitude[k] * shape[k][i];
    out[i] = x;
  }
}

double DiscreteSystem::highest_frequency_bound() const
{
  if (omega_max_bound >= 0.)
    return omega_max_bound;
  if (!has_stiffness())
    return 0.;
  // Gershgorin: lambda_max(M^-1 K) <= max_i sum_j |K_ij| / m_i
  double bound = 0.;
  for (unsigned int i = 0; i < stiffness.m(); ++i)
  {
    if (fixed[i])
      continue;
    double row = 0.;
    for (auto it = stiffness.begin(i); it != stiffness.end(i); ++it)
      if (!fixed[it->column()])
        row += std::abs(it->value());
    bound = std::max(bound, row / lumped_mass[i]);
  }
  return std::sqrt(bound);
}

void DiscreteSystem::fill_default_mass_influence()
{
  for (unsigned int d = 0; d < 3; ++d)
  {
    if (mass_influence[d].size() == n_dofs() || influence[d].size() != n_dofs())
      continue;
    mass_influence[d].reinit(n_dofs());
    if (has_consistent_mass())
      consistent_mass.vmult(mass_influence[d], influence[d]);
    else
      for (unsigned int i = 0; i < n_dofs(); ++i)
        mass_influence[d][i] = lumped_mass[i] * influence[d][i];
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (fixed[i])
        mass_influence[d][i] = 0.;
  }
}

bool has_friction(const std::vector<ContactRow> &contacts)
{
  for (const auto &c : contacts)
    if (c.frictional())
      return true;
  return false;
}

unsigned int n_contacts(const std::vector<ContactRow> &contacts)
{
  return std::count_if(contacts.begin(),
                       contacts.end(),
                       [](const ContactRow &c) { return !c.constraint; });
}

void check_finite(const DiscreteSystem &system)
{
  auto finite = [](const SparseMatrix<double> &a)
  {
    if (a.empty())
      return true;
    for (unsigned int i = 0; i < a.m(); ++i)
      for (auto it = a.begin(i); it != a.end(i); ++it)
        if (!std::isfinite(it->value()))
          return false;
    return true;
  };
  const char *advice =
      ": check the material constants (E, rho), the section values and the "
      "node coordinates for values too large";
  AssertThrow(
      !system.has_stiffness() || finite(system.stiffness),
      ExcMessage(std::string("the assembled stiffness matrix has an entry that is "
                             "not finite (overflow)") +
                 advice));
  AssertThrow(finite(system.consistent_mass) &&
                  std::isfinite(system.lumped_mass.linfty_norm()),
              ExcMessage(std::string("the assembled mass matrix has an entry that is not "
                                     "finite (overflow)") +
                         advice));
  AssertThrow(std::isfinite(system.constant_force.linfty_norm()),
              ExcMessage(std::string("the assembled constant load (gravity, nodal loads) "
                                     "has an entry that is not finite (overflow)") +
                         advice));
}

void decouple_fixed_dofs(SparseMatrix<double> &matrix, const std::vector<bool> &fixed)
{
  for (unsigned int i = 0; i < matrix.m(); ++i)
    for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
    {
      const unsigned int j = it->column();
      if (i == j)
      {
        if (fixed[i] && !(it->value() > 0.))
          it->value() = 1.;
      }
      else if (fixed[i] || fixed[j])
        it->value() = 0.;
    }
}

double element_omega_squared(const FullMatrix<double> &element_stiffness,
                             const std::vector<double> &element_mass)
{
  const unsigned int n = element_mass.size();
  if (n == 2) // closed form for two DoFs
  {
    const double a = element_stiffness(0, 0) / element_mass[0],
                 d = element_stiffness(1, 1) / element_mass[1],
                 b = element_stiffness(0, 1) /
                     std::sqrt(element_mass[0] * element_mass[1]);
    return 0.5 * (a + d) + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  }
  LAPACKFullMatrix<double> a(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      a(i, j) = element_stiffness(i, j) / std::sqrt(element_mass[i] * element_mass[j]);
  Vector<double> eigenvalues;
  FullMatrix<double> eigenvectors;
  a.compute_eigenvalues_symmetric(
      -1., std::numeric_limits<double>::max(), 0., eigenvalues, eigenvectors);
  double lmax = 0.;
  for (unsigned int i = 0; i < eigenvalues.size(); ++i)
    lmax = std::max(lmax, eigenvalues[i]);
  return lmax;
}
Vector<double> DiscreteSystem::lumped_gravity_correction() const
{
  const unsigned int n = n_dofs();
  Vector<double> c(n);
  for (unsigned int d = 0; d < 3; ++d)
    if (gravity[d] != 0. && mass_influence[d].size() == n && influence[d].size() == n)
      for (unsigned int i = 0; i < n; ++i)
        c[i] += gravity[d] * (lumped_mass[i] * influence[d][i] - mass_influence[d][i]);
  return c;
}

} // namespace hati

#include <hati/loading/base_excitation.h>

namespace hati
{
void add_base_excitation(DiscreteSystem &system,
                         const std::array<std::function<double(double)>, 3> &acceleration)
{
  for (unsigned int d = 0; d < 3; ++d)
  {
    if (!acceleration[d] || system.influence[d].size() == 0)
      continue;
    TimeDependentLoad load;
    load.shape.reinit(system.n_dofs());
    if (system.has_consistent_mass())
      system.consistent_mass.vmult(load.shape, system.influence[d]);
    else
      for (unsigned int i = 0; i < system.n_dofs(); ++i)
        load.shape[i] = system.lumped_mass[i] * system.influence[d][i];
    load.shape *= -1.; // F = -M r a_g
    for (unsigned int i = 0; i < system.n_dofs(); ++i)
      if (system.fixed[i])
        load.shape[i] = 0.;
    load.amplitude = acceleration[d];
    system.time_dependent_loads.push_back(load);
  }
}

std::array<std::function<double(double)>, 3> base_acceleration_step(const Tensor<1, 3> &a,
                                                                    const double start)
{
  std::array<std::function<double(double)>, 3> f;
  for (unsigned int d = 0; d < 3; ++d)
    if (a[d] != 0.)
    {
      const double ad = a[d];
      f[d] = [ad, start](const double t) { return t >= start ? ad : 0.; };
    }
  return f;
}
} // namespace hati

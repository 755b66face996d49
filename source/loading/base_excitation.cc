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
    system.fill_default_mass_influence();
    // only the excited members' inertia (Loading/Excited members) if the
    // model restricted it
    load.shape = system.excited_mass_influence[d].size() == system.n_dofs()
                     ? system.excited_mass_influence[d]
                     : system.mass_influence[d];
    load.shape *= -1.; // F = -M r a_g
    load.amplitude = acceleration[d];
    load.acceleration_direction = d;
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

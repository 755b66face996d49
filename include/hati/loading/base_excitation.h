#ifndef hati_loading_base_excitation_h
#define hati_loading_base_excitation_h

#include <deal.II/base/tensor.h>

#include <hati/model/discrete_system.h>

#include <functional>

namespace hati
{
/**
 * Add the seismic loads of a uniform base acceleration in the relative
 * formulation (algorithms.md section 4): for each direction d with a
 * non-zero amplitude, a time-dependent load with shape `-M r_d`
 * (DiscreteSystem::mass_influence) and amplitude `a_d(t)`.
 */
void add_base_excitation(
    DiscreteSystem &system,
    const std::array<std::function<double(double)>, 3> &acceleration);

/** A step of amplitude @p a (m/s^2) starting at @p start (s), per direction. */
std::array<std::function<double(double)>, 3> base_acceleration_step(const Tensor<1, 3> &a,
                                                                    const double start);
} // namespace hati

#endif

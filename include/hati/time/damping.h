#ifndef hati_time_damping_h
#define hati_time_damping_h

#include <deal.II/base/parameter_handler.h>

#include <hati/base/registry.h>
#include <hati/time/rayleigh_damping.h>

#include <functional>

namespace hati
{
/**
 * Reads one damping model from the subsection `Time integration/Damping`
 * (the caller has entered it). Every model gives the integrators their
 * Rayleigh coefficients today; a model with a state of its own (spec A8,
 * N4) widens this type.
 */
using DampingFactory = std::function<RayleighDamping(dealii::ParameterHandler &prm)>;

/**
 * The damping models of `Time integration/Damping/Type`, registered in
 * source/time/damping.cc (one line each): today `Rayleigh`.
 */
const Registry<DampingFactory> &damping_registry();

/** Declare `Type` and the entries of every registered damping model (current subsection).
 */
void declare_damping_parameters(dealii::ParameterHandler &prm);

/** The damping of the model chosen by `Type` (current subsection). */
RayleighDamping parse_damping_parameters(dealii::ParameterHandler &prm);
} // namespace hati

#endif

#ifndef hati_time_damping_h
#define hati_time_damping_h

#include <deal.II/base/parameter_handler.h>

#include <hati/base/registry.h>
#include <hati/time/frequency_range_damping.h>
#include <hati/time/rayleigh_damping.h>

#include <functional>
#include <string>

namespace hati
{
/**
 * The damping of a transient run, as `Time integration/Damping` describes
 * it: Rayleigh coefficients (A7) or Maxwell branches of frequency-range
 * damping (A8, N4), one of the two.
 */
struct DampingModel
{
  /** The value of `Type`: `Rayleigh` or `frequency range`. */
  std::string type = "Rayleigh";
  /** Rayleigh coefficients a0, a1 (zero for frequency-range damping). */
  RayleighDamping rayleigh;
  /** The fitted branches (empty for Rayleigh damping). */
  MaxwellBranches branches;
  /** Frequency range: the target ratio (-) and its band (Hz). */
  double ratio = 0., lower_frequency = 0., upper_frequency = 0.;
  /** Largest relative deviation of the fitted ratio over the band (-). */
  double fit_error = 0.;

  /** Whether there are Maxwell branches (Type = frequency range). */
  bool frequency_range() const { return !branches.alpha.empty(); }

  /**
   * Whether the user gave a damping (a non-zero Rayleigh entry, or the
   * frequency range): the model's default damping is then not applied.
   */
  bool given() const { return rayleigh.given || frequency_range(); }
  /** Frequency range: whether the fit is within 10 % over the band (A8). */
  bool fit_acceptable() const { return fit_error <= 0.1 && branches.alpha_sum() > 0.; }
};

/**
 * Reads one damping model from the subsection `Time integration/Damping`
 * (the caller has entered it).
 */
using DampingFactory = std::function<DampingModel(dealii::ParameterHandler &prm)>;

/**
 * The damping models of `Time integration/Damping/Type`, registered in
 * source/time/damping.cc (one line each): `Rayleigh` and `frequency range`.
 */
const Registry<DampingFactory> &damping_registry();

/** Declare `Type` and the entries of every registered damping model (current subsection).
 */
void declare_damping_parameters(dealii::ParameterHandler &prm);

/**
 * Frequency-range damping (A8, N4): @p n_branches Maxwell branches fitted to
 * the ratio @p ratio over [@p lower_frequency, @p upper_frequency] (Hz) by
 * fit_maxwell_branches(); the caller checks the inputs before (0 < ratio,
 * 0 < lower < upper) and DampingModel::fit_acceptable() after.
 */
DampingModel frequency_range_damping(double ratio,
                                     double lower_frequency,
                                     double upper_frequency,
                                     unsigned int n_branches);

/** The damping of the model chosen by `Type` (current subsection). */
DampingModel parse_damping_parameters(dealii::ParameterHandler &prm);
} // namespace hati

#endif

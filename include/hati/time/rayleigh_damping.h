#ifndef hati_time_rayleigh_damping_h
#define hati_time_rayleigh_damping_h

#include <deal.II/base/parameter_handler.h>

// The damping models of `Time integration/Damping`, one header each
// (time/<name>_damping.h); the integrators (CDLagrange, Newmark,
// HATICoupling) take the Rayleigh coefficients a0, a1.
namespace hati
{
/**
 * Rayleigh damping `C = a0 M + a1 K` (algorithms.md section 2, A7), given
 * either by its two coefficients or by a damping ratio zeta reached exactly
 * at two frequencies f1, f2: with `w_i = 2 pi f_i`,
 * `a0 = 2 zeta w1 w2 / (w1 + w2)`, `a1 = 2 zeta / (w1 + w2)`
 * (the modal damping ratio is `zeta(w) = a0 / (2 w) + a1 w / 2`).
 */
struct RayleighDamping
{
  /** Mass-proportional coefficient a0 (1/s). */
  double a0 = 0.;
  /** Stiffness-proportional coefficient a1 (s). */
  double a1 = 0.;
  /**
   * Whether an entry of the subsection is non-zero (the user set the
   * damping; a model's default damping is then not applied).
   */
  bool given = false;

  /**
   * Declare "Mass coefficient", "Stiffness coefficient", "Damping ratio",
   * "First frequency" and "Second frequency" in the current subsection.
   */
  static void declare_parameters(dealii::ParameterHandler &prm);

  /**
   * Read the entries from the current subsection and compute a0, a1 from the
   * damping ratio if it is > 0. Throws if both the damping ratio and a
   * coefficient are given, or if a frequency is missing.
   */
  void parse_parameters(dealii::ParameterHandler &prm);
};
} // namespace hati

#endif

#ifndef hati_output_response_spectrum_h
#define hati_output_response_spectrum_h

#include <vector>

namespace hati
{
/**
 * The exact step of a linear single-DoF oscillator
 * `u'' + 2 xi omega u' + omega^2 u = f(t)` over an interval of length `h`
 * in which the load `f` is linear (Nigam & Jennings 1969):
 *
 *     u_1 = a11 u_0 + a12 v_0 + b11 f_0 + b12 f_1
 *     v_1 = a21 u_0 + a22 v_0 + b21 f_0 + b22 f_1
 *
 * The coefficients follow from the free response (A) and the particular
 * solution `c0 + c1 tau` of the linear load (B): with
 * `c1 = (f_1 - f_0) / (omega^2 h)`, `c0 = f_0 / omega^2 - 2 xi c1 / omega`,
 * `u_1 = A (u_0 - c0, v_0 - c1) + c0 + c1 h`, `v_1 = ... + c1`
 * (doc/user_guide.md, "Response spectra"). Underdamped only: 0 <= xi < 1.
 */
class OscillatorStep
{
public:
  /** The coefficients for @p omega (rad/s, > 0), @p xi in [0, 1) and @p h (s, > 0). */
  OscillatorStep(const double omega, const double xi, const double h);

  /** Advance (@p u, @p v) over one interval with the load @p f0 at its start, @p f1 at
   * its end. */
  void advance(double &u, double &v, const double f0, const double f1) const
  {
    const double u1 = a11 * u + a12 * v + b11 * f0 + b12 * f1;
    v = a21 * u + a22 * v + b21 * f0 + b22 * f1;
    u = u1;
  }

  double interval() const { return h; }

private:
  double h, a11, a12, a21, a22, b11, b12, b21, b22;
};

/**
 * Displacement and velocity of the oscillator (@p omega rad/s, @p xi) at
 * rest at @p times[0] under the base acceleration @p acceleration (m/s^2,
 * linear between the samples at @p times, increasing), i.e. under the load
 * `f = -a_g`: relative displacement `u` (m) and velocity `v` (m/s) at every
 * sample. The coefficients are recomputed only where the interval changes
 * (relative 1e-9).
 */
void oscillator_response(const std::vector<double> &times,
                         const std::vector<double> &acceleration,
                         const double omega,
                         const double xi,
                         std::vector<double> &u,
                         std::vector<double> &v);

/**
 * Pseudo-acceleration response spectrum of @p acceleration (m/s^2, at
 * @p times): `S_a(T) = omega^2 max_i |u_i|`, `omega = 2 pi / T`, for each
 * period of @p periods (s, > 0) at the damping ratio @p xi (m/s^2, one
 * value per period).
 */
std::vector<double> pseudo_acceleration_spectrum(const std::vector<double> &times,
                                                 const std::vector<double> &acceleration,
                                                 const std::vector<double> &periods,
                                                 const double xi);

/** @p n periods from @p first to @p last (s), equally spaced in log T. */
std::vector<double>
log_spaced_periods(const double first, const double last, const unsigned int n);
} // namespace hati

#endif

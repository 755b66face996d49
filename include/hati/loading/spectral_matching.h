#ifndef hati_loading_spectral_matching_h
#define hati_loading_spectral_matching_h

#include <cstddef>
#include <random>
#include <vector>

namespace hati
{
class DesignSpectrum;
struct ArtificialRecordParameters;

/**
 * The baseline correction of records of @p n samples @p h apart (DS4,
 * doc/theory.md 13.3): subtract the polynomial acceleration
 * `sum_{k=2}^{5} c_k k (k-1) t^(k-2) / L^k` whose displacement fits the
 * record's best (least squares) under the constraints that the corrected
 * end velocity and end displacement vanish; velocity and displacement
 * integrated exactly for an acceleration linear between the samples. The
 * correction is a linear projection, set up once (the basis, its
 * integrals and the inverse of the constrained normal equations).
 */
class BaselineCorrection
{
public:
  BaselineCorrection(const std::size_t n, const double h);
  /** Correct @p a (m/s^2, n samples) in place: a -= sum_k c_k basis(k). */
  void apply(std::vector<double> &a) const;
  /** The coefficients c_k of the correction of @p a (linear in a). */
  std::vector<double> coefficients(const std::vector<double> &a) const;
  /** The polynomial acceleration k at the samples (k < size()). */
  const std::vector<double> &basis_function(const unsigned int k) const
  {
    return basis[k];
  }
  unsigned int size() const { return basis.size(); }

private:
  const double h;
  /** The polynomial accelerations and their displacements at the samples. */
  std::vector<std::vector<double>> basis, basis_displacement;
  /** The inverse of [G C^T; C 0] (G = D D^T, C the end velocities and displacements). */
  std::vector<std::vector<double>> inverse;
  std::vector<double> end_velocity, end_displacement;
};

/** Velocity and displacement of an acceleration linear between samples @p h apart. */
void integrate_record(const std::vector<double> &a,
                      const double h,
                      std::vector<double> &v,
                      std::vector<double> &d);

/**
 * One attempt at a spectrum-compatible record (DS3, doc/theory.md 13.3):
 * the stationary Gaussian signal of the target's power spectral density
 * (sum of sinusoids with the phases drawn from @p random) under the
 * intensity envelope; twelve corrections of its Fourier amplitudes by the
 * ratio target / computed spectrum; then time-domain corrections by
 * wavelets at the times of the oscillators' peaks (Al Atik & Abrahamson
 * 2010) on the periods of matching_periods(), the peak ground
 * acceleration held at the target's zero-period value, until the largest
 * deviation of the spectrum and of the peak is at most @p tolerance or
 * @p max_iterations have passed. Returns the best record found and its
 * deviation (@p deviation) and corrections (@p iterations).
 */
std::vector<double> match_record(const DesignSpectrum &target,
                                 const ArtificialRecordParameters &parameters,
                                 const unsigned int axis,
                                 std::mt19937_64 &random,
                                 const unsigned int max_iterations,
                                 double &deviation,
                                 unsigned int &iterations);
} // namespace hati

#endif

#ifndef hati_time_frequency_range_damping_h
#define hati_time_frequency_range_damping_h

#include <vector>

namespace hati
{
/**
 * Maxwell branches of frequency-range damping (doc/theory.md, A8 and N4):
 * the internal force is `K (U + S)`, `S = sum_l alpha_l q_l`, with one
 * memory vector per branch, `dq_l/dt = V - q_l / tau_l`. The complex
 * stiffness is `K c(w)`, `c(w) = 1 + sum_l alpha_l i w tau_l / (1 + i w tau_l)`,
 * and the damping ratio at `w` is half the loss factor,
 * `xi(w) = Im c / (2 Re c)`.
 */
struct MaxwellBranches
{
  /** Branch stiffnesses alpha_l (-), relative to K; all >= 0. */
  std::vector<double> alpha;
  /** Relaxation times tau_l (s), tau_l = 1 / (2 pi f_l). */
  std::vector<double> tau;

  /** The exact damping ratio xi(w) = Im c / (2 Re c) at the frequency @p f (Hz). */
  double damping_ratio(double f) const;

  /**
   * Sum of alpha_l: at high frequency the branches act as springs of total
   * stiffness `(sum alpha) K`, so the explicit stable step is
   * `(2 / w_max) / sqrt(1 + sum alpha)` (A8).
   */
  double alpha_sum() const;
};

/** The branches fitted by fit_maxwell_branches() and how well they fit. */
struct MaxwellFit
{
  MaxwellBranches branches;
  /**
   * Largest relative deviation `|xi(f) / ratio - 1|` of the fitted ratio
   * over the band (200 log-spaced frequencies, the band's ends included).
   */
  double error = 0.;
};

/**
 * Fit @p n_branches Maxwell branches to a constant damping ratio @p ratio
 * over the band [@p lower_frequency, @p upper_frequency] (Hz), A8: the
 * relaxation times are `tau_l = 1 / (2 pi f_l)`, `f_l` log-spaced over the
 * band (both ends included; one branch: the band's geometric mean); the
 * `alpha_l >= 0` solve the non-negative least-squares problem
 * `sum_l alpha_l w tau_l / (1 + w^2 tau_l^2) = 2 ratio Re c(w)` at 60
 * log-spaced frequencies of the band, with `Re c` first taken as 1 and then
 * updated five times from the previous `alpha` (the exact loss factor
 * `Im c / Re c = 2 ratio`). The non-negative problem is solved exactly by
 * trying every set of free branches (at most 2^8).
 *
 * Requires 0 < lower_frequency < upper_frequency and
 * 1 <= n_branches <= 8; the caller checks the inputs and the error.
 */
MaxwellFit fit_maxwell_branches(double ratio,
                                double lower_frequency,
                                double upper_frequency,
                                unsigned int n_branches);
} // namespace hati

#endif

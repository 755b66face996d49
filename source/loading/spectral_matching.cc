#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/loading/artificial_records.h>
#include <hati/loading/design_spectrum.h>
#include <hati/loading/spectral_matching.h>
#include <hati/output/response_spectrum.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hati
{
using dealii::FullMatrix;
using dealii::Vector;

void integrate_record(const std::vector<double> &a,
                      const double h,
                      std::vector<double> &v,
                      std::vector<double> &d)
{
  const std::size_t n = a.size();
  v.assign(n, 0.);
  d.assign(n, 0.);
  for (std::size_t i = 0; i + 1 < n; ++i)
  {
    v[i + 1] = v[i] + 0.5 * h * (a[i] + a[i + 1]);
    d[i + 1] = d[i] + h * v[i] + h * h * (2. * a[i] + a[i + 1]) / 6.;
  }
}

BaselineCorrection::BaselineCorrection(const std::size_t n, const double h) : h(h)
{
  constexpr unsigned int n_terms = 4; // t^2 ... t^5
  const double length = h * (n - 1);
  basis.resize(n_terms);
  basis_displacement.resize(n_terms);
  for (unsigned int k = 0; k < n_terms; ++k)
  {
    const double p = k + 2.;
    basis[k].resize(n);
    for (std::size_t i = 0; i < n; ++i)
      basis[k][i] = p * (p - 1.) * std::pow(i * h / length, p - 2.) / (length * length);
    std::vector<double> v;
    integrate_record(basis[k], h, v, basis_displacement[k]);
    end_velocity.push_back(v.back());
    end_displacement.push_back(basis_displacement[k].back());
  }
  // [G C^T; C 0], G the displacements' Gram matrix, C the end values
  FullMatrix<double> kkt(n_terms + 2, n_terms + 2);
  for (unsigned int j = 0; j < n_terms; ++j)
  {
    for (unsigned int k = 0; k < n_terms; ++k)
      for (std::size_t i = 0; i < n; ++i)
        kkt(j, k) += basis_displacement[j][i] * basis_displacement[k][i];
    kkt(j, n_terms) = kkt(n_terms, j) = end_velocity[j];
    kkt(j, n_terms + 1) = kkt(n_terms + 1, j) = end_displacement[j];
  }
  kkt.gauss_jordan();
  inverse.assign(n_terms + 2, std::vector<double>(n_terms + 2));
  for (unsigned int j = 0; j < n_terms + 2; ++j)
    for (unsigned int k = 0; k < n_terms + 2; ++k)
      inverse[j][k] = kkt(j, k);
}

std::vector<double> BaselineCorrection::coefficients(const std::vector<double> &a) const
{
  const std::size_t n = a.size();
  const unsigned int n_terms = basis.size();
  std::vector<double> v, d, rhs(n_terms + 2, 0.), c(n_terms, 0.);
  integrate_record(a, h, v, d);
  for (unsigned int j = 0; j < n_terms; ++j)
    for (std::size_t i = 0; i < n; ++i)
      rhs[j] += basis_displacement[j][i] * d[i];
  rhs[n_terms] = v.back();
  rhs[n_terms + 1] = d.back();
  for (unsigned int k = 0; k < n_terms; ++k)
    for (unsigned int j = 0; j < n_terms + 2; ++j)
      c[k] += inverse[k][j] * rhs[j];
  return c;
}

void BaselineCorrection::apply(std::vector<double> &a) const
{
  if (a.size() < 3)
    return;
  const std::vector<double> c = coefficients(a);
  for (unsigned int k = 0; k < basis.size(); ++k)
    for (std::size_t i = 0; i < a.size(); ++i)
      a[i] -= c[k] * basis[k][i];
}

namespace
{
double largest_magnitude(const std::vector<double> &x)
{
  double m = 0.;
  for (const double y : x)
    m = std::max(m, std::abs(y));
  return m;
}

/** A uniform number in [0, 1) from 53 bits of @p x. */
double unit_interval(const std::uint64_t x)
{
  return double(x >> 11) * (1. / 9007199254740992.);
}

/**
 * The trapezoidal intensity envelope at @p t (-): a linear rise over a
 * quarter of the weak motion, the strong motion, a linear decay over the
 * rest.
 */
double envelope(const double t, const ArtificialRecordParameters &p)
{
  const double rise = 0.25 * (p.duration - p.strong_motion);
  const double decay = p.duration - p.strong_motion - rise;
  if (t < rise)
    return t / rise;
  if (t <= rise + p.strong_motion)
    return 1.;
  return decay > 0. ? std::max(0., (p.duration - t) / decay) : 1.;
}

/** The ratio at @p period, interpolated in log T on @p periods (constant beyond). */
double ratio_at(const double period,
                const std::vector<double> &periods,
                const std::vector<double> &ratio)
{
  if (period <= periods.front())
    return ratio.front();
  if (period >= periods.back())
    return ratio.back();
  const std::size_t i =
      std::upper_bound(periods.begin(), periods.end(), period) - periods.begin();
  const double s =
      std::log(period / periods[i - 1]) / std::log(periods[i] / periods[i - 1]);
  return ratio[i - 1] * std::pow(ratio[i] / ratio[i - 1], s);
}

/** sum_k A_k cos(w_k t + phi_k) under the envelope, baseline corrected. */
std::vector<double> synthesise(const std::vector<double> &amplitude,
                               const std::vector<double> &phase,
                               const double dw,
                               const ArtificialRecordParameters &p,
                               const BaselineCorrection &baseline,
                               const std::size_t n)
{
  std::vector<double> a(n, 0.);
  for (std::size_t k = 0; k < amplitude.size(); ++k)
  {
    const double w = (k + 1) * dw;
    // cos(w t_i + phi) by rotation, restarted every 256 samples against drift
    const double cr = std::cos(w * p.time_step), sr = std::sin(w * p.time_step);
    double c = 0., s = 0.;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (i % 256 == 0)
      {
        c = std::cos(w * i * p.time_step + phase[k]);
        s = std::sin(w * i * p.time_step + phase[k]);
      }
      a[i] += amplitude[k] * c;
      const double c1 = c * cr - s * sr;
      s = s * cr + c * sr;
      c = c1;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    a[i] *= envelope(i * p.time_step, p);
  baseline.apply(a);
  return a;
}

/**
 * The displacement x[m] of the oscillator (@p omega, @p xi) m samples after
 * a unit acceleration sample (linear between samples @p h apart): a
 * record's response is x_m = sum_i x[m - i] a_i.
 */
std::vector<double>
unit_response(const double omega, const double xi, const double h, const std::size_t n)
{
  const OscillatorStep step(omega, xi, h);
  std::vector<double> x(n, 0.);
  double u = 0., v = 0.;
  step.advance(u, v, 0., -1.);
  x[0] = u;
  for (std::size_t m = 1; m < n; ++m)
  {
    step.advance(u, v, m == 1 ? -1. : 0., 0.);
    x[m] = u;
  }
  return x;
}

/**
 * The improved tapered cosine wavelet (Al Atik & Abrahamson 2010) of the
 * oscillator (@p omega, @p xi), peaking at t_peak:
 * `cos(w'(t - t_peak + dt)) exp(-((t - t_peak + dt) / gamma)^2)`,
 * `w' = omega sqrt(1 - xi^2)`, `dt = atan(sqrt(1 - xi^2) / xi) / w'`,
 * `gamma = 1.178 f^-0.93` (f in Hz); zero where the exponent is below -40
 * (its support).
 */
struct Wavelet
{
  Wavelet(const double omega, const double xi)
      : wd(omega * std::sqrt(1. - xi * xi)),
        shift(std::atan(std::sqrt(1. - xi * xi) / xi) / wd),
        gamma(1.178 * std::pow(omega / (2. * M_PI), -0.93)),
        half_width(std::sqrt(40.) * 1.178 * std::pow(omega / (2. * M_PI), -0.93))
  {
  }

  /** The value at @p t (s) of the wavelet peaking at @p t_peak (s). */
  double operator()(const double t, const double t_peak) const
  {
    const double s = t - t_peak + shift;
    const double e = s / gamma;
    return e * e > 40. ? 0. : std::cos(wd * s) * std::exp(-e * e);
  }

  /** Its support [first, last] (s) when it peaks at @p t_peak. */
  std::pair<double, double> support(const double t_peak) const
  {
    return {t_peak - shift - half_width, t_peak - shift + half_width};
  }

  /** sqrt(40) gamma (s). */
  const double wd, shift, gamma, half_width;
};

/** The sample and signed value of the peak displacement of the oscillator under @p a. */
std::pair<std::size_t, double> peak_response(const std::vector<double> &a,
                                             const OscillatorStep &step)
{
  double u = 0., v = 0., peak = 0.;
  std::size_t at = 0;
  for (std::size_t i = 1; i < a.size(); ++i)
  {
    step.advance(u, v, -a[i - 1], -a[i]);
    if (std::abs(u) > std::abs(peak))
    {
      peak = u;
      at = i;
    }
  }
  return {at, peak};
}
} // namespace

namespace
{
/** What every step of the matching of one record needs. */
struct Matching
{
  Matching(const DesignSpectrum &target,
           const ArtificialRecordParameters &p,
           const unsigned int axis)
      : target(target), p(p), axis(axis), xi(target.parameters().damping_ratio),
        h(p.time_step), n(std::size_t(std::llround(p.duration / h)) + 1), baseline(n, h),
        periods(matching_periods(target)), pga_goal(target.zero_period_value(axis))
  {
    for (std::size_t i = 0; i < n; ++i)
      times.push_back(i * h);
    for (const double T : periods)
    {
      goal.push_back(target(T, axis));
      unit.push_back(unit_response(2. * M_PI / T, xi, h, n));
      steps.emplace_back(2. * M_PI / T, xi, h);
    }
  }

  const DesignSpectrum &target;
  const ArtificialRecordParameters &p;
  const unsigned int axis;
  const double xi, h;
  const std::size_t n;
  const BaselineCorrection baseline;
  /** The check periods (s), their target (m/s^2), the target's peak (m/s^2). */
  const std::vector<double> periods;
  std::vector<double> goal;
  const double pga_goal;
  std::vector<double> times;
  /** Each oscillator's unit response and step. */
  std::vector<std::vector<double>> unit;
  std::vector<OscillatorStep> steps;
};

/** The number of corrections of the Fourier amplitudes (DS3, step 2). */
constexpr unsigned int n_ratio_passes = 12;

/**
 * Steps 1 and 2 of DS3: the stationary signal of the target's power
 * spectral density with the phases drawn from @p random, under the
 * envelope, and its Fourier amplitudes corrected n_ratio_passes times.
 */
std::vector<double> stationary_record(const Matching &s, std::mt19937_64 &random)
{
  const double dw = 2. * M_PI / ((s.n - 1) * s.h);
  const std::size_t n_frequencies = std::size_t(M_PI / s.h / dw + 1e-9);
  std::vector<double> phase(n_frequencies), amplitude(n_frequencies);
  for (auto &phi : phase)
    phi = 2. * M_PI * unit_interval(random());
  // the target's power spectral density (Vanmarcke): G = 4 xi S_a^2 /
  // (pi w r^2), r the peak factor over the strong motion; A = sqrt(2 G dw)
  for (std::size_t k = 0; k < n_frequencies; ++k)
  {
    const double w = (k + 1) * dw, sa = s.target(2. * M_PI / w, s.axis);
    const double r = std::sqrt(
        2. * std::log(std::max(2.8 * w * s.p.strong_motion / (2. * M_PI), std::exp(1.))));
    amplitude[k] = std::sqrt(8. * s.xi * sa * sa / (M_PI * w * r * r) * dw);
  }
  // the Fourier amplitudes corrected by the ratio target / computed
  // (below the range: the peak's ratio; above it: none)
  const std::size_t m = s.periods.size();
  for (unsigned int pass = 0;; ++pass)
  {
    std::vector<double> a = synthesise(amplitude, phase, dw, s.p, s.baseline, s.n);
    if (pass == n_ratio_passes)
      return a;
    const auto computed = pseudo_acceleration_spectrum(s.times, a, s.periods, s.xi);
    std::vector<double> ratio(m);
    for (std::size_t j = 0; j < m; ++j)
      ratio[j] = s.goal[j] / std::max(computed[j], 1e-300);
    const double pga_ratio = s.pga_goal / std::max(largest_magnitude(a), 1e-300);
    for (std::size_t k = 0; k < n_frequencies; ++k)
    {
      const double period = 2. * M_PI / ((k + 1) * dw);
      amplitude[k] *=
          period < s.periods.front()
              ? pga_ratio
              : (period > s.periods.back() ? 1. : ratio_at(period, s.periods, ratio));
    }
  }
}

/**
 * Step 3 of DS3, one correction of @p a whose oscillators peak at
 * @p peaks: a wavelet per period at the time of its peak, baseline
 * corrected (the correction is linear), the amplitudes from the
 * regularised least squares of C b = dR (C_jk the response of oscillator j
 * at its peak to wavelet k, rows relative to the target, columns to a unit
 * diagonal) with rows holding the local peaks of |a| above the target's
 * peak at it. Returns the correction sum_k b_k BL(f_k) (m/s^2).
 */
std::vector<double>
wavelet_correction(const Matching &s,
                   const std::vector<double> &a,
                   const std::vector<std::pair<std::size_t, double>> &peaks)
{
  constexpr double regularisation = 1e-4;
  const std::size_t m = s.periods.size(), n = s.n;
  const unsigned int nb = s.baseline.size();
  const auto &periods = s.periods;
  const auto &goal = s.goal;
  const auto &unit = s.unit;
  const BaselineCorrection &baseline = s.baseline;
  const double xi = s.xi, h = s.h, pga_goal = s.pga_goal;
  FullMatrix<double> C(m, m), N(m, m);
  Vector<double> dR(m), rhs(m), b(m);
  std::vector<std::vector<double>> f(m, std::vector<double>(n)), c(m);
  std::vector<std::size_t> lo(m), hi(m);
  // the wavelets on their supports [lo_k, hi_k], their baseline
  // corrections c_kl basis_l (everywhere), the oscillators' responses at
  // their peaks to the basis
  for (std::size_t k = 0; k < m; ++k)
  {
    const Wavelet wavelet(2. * M_PI / periods[k], xi);
    const auto [first, last] = wavelet.support(peaks[k].first * h);
    lo[k] = std::size_t(std::max(0., std::floor(first / h)));
    hi[k] = std::size_t(std::max(0., std::min(n - 1., std::ceil(last / h))));
    std::fill(f[k].begin(), f[k].end(), 0.);
    for (std::size_t i = lo[k]; i <= hi[k]; ++i)
      f[k][i] = wavelet(i * h, peaks[k].first * h);
    c[k] = baseline.coefficients(f[k]);
  }
  std::vector<double> column_scale(m);
  for (std::size_t j = 0; j < m; ++j)
  {
    const double w = 2. * M_PI / periods[j], row = w * w / goal[j];
    const std::size_t at = peaks[j].first;
    std::vector<double> to_basis(nb, 0.);
    for (unsigned int l = 0; l < nb; ++l)
      for (std::size_t i = 1; i <= at; ++i)
        to_basis[l] += unit[j][at - i] * baseline.basis_function(l)[i];
    for (std::size_t k = 0; k < m; ++k)
    {
      double sum = 0.;
      for (std::size_t i = std::max<std::size_t>(1, lo[k]); i <= std::min(at, hi[k]); ++i)
        sum += unit[j][at - i] * f[k][i];
      for (unsigned int l = 0; l < nb; ++l)
        sum -= c[k][l] * to_basis[l];
      C(j, k) = row * sum;
    }
    const double sign = peaks[j].second < 0. ? -1. : 1.;
    dR(j) = row * (goal[j] / (w * w) - std::abs(peaks[j].second)) * sign;
  }
  for (std::size_t k = 0; k < m; ++k)
  {
    column_scale[k] = std::abs(C(k, k)) > 0. ? 1. / std::abs(C(k, k)) : 1.;
    for (std::size_t j = 0; j < m; ++j)
      C(j, k) *= column_scale[k];
  }
  C.Tmmult(N, C);
  C.Tvmult(rhs, dR);
  double trace = 0.;
  for (std::size_t j = 0; j < m; ++j)
    trace += N(j, j);
  for (std::size_t j = 0; j < m; ++j)
    N(j, j) += regularisation * trace / m;
  // the local peaks of |a| above the target's peak (or the peak below it)
  std::vector<std::size_t> tops;
  std::size_t top = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    top = std::abs(a[i]) > std::abs(a[top]) ? i : top;
    if (std::abs(a[i]) > pga_goal && (i == 0 || std::abs(a[i]) >= std::abs(a[i - 1])) &&
        (i + 1 == n || std::abs(a[i]) >= std::abs(a[i + 1])))
      tops.push_back(i);
  }
  if (tops.empty())
    tops.push_back(top);
  std::sort(tops.begin(),
            tops.end(),
            [&](const std::size_t x, const std::size_t y)
            {
              return std::abs(a[x]) > std::abs(a[y]) ||
                     (std::abs(a[x]) == std::abs(a[y]) && x < y);
            });
  tops.resize(std::min<std::size_t>(tops.size(), 30));
  Vector<double> g(m);
  for (const std::size_t i : tops)
  {
    for (std::size_t k = 0; k < m; ++k)
    {
      double fi = f[k][i];
      for (unsigned int l = 0; l < nb; ++l)
        fi -= c[k][l] * baseline.basis_function(l)[i];
      g(k) = fi * column_scale[k] / pga_goal;
    }
    const double r = ((a[i] < 0. ? -pga_goal : pga_goal) - a[i]) / pga_goal;
    for (std::size_t j = 0; j < m; ++j)
    {
      rhs(j) += g(j) * r;
      for (std::size_t k = 0; k < m; ++k)
        N(j, k) += g(j) * g(k);
    }
  }
  N.gauss_jordan();
  N.vmult(b, rhs);
  std::vector<double> step(n, 0.), basis_step(nb, 0.);
  for (std::size_t k = 0; k < m; ++k)
  {
    const double bk = b(k) * column_scale[k];
    for (std::size_t i = lo[k]; i <= hi[k]; ++i)
      step[i] += bk * f[k][i];
    for (unsigned int l = 0; l < nb; ++l)
      basis_step[l] += bk * c[k][l];
  }
  for (unsigned int l = 0; l < nb; ++l)
    for (std::size_t i = 0; i < n; ++i)
      step[i] -= basis_step[l] * s.baseline.basis_function(l)[i];
  return step;
}
} // namespace

std::vector<double> match_record(const DesignSpectrum &target,
                                 const ArtificialRecordParameters &p,
                                 const unsigned int axis,
                                 std::mt19937_64 &random,
                                 const unsigned int max_iterations,
                                 double &deviation,
                                 unsigned int &iterations)
{
  const Matching s(target, p, axis);
  const std::size_t m = s.periods.size();
  std::vector<double> a = stationary_record(s, random);
  double relax = 0.5;
  std::vector<double> best = a, last = a;
  double best_deviation = std::numeric_limits<double>::max();
  double last_rms = std::numeric_limits<double>::max();
  unsigned int improved = 0;
  iterations = n_ratio_passes;
  for (unsigned int iteration = 0;; ++iteration)
  {
    std::vector<std::pair<std::size_t, double>> peaks(m);
    double d = std::abs(largest_magnitude(a) / s.pga_goal - 1.), sum = d * d;
    for (std::size_t j = 0; j < m; ++j)
    {
      peaks[j] = peak_response(a, s.steps[j]);
      const double w = 2. * M_PI / s.periods[j];
      const double e = w * w * std::abs(peaks[j].second) / s.goal[j] - 1.;
      d = std::max(d, std::abs(e));
      sum += e * e;
    }
    const double rms = std::sqrt(sum / (m + 1));
    if (d < best_deviation)
    {
      if (d < 0.99 * best_deviation)
        improved = iteration;
      best_deviation = d;
      best = a;
    }
    if (rms <= last_rms || d <= best_deviation)
    {
      // a step that helps: kept, the next one longer
      relax = std::min(1., 1.5 * relax);
      last_rms = rms;
      last = a;
    }
    else
    {
      // worse on the whole: a shorter step from the last good record
      a = last;
      relax = std::max(0.05, 0.5 * relax);
      for (std::size_t j = 0; j < m; ++j)
        peaks[j] = peak_response(a, s.steps[j]);
    }
    // met, or no longer improving (by 1 % in 15 corrections): another draw does better
    if (best_deviation <= p.matching_tolerance || iteration == max_iterations ||
        iteration >= improved + 15)
      break;
    ++iterations;
    const std::vector<double> step = wavelet_correction(s, a, peaks);
    for (std::size_t i = 0; i < s.n; ++i)
      a[i] += relax * step[i];
  }
  deviation = best_deviation;
  return best;
}
} // namespace hati

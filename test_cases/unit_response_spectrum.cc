// Response spectra (output/response_spectrum.h, issue #18): the exact
// Nigam-Jennings recursion of a linear single-DoF oscillator against
// - the closed-form response to a sine (sampled finely enough that the
//   linear interpolation of the sine is below 1e-9 of the response),
// - the closed-form response to a piecewise-linear pulse (superposed unit
//   ramps, exact at any sampling),
// - the peak ground acceleration at T = 0.02 s (rigid oscillator, 1 %),
// - an independent time stepping (Newmark average acceleration on a 100x
//   finer step, written here) for the 5 % spectrum of El Centro.
#include <deal.II/base/mpi.h>

#include <hati/loading/accelerogram.h>
#include <hati/output/response_spectrum.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hati_unit_response_spectrum
{

using namespace hati;
using hati_test::check;

namespace
{
/** Largest |a - b| over the largest |b|. */
double normwise_error(const std::vector<double> &a, const std::vector<double> &b)
{
  double diff = 0., scale = 0.;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

void check_sine()
{
  // u'' + 2 xi w u' + w^2 u = -A sin(W t), at rest at t = 0
  for (const double xi : {0., 0.05, 0.3})
  {
    const double w = 2. * M_PI * 2., W = 2. * M_PI * 1.3, A = 3.;
    const double det = std::pow(w * w - W * W, 2) + std::pow(2. * xi * w * W, 2);
    const double C = -A * (w * w - W * W) / det, D = A * 2. * xi * w * W / det;
    const double wd = w * std::sqrt(1. - xi * xi);
    const double E = -D, F = (xi * w * E - C * W) / wd;
    std::vector<double> t, a, exact_u, exact_v, u, v;
    const double h = 2e-5;
    for (unsigned int i = 0; i <= 150000; ++i)
    {
      const double s = i * h;
      t.push_back(s);
      a.push_back(A * std::sin(W * s));
      const double e = std::exp(-xi * w * s);
      exact_u.push_back(C * std::sin(W * s) + D * std::cos(W * s) +
                        e * (E * std::cos(wd * s) + F * std::sin(wd * s)));
      exact_v.push_back(C * W * std::cos(W * s) - D * W * std::sin(W * s) +
                        e * ((-xi * w * E + wd * F) * std::cos(wd * s) +
                             (-xi * w * F - wd * E) * std::sin(wd * s)));
    }
    oscillator_response(t, a, w, xi, u, v);
    check("sine, xi = " + std::to_string(xi) + ": displacement, max error / max |u|",
          normwise_error(u, exact_u),
          0.,
          1e-8);
    check("sine, xi = " + std::to_string(xi) + ": velocity, max error / max |v|",
          normwise_error(v, exact_v),
          0.,
          1e-8);
  }
}

/** Response to the unit ramp f = t (from rest at t = 0) of the oscillator. */
double unit_ramp(const double t, const double w, const double xi)
{
  if (t <= 0.)
    return 0.;
  const double wd = w * std::sqrt(1. - xi * xi);
  return (t - 2. * xi / w) / (w * w) +
         std::exp(-xi * w * t) * (2. * xi / (w * w * w) * std::cos(wd * t) +
                                  (2. * xi * xi - 1.) / (w * w * wd) * std::sin(wd * t));
}

void check_pulse()
{
  // a_g: 0 at t = 0, 4 at 0.13 s, -1.5 at 0.29 s, 0 at 0.5 s, then 0;
  // f = -a_g is a sum of ramps with the slope changes s_k at t_k
  const std::vector<double> knots = {0., 0.13, 0.29, 0.5}, values = {0., 4., -1.5, 0.};
  std::vector<double> slope_change;
  double previous = 0.;
  for (unsigned int k = 0; k + 1 < knots.size(); ++k)
  {
    const double s = -(values[k + 1] - values[k]) / (knots[k + 1] - knots[k]);
    slope_change.push_back(s - previous);
    previous = s;
  }
  slope_change.push_back(-previous);
  for (const double xi : {0., 0.02, 0.05, 0.2})
    for (const double period : {0.05, 0.3, 2.})
    {
      const double w = 2. * M_PI / period;
      // samples: the knots and a few points of uneven spacing in between
      std::vector<double> t, a, exact, u, v;
      for (double s = 0.; s <= 3.; s += 0.0173)
        t.push_back(s);
      t.insert(t.end(), knots.begin(), knots.end());
      std::sort(t.begin(), t.end());
      t.erase(std::unique(t.begin(), t.end()), t.end());
      for (const double s : t)
      {
        double value = 0.;
        for (unsigned int k = 0; k + 1 < knots.size(); ++k)
          if (s >= knots[k] && s <= knots[k + 1])
            value = values[k] + (values[k + 1] - values[k]) * (s - knots[k]) /
                                    (knots[k + 1] - knots[k]);
        a.push_back(value);
        double x = 0.;
        for (unsigned int k = 0; k < knots.size(); ++k)
          x += slope_change[k] * unit_ramp(s - knots[k], w, xi);
        exact.push_back(x);
      }
      oscillator_response(t, a, w, xi, u, v);
      check("pulse, xi = " + std::to_string(xi) + ", T = " + std::to_string(period) +
                " s: max error / max |u|",
            normwise_error(u, exact),
            0.,
            1e-8);
    }
}

/**
 * Peak |u| at the record's samples by Newmark average acceleration with
 * @p substeps steps per record interval.
 */
double newmark_peak(const Accelerogram &record,
                    const double w,
                    const double xi,
                    const unsigned int substeps)
{
  const double h = (record.times()[1] - record.times()[0]) / substeps;
  const double end = record.times().back();
  double u = 0., v = 0., acc = -record(0.), peak = 0.;
  const double k_eff = w * w + 2. * xi * w * 2. / h + 4. / (h * h);
  const unsigned long n = std::lround(end / h);
  for (unsigned long i = 1; i <= n; ++i)
  {
    const double t = i * h;
    const double f = -record(t);
    const double rhs =
        f + (4. / (h * h) * u + 4. / h * v + acc) + 2. * xi * w * (2. / h * u + v);
    const double u1 = rhs / k_eff;
    const double v1 = 2. / h * (u1 - u) - v;
    acc = 4. / (h * h) * (u1 - u) - 4. / h * v - acc;
    u = u1;
    v = v1;
    if (i % substeps == 0) // the recursion's peak is over the samples too
      peak = std::max(peak, std::abs(u));
  }
  return peak;
}

void check_records(const std::string &source)
{
  for (const std::string name :
       {"RSN6_IMPVALL.I_I-ELC180.AT2", "Rinaldi228.AT2", "RinaldiUP.AT2"})
  {
    const Accelerogram record =
        Accelerogram::read(source + "/data/accelerograms/" + name, "g", 1.);
    const double pga = record.peak().first;
    for (const double xi : {0.02, 0.05})
      check(name + ": S_a(0.02 s), xi = " + std::to_string(xi) + " / PGA",
            pseudo_acceleration_spectrum(record.times(), record.values(), {0.02}, xi)[0] /
                pga,
            1.,
            0.01);
  }
  const Accelerogram elcentro = Accelerogram::read(
      source + "/data/accelerograms/RSN6_IMPVALL.I_I-ELC180.AT2", "g", 1.);
  const std::vector<double> periods = {0.1, 0.3, 0.5, 1., 2.};
  const auto spectrum =
      pseudo_acceleration_spectrum(elcentro.times(), elcentro.values(), periods, 0.05);
  for (unsigned int k = 0; k < periods.size(); ++k)
  {
    const double w = 2. * M_PI / periods[k];
    const double reference = w * w * newmark_peak(elcentro, w, 0.05, 100);
    check("El Centro, 5 %, T = " + std::to_string(periods[k]) +
              " s: S_a / Newmark (h = 1e-4 s)",
          spectrum[k] / reference,
          1.,
          1e-4);
  }
}
} // namespace

HATI_UNIT_TEST(response_spectrum)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
  {
    check_sine();
    check_pulse();
    check_records(HATI_SOURCE_DIR);
    const auto p = log_spaced_periods(0.02, 4., 100);
    check("log-spaced periods: first", p.front(), 0.02, 0.);
    check("log-spaced periods: last", p.back(), 4., 0.);
    check("log-spaced periods: ratio", p[1] / p[0], std::pow(200., 1. / 99.), 1e-14);
  }
  catch (const std::exception &e)
  {
    hati_test::expect(false, std::string("exception: ") + hati_test::message_of(e));
  }
  return hati_test::finish();
}
} // namespace hati_unit_response_spectrum

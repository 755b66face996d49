#include <deal.II/base/exceptions.h>

#include <hati/output/response_spectrum.h>

#include <algorithm>
#include <cmath>

namespace hati
{
OscillatorStep::OscillatorStep(const double omega, const double xi, const double h) : h(h)
{
  Assert(omega > 0. && xi >= 0. && xi < 1. && h > 0., dealii::ExcInternalError());
  // free response over h (the matrix A)
  const double root = std::sqrt(1. - xi * xi);
  const double omega_d = omega * root;
  const double e = std::exp(-xi * omega * h);
  const double s = std::sin(omega_d * h), c = std::cos(omega_d * h);
  a11 = e * (c + xi / root * s);
  a12 = e * s / omega_d;
  a21 = -e * omega / root * s;
  a22 = e * (c - xi / root * s);
  // particular solution of f = f0 + (f1 - f0) tau / h: c0 + c1 tau with
  // c1 = (f1 - f0) / (omega^2 h), c0 = f0 / omega^2 - 2 xi c1 / omega;
  // u1 = a11 (u0 - c0) + a12 (v0 - c1) + c0 + c1 h, v1 = a21 (u0 - c0) + a22 (v0 - c1) +
  // c1
  const double w2 = omega * omega;
  // derivatives of c0 and c1 with respect to f0 and f1
  const double c1_f0 = -1. / (w2 * h), c1_f1 = 1. / (w2 * h);
  const double c0_f0 = 1. / w2 - 2. * xi / omega * c1_f0,
               c0_f1 = -2. * xi / omega * c1_f1;
  b11 = (1. - a11) * c0_f0 + (h - a12) * c1_f0;
  b12 = (1. - a11) * c0_f1 + (h - a12) * c1_f1;
  b21 = -a21 * c0_f0 + (1. - a22) * c1_f0;
  b22 = -a21 * c0_f1 + (1. - a22) * c1_f1;
}

void oscillator_response(const std::vector<double> &times,
                         const std::vector<double> &acceleration,
                         const double omega,
                         const double xi,
                         std::vector<double> &u,
                         std::vector<double> &v)
{
  const std::size_t n = std::min(times.size(), acceleration.size());
  u.assign(n, 0.);
  v.assign(n, 0.);
  if (n == 0)
    return;
  double x = 0., y = 0.;
  OscillatorStep step(omega, xi, n > 1 && times[1] > times[0] ? times[1] - times[0] : 1.);
  for (std::size_t i = 1; i < n; ++i)
  {
    const double h = times[i] - times[i - 1];
    if (h > 0.)
    {
      if (std::abs(h - step.interval()) > 1e-9 * step.interval())
        step = OscillatorStep(omega, xi, h);
      step.advance(x, y, -acceleration[i - 1], -acceleration[i]);
    }
    u[i] = x;
    v[i] = y;
  }
}

std::vector<double> pseudo_acceleration_spectrum(const std::vector<double> &times,
                                                 const std::vector<double> &acceleration,
                                                 const std::vector<double> &periods,
                                                 const double xi)
{
  std::vector<double> spectrum;
  const std::size_t n = std::min(times.size(), acceleration.size());
  for (const double period : periods)
  {
    const double omega = 2. * M_PI / period;
    double x = 0., y = 0., peak = 0.;
    if (n > 1)
    {
      OscillatorStep step(omega, xi, times[1] > times[0] ? times[1] - times[0] : 1.);
      for (std::size_t i = 1; i < n; ++i)
      {
        const double h = times[i] - times[i - 1];
        if (h <= 0.)
          continue;
        if (std::abs(h - step.interval()) > 1e-9 * step.interval())
          step = OscillatorStep(omega, xi, h);
        step.advance(x, y, -acceleration[i - 1], -acceleration[i]);
        peak = std::max(peak, std::abs(x));
      }
    }
    spectrum.push_back(omega * omega * peak);
  }
  return spectrum;
}

std::vector<double>
log_spaced_periods(const double first, const double last, const unsigned int n)
{
  std::vector<double> periods;
  for (unsigned int i = 0; i < n; ++i)
    periods.push_back(n == 1 ? first
                             : first * std::pow(last / first, double(i) / double(n - 1)));
  if (n > 1)
    periods.back() = last;
  return periods;
}
} // namespace hati

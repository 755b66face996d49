// Unit test of the fit of frequency-range damping (doc/theory.md, A8):
// fit_maxwell_branches() against an independent reference, the numpy/scipy
// prototype of the specification (scipy.optimize.nnls on the same 60
// log-spaced frequencies, refined five times with the exact loss factor):
// its alpha_l, its largest relative deviation over 200 log-spaced
// frequencies of the band, and its exact ratio xi = Im c / (2 Re c) at
// 0.5, 60 and 300 Hz, for six bands (3 and 4 branches, ratios 2 to 20 %,
// a band so wide that three branches fit it badly). Also: xi(f) of one
// branch against its closed form, and the stable-step factor sum(alpha).
// Returns non-zero on failure.
#include "test_tools.h"

#include <hati/time/frequency_range_damping.h>

#include <cmath>
#include <string>
#include <vector>

namespace hati_unit_frequency_range_damping
{

using namespace hati_test;

namespace
{
struct Reference
{
  double ratio, f1, f2;
  std::vector<double> alpha;
  double error;
  std::vector<double> xi_at_05_60_300;
};
} // namespace

HATI_UNIT_TEST(frequency_range_damping)
{
  // printed by the prototype (scipy 1.10.1), 12 digits
  const std::vector<Reference> references = {
      {0.02,
       1,
       30,
       {0.061891573524, 0.040225044803, 0.069367882327},
       0.0344695801312,
       {0.014591312249, 0.014007239684, 0.003334762669}},
      {0.02,
       0.5,
       30,
       {0.066373834779, 0.053493976171, 0.07522797496},
       0.0233644780751,
       {0.019937049289, 0.014444091409, 0.00345354483}},
      {0.05,
       0.1,
       10,
       {0.184936204354, 0.179287712241, 0.257381313082},
       0.0476148946217,
       {0.049458317921, 0.013945581581, 0.00284617886}},
      {0.02,
       0.5,
       30,
       {0.055416436739, 0.03490632636, 0.033518093107, 0.065330379311},
       0.0493336785128,
       {0.019099237272, 0.013586960198, 0.003215848345}},
      {0.2,
       0.1,
       10,
       {0.955350008961, 1.302192366814, 3.346180274532},
       0.0790444460443,
       {0.199207811262, 0.043445425389, 0.008793537271}},
      {0.02,
       0.01,
       1000,
       {0.124965795038, 0.140196801806, 0.148514057494},
       0.679849030551,
       {0.010723308171, 0.006428581976, 0.016579346364}}};

  for (const Reference &r : references)
  {
    const hati::MaxwellFit fit =
        hati::fit_maxwell_branches(r.ratio, r.f1, r.f2, r.alpha.size());
    const std::string band = "xi = " + std::to_string(r.ratio) + " over [" +
                             std::to_string(r.f1) + ", " + std::to_string(r.f2) +
                             "] Hz, " + std::to_string(r.alpha.size()) + " branches";
    double sum = 0.;
    for (unsigned int l = 0; l < r.alpha.size(); ++l)
    {
      // the two fits solve the same problem: agreement to the prototype's
      // printed digits (relative 1e-9)
      check(band + ": alpha_" + std::to_string(l),
            fit.branches.alpha[l],
            r.alpha[l],
            1e-9 * r.alpha[l] + 1e-12);
      // tau_l = 1 / (2 pi f_l), f_l log-spaced with the band's ends
      const double f_l =
          r.f1 * std::pow(r.f2 / r.f1, double(l) / double(r.alpha.size() - 1));
      check(band + ": tau_" + std::to_string(l),
            fit.branches.tau[l],
            1. / (2. * M_PI * f_l),
            1e-14 / f_l);
      sum += r.alpha[l];
    }
    check(band + ": fit error", fit.error, r.error, 1e-8 * r.error);
    check(band + ": sum alpha", fit.branches.alpha_sum(), sum, 1e-9 * sum);
    const double f[3] = {0.5, 60., 300.};
    for (unsigned int i = 0; i < 3; ++i)
      check(band + ": xi at " + std::to_string(f[i]) + " Hz",
            fit.branches.damping_ratio(f[i]),
            r.xi_at_05_60_300[i],
            1e-9 * r.xi_at_05_60_300[i]);
  }

  // one branch alpha, tau: c = 1 + alpha i w tau / (1 + i w tau), so
  // xi = alpha x / (2 (1 + x^2 + alpha x^2)) with x = w tau (closed form)
  hati::MaxwellBranches one;
  one.alpha = {0.3};
  one.tau = {0.01};
  for (const double f : {0.1, 1., 15.9, 100., 1e4})
  {
    const double x = 2. * M_PI * f * 0.01;
    check("one branch: xi at " + std::to_string(f) + " Hz",
          one.damping_ratio(f),
          0.3 * x / (2. * (1. + x * x + 0.3 * x * x)),
          1e-15);
  }
  // one fitted branch sits at the band's geometric mean
  const hati::MaxwellFit single = hati::fit_maxwell_branches(0.02, 1., 100., 1);
  check("one fitted branch: tau = 1 / (2 pi sqrt(f1 f2))",
        single.branches.tau[0],
        1. / (2. * M_PI * 10.),
        1e-15);
  expect(single.branches.alpha[0] > 0., "one fitted branch: alpha > 0");
  return finish();
}
} // namespace hati_unit_frequency_range_damping

// Macro-step aliasing (doc/theory.md 11.3, source/time/macro_aliasing.cc).
// References: the free-interface frequencies of a two-mass chain against
// its closed-form eigenvalues; the folded phase |Omega DT - 2 pi k| of a
// single mode against its hand computation.
#include <hati/time/macro_aliasing.h>

#include <cmath>
#include <iostream>

using namespace hati;

namespace
{
int failures = 0;

void check(const std::string &what,
           const double value,
           const double reference,
           const double tol)
{
  const bool ok = std::abs(value - reference) <= tol;
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (reference "
            << reference << ", tolerance " << tol << ")" << std::endl;
  failures += ok ? 0 : 1;
}
} // namespace

int main()
{
  // a free-free chain m1 -k- m2 and a fixed DoF: Omega^2 = 0 and k (1/m1 + 1/m2)
  const double k = 4e6, m1 = 2., m2 = 3.;
  DiscreteSystem s;
  s.reinit(3);
  DynamicSparsityPattern dsp(3, 3);
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      dsp.add(i, j);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  s.stiffness.set(0, 0, k);
  s.stiffness.set(0, 1, -k);
  s.stiffness.set(1, 0, -k);
  s.stiffness.set(1, 1, k);
  s.stiffness.set(2, 2, 1e9);
  s.lumped_mass[0] = m1;
  s.lumped_mass[1] = m2;
  s.lumped_mass[2] = 1.;
  s.fixed[2] = true;
  const std::vector<double> omegas = free_interface_frequencies(s);
  check("two free modes", omegas.size(), 2., 0.);
  const double omega = std::sqrt(k * (1. / m1 + 1. / m2));
  check("rigid mode (rad/s)", omegas[0], 0., 1e-6 * omega);
  check("chain mode (rad/s)", omegas[1], omega, 1e-12 * omega);
  check(
      "more than max_dofs: not checked", free_interface_frequencies(s, 1).size(), 0., 0.);

  // one mode of 1000 Hz, dt = 1e-5 s: Omega DT = 2 pi m / 100
  const std::vector<double> one = {2. * M_PI * 1000.};
  const double dt = 1e-5;
  check(
      "m = 50: Omega DT = pi, resolved", aliasing_modes(one, dt, 50, 0.2).size(), 0., 0.);
  check(
      "m = 97: folded 0.188 rad < 0.2", aliasing_modes(one, dt, 97, 0.2).size(), 1., 0.);
  check(
      "m = 96: folded 0.251 rad > 0.2", aliasing_modes(one, dt, 96, 0.2).size(), 0., 0.);
  const auto modes = aliasing_modes(one, dt, 99, 0.2);
  check("m = 99: one mode", modes.size(), 1., 0.);
  // Omega DT = 2 pi 0.99: folds to 2 pi 0.01 rad per DT = 9.9e-4 s, 10.10 Hz
  check("m = 99: folded frequency (Hz)", modes[0].folded_frequency, 0.01 / 9.9e-4, 1e-9);
  check("m = 99: mode frequency (Hz)", modes[0].frequency, 1000., 1e-9);
  check("m = 100: folds to zero (Hz)",
        aliasing_modes(one, dt, 100, 0.2)[0].folded_frequency,
        0.,
        1e-9);
  const std::string w = aliasing_warning(modes, one, dt, 99, 0.2);
  std::cout << w << std::endl;
  // the clean ratios near 99 are those folded by more than 0.2 rad: 95, 96
  check("warning names the clean ratios 95, 96",
        w.find("without such a mode: 95, 96") != std::string::npos,
        1.,
        0.);
  if (failures > 0)
    std::cout << failures << " check(s) failed" << std::endl;
  return failures > 0 ? 1 : 0;
}

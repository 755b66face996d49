// Macro-step aliasing (doc/theory.md 11.3, source/time/macro_aliasing.cc).
// References: the free-interface frequencies of a two-mass chain against
// its closed-form eigenvalues and the interface-flexibility shares of a
// three-mass chain against its modal solution; the folded phase
// |Omega DT - 2 pi k| of a single mode against its hand computation.
#include "test_tools.h"

#include <hati/time/macro_aliasing.h>

#include <cmath>
#include <iostream>

namespace hati_unit_macro_aliasing
{

using namespace hati;
using namespace hati_test;

HATI_UNIT_TEST(macro_aliasing)
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
  // the interface row: DoF 0
  SparseRow row;
  row.dofs = {0};
  row.coefficients = {1.};
  const std::vector<FreeInterfaceMode> free = free_interface_modes(s, {row});
  check("two free modes", free.size(), 2., 0.);
  const double omega = std::sqrt(k * (1. / m1 + 1. / m2));
  check("rigid mode (rad/s)", free[0].omega, 0., 1e-6 * omega);
  check("chain mode (rad/s)", free[1].omega, omega, 1e-12 * omega);
  check("rigid mode: no share", free[0].share, 0., 0.);
  check("the only flexible mode: all of the flexibility", free[1].share, 1., 1e-12);
  check("more than max_dofs: not checked",
        free_interface_modes(s, {row}, 1).size(),
        0.,
        0.);

  // three equal masses m in a free chain -k- -k-, the interface at the end
  // DoF: modes Omega^2 = k/m (1, 3) with phi = (1, 0, -1)/sqrt(2m) and
  // (1, -2, 1)/sqrt(6m): (phi_0)^2 / Omega^2 = 1/(2k), 1/(18k), shares 9/10, 1/10
  DiscreteSystem c;
  c.reinit(3);
  DynamicSparsityPattern dsp3(3, 3);
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      dsp3.add(i, j);
  c.stiffness_pattern.copy_from(dsp3);
  c.stiffness.reinit(c.stiffness_pattern);
  for (unsigned int i = 0; i < 2; ++i)
  {
    c.stiffness.add(i, i, k);
    c.stiffness.add(i + 1, i + 1, k);
    c.stiffness.add(i, i + 1, -k);
    c.stiffness.add(i + 1, i, -k);
  }
  for (unsigned int i = 0; i < 3; ++i)
    c.lumped_mass[i] = m1;
  const std::vector<FreeInterfaceMode> chain = free_interface_modes(c, {row});
  check("chain: first flexible mode (rad/s)",
        chain[1].omega,
        std::sqrt(k / m1),
        1e-12 * omega);
  check("chain: its share", chain[1].share, 0.9, 1e-12);
  check("chain: second flexible mode (rad/s)",
        chain[2].omega,
        std::sqrt(3. * k / m1),
        1e-12 * omega);
  check("chain: its share", chain[2].share, 0.1, 1e-12);

  // one mode of 1000 Hz, dt = 1e-5 s: Omega DT = 2 pi m / 100
  std::vector<FreeInterfaceMode> one(1);
  one[0].omega = 2. * M_PI * 1000.;
  one[0].share = 0.5;
  check("a share below the limit: none",
        aliasing_modes(one, 1e-5, 100, 0.2, 0.6).size(),
        0.,
        0.);
  const double dt = 1e-5;
  check("m = 50: Omega DT = pi, resolved",
        aliasing_modes(one, dt, 50, 0.2, 0.01).size(),
        0.,
        0.);
  check("m = 97: folded 0.188 rad < 0.2",
        aliasing_modes(one, dt, 97, 0.2, 0.01).size(),
        1.,
        0.);
  check("m = 96: folded 0.251 rad > 0.2",
        aliasing_modes(one, dt, 96, 0.2, 0.01).size(),
        0.,
        0.);
  const auto modes = aliasing_modes(one, dt, 99, 0.2, 0.01);
  check("m = 99: one mode", modes.size(), 1., 0.);
  // Omega DT = 2 pi 0.99: folds to 2 pi 0.01 rad per DT = 9.9e-4 s, 10.10 Hz
  check("m = 99: folded frequency (Hz)", modes[0].folded_frequency, 0.01 / 9.9e-4, 1e-9);
  check("m = 99: mode frequency (Hz)", modes[0].frequency, 1000., 1e-9);
  check("m = 100: folds to zero (Hz)",
        aliasing_modes(one, dt, 100, 0.2, 0.01)[0].folded_frequency,
        0.,
        1e-9);
  const std::string w = aliasing_warning(modes, one, dt, 99, 0.2, 0.01);
  std::cout << w << std::endl;
  // the clean ratios near 99 are those folded by more than 0.2 rad: 95, 96
  expect(w.find("without such a mode: 95, 96") != std::string::npos,
         "warning names the clean ratios 95, 96");
  return finish();
}
} // namespace hati_unit_macro_aliasing

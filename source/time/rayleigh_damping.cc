#include <deal.II/base/exceptions.h>

#include <hati/time/rayleigh_damping.h>

#include <cmath>

namespace hati
{
using namespace dealii;

void RayleighDamping::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Mass coefficient",
                    "0",
                    Patterns::Double(0.),
                    "Rayleigh damping C = a0 M + a1 K: a0 (1/s). Do not combine with "
                    "Damping ratio.");
  prm.declare_entry("Stiffness coefficient",
                    "0",
                    Patterns::Double(0.),
                    "Rayleigh damping C = a0 M + a1 K: a1 (s). Do not combine with "
                    "Damping ratio.");
  prm.declare_entry("Damping ratio",
                    "0",
                    Patterns::Double(0.),
                    "Damping ratio zeta (-). If > 0, a0 and a1 are computed so that "
                    "the First frequency and the Second frequency have exactly this "
                    "damping ratio: a0 = 2 zeta w1 w2 / (w1 + w2), "
                    "a1 = 2 zeta / (w1 + w2), w = 2 pi f.");
  prm.declare_entry("First frequency",
                    "0",
                    Patterns::Double(0.),
                    "First frequency f1 (Hz) of the damping ratio.");
  prm.declare_entry("Second frequency",
                    "0",
                    Patterns::Double(0.),
                    "Second frequency f2 (Hz) of the damping ratio.");
}

void RayleighDamping::parse_parameters(ParameterHandler &prm)
{
  a0 = prm.get_double("Mass coefficient");
  a1 = prm.get_double("Stiffness coefficient");
  const double zeta = prm.get_double("Damping ratio");
  const double f1 = prm.get_double("First frequency");
  const double f2 = prm.get_double("Second frequency");
  given = a0 != 0. || a1 != 0. || zeta != 0. || f1 != 0. || f2 != 0.;
  if (zeta > 0.)
  {
    AssertThrow(a0 == 0. && a1 == 0.,
                ExcMessage("Rayleigh damping: give either the Damping ratio (with "
                           "the First and Second frequency) or the Mass and "
                           "Stiffness coefficients, not both."));
    AssertThrow(f1 > 0. && f2 > 0.,
                ExcMessage("Rayleigh damping: a Damping ratio > 0 needs a First "
                           "frequency and a Second frequency > 0 (Hz)."));
    const double w1 = 2. * M_PI * f1, w2 = 2. * M_PI * f2;
    a0 = 2. * zeta * w1 * w2 / (w1 + w2);
    a1 = 2. * zeta / (w1 + w2);
  }
}
} // namespace hati

// Rayleigh damping fitted to the first vertical and the first horizontal
// mode of a model (the bridge crane's default damping, doc/theory.md 7.4).
#include <deal.II/base/exceptions.h>

#include <hati/analysis/modal_damping.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hati
{
namespace
{
/** omega^2 below this fraction of the highest computed one: a rigid mode. */
constexpr double rigid_fraction = 1e-8;
/** Smallest effective mass, as a fraction of the free mass, that dominates. */
constexpr double participation_fraction = 1e-3;

/**
 * Direction 0, 1, 2 (x, y, z) whose effective mass dominates mode @p k of
 * @p r, or -1 for a mode without significant net participation.
 */
int dominant_direction(const ModalResult &r, const unsigned int k)
{
  const auto &m = r.effective_mass[k];
  const int d = std::max_element(m.begin(), m.end()) - m.begin();
  return m[d] >= participation_fraction * r.total_mass[d] && m[d] > 0. ? d : -1;
}
} // namespace

ModalRayleighDamping modal_rayleigh_damping(const DiscreteSystem &system,
                                            const double damping_ratio,
                                            const std::string &linear_solver)
{
  AssertThrow(damping_ratio > 0.,
              ExcMessage("modal Rayleigh damping: the damping ratio must be > 0."));
  // free DoFs once the closed contacts are eliminated: the most modes there are
  unsigned int n_free = 0;
  for (unsigned int i = 0; i < system.n_dofs(); ++i)
    n_free += system.fixed[i] ? 0 : 1;
  n_free -= compute_modes(system, 0, true, &system.initial_displacement, linear_solver)
                .n_constraints;
  ModalRayleighDamping result;
  result.damping_ratio = damping_ratio;
  unsigned int n_modes = 20, searched = 0;
  while (true)
  {
    n_modes = std::min(n_modes, n_free);
    const ModalResult r =
        compute_modes(system, n_modes, true, &system.initial_displacement, linear_solver);
    searched = r.frequencies.size();
    const double f_max = r.frequencies.empty() ? 0. : r.frequencies.back();
    result.mode_vertical = result.mode_horizontal = 0;
    for (unsigned int k = 0; k < r.frequencies.size(); ++k)
    {
      const double f = r.frequencies[k];
      if (f * f <= rigid_fraction * f_max * f_max)
        continue;
      const int d = dominant_direction(r, k);
      if (d == 2 && result.mode_vertical == 0)
      {
        result.mode_vertical = k + 1;
        result.f_vertical = f;
      }
      if ((d == 0 || d == 1) && result.mode_horizontal == 0)
      {
        result.mode_horizontal = k + 1;
        result.f_horizontal = f;
      }
    }
    const bool found = result.mode_vertical > 0 && result.mode_horizontal > 0;
    if (found || n_modes >= 160 || n_modes >= n_free)
      break;
    n_modes *= 2;
  }
  if (result.mode_vertical == 0 || result.mode_horizontal == 0)
  {
    std::ostringstream s;
    s << "Time integration/Damping: no " << (result.mode_vertical == 0 ? "vertical" : "")
      << (result.mode_vertical == 0 && result.mode_horizontal == 0 ? " and no " : "")
      << (result.mode_horizontal == 0 ? "horizontal" : "")
      << " elastic mode among the lowest " << searched
      << " modes for the model's default damping ratio: set the damping explicitly";
    AssertThrow(false, ExcMessage(s.str()));
  }
  const double w1 = 2. * M_PI * result.f_vertical, w2 = 2. * M_PI * result.f_horizontal;
  result.a0 = 2. * damping_ratio * w1 * w2 / (w1 + w2);
  result.a1 = 2. * damping_ratio / (w1 + w2);
  return result;
}

SummaryEntries apply_default_damping(const double zeta,
                                     const DiscreteSystem &system,
                                     const std::string &method,
                                     const std::string &linear_solver,
                                     RayleighDamping &damping)
{
  if (zeta <= 0. || damping.given)
    return {};
  if (method == "event-driven")
  {
    std::cout << "  no default Rayleigh damping (" << zeta
              << ") with Method = event-driven: undamped" << std::endl;
    return {};
  }
  const ModalRayleighDamping d = modal_rayleigh_damping(system, zeta, linear_solver);
  damping.a0 = d.a0;
  damping.a1 = d.a1;
  std::cout << "  default Rayleigh damping " << zeta << " at the first vertical mode ("
            << d.mode_vertical << ", " << std::setprecision(8) << d.f_vertical
            << " Hz) and the first horizontal mode (" << d.mode_horizontal << ", "
            << d.f_horizontal << " Hz), contacts closed: a0 = " << d.a0
            << " 1/s, a1 = " << d.a1 << " s" << std::endl;
  return {{"damping_frequencies",
           SummaryValue::list().push_back(d.f_vertical).push_back(d.f_horizontal)},
          {"rayleigh_a0", d.a0},
          {"rayleigh_a1", d.a1}};
}
} // namespace hati

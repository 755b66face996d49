// Unit test of the frozen activation of CD-Lagrange's contacts (A4 with the
// active set taken from a pattern; CDLagrange::CouplingView::
// freeze_activation(), the HATI corrections of doc/theory.md 9.6 item 6).
// A mass of 2 kg on a soft spring moves at -1 m/s towards a wall (restitution
// 0). Independent references: the velocity-level Signorini law of one
// contact (A5) gives the velocity after an active step in closed form, zero
// normal velocity; an inactive step leaves the free velocity unchanged.
//  (a) the wall 0.5 m away, activation frozen on: the contact acts at once
//      (impulse m |v|, velocity 0) where the gap alone leaves it open;
//  (b) the mass 1 mm into the wall, activation frozen off: no impulse, the
//      velocity unchanged, where the gap alone closes it;
//  (c) freeze_activation(nullptr) restores the gaps' decision.
// Returns non-zero on failure.
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "test_tools.h"

#include <hati/model/discrete_system.h>
#include <hati/time/cd_lagrange.h>

#include <cmath>
#include <iostream>
#include <vector>

namespace hati_unit_frozen_activation
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{
/** A mass m on a spring k (1 N/m: its force over one step is negligible) with a wall. */
void make_system(DiscreteSystem &s, const double gap, const double v0)
{
  s.reinit(1);
  s.lumped_mass[0] = 2.;
  DynamicSparsityPattern dsp(1, 1);
  dsp.add(0, 0);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  s.stiffness.set(0, 0, 1.);
  s.initial_velocity[0] = v0;
  ContactRow c;
  c.name = "wall";
  c.dofs = {0};
  c.coefficients = {1.}; // gap = initial gap + u: the wall at u = -gap
  c.initial_gap = gap;
  c.restitution = 0.;
  s.contacts.push_back(c);
}
} // namespace

HATI_UNIT_TEST(frozen_activation)
{
  const double dt = 1e-3, m = 2., v0 = -1.;
  const std::vector<bool> on = {true}, off = {false};
  // (a) open by its gap, frozen active: one step of the Signorini law
  {
    DiscreteSystem s;
    make_system(s, 0.5, v0);
    CDLagrange free_run(s, dt, 1.);
    free_run.step();
    check("(a) gaps alone: impulse (N s)", free_run.impulses()[0], 0., 0.);
    CDLagrange frozen(s, dt, 1.);
    frozen.coupling_view().freeze_activation(&on);
    frozen.step();
    check("(a) frozen active: velocity after the step (m/s)",
          frozen.velocity()[0],
          0.,
          1e-12);
    check("(a) frozen active: impulse m |v0| (N s)",
          frozen.impulses()[0],
          m * std::abs(v0),
          1e-5);
    check("(a) frozen active: gap of the step (m)", frozen.gaps()[0], 0.5, 2e-3);
    // (c) unfrozen: the next steps decide from the gap again (open, moving
    // away from nothing: the velocity stays at zero, no impulse)
    frozen.coupling_view().freeze_activation(nullptr);
    frozen.step();
    check("(c) unfrozen: impulse (N s)", frozen.impulses()[0], 0., 0.);
  }
  // (b) closed by its gap, frozen open: the free velocity
  {
    DiscreteSystem s;
    make_system(s, -1e-3, v0);
    CDLagrange by_gap(s, dt, 1.);
    by_gap.step();
    expect(by_gap.impulses()[0] > 0.9 * m * std::abs(v0),
           "(b) gaps alone: the wall acts");
    CDLagrange frozen(s, dt, 1.);
    frozen.coupling_view().freeze_activation(&off);
    frozen.step();
    check("(b) frozen open: impulse (N s)", frozen.impulses()[0], 0., 0.);
    check("(b) frozen open: velocity (m/s)", frozen.velocity()[0], v0, 1e-5);
  }
  return finish();
}
} // namespace hati_unit_frozen_activation

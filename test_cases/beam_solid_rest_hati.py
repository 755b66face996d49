#!/usr/bin/python3
"""A static start under HATI with a contact on a tied interface node (the
3D crane's trolley wheels on its rails, doc/theory.md 6.1 and 9.5), on
parameter_files/beam_solid_prism.prm under gravity: beam 'a' clamped at A0
and tied at A1 to the prism (implicit, eliminated), beam 'b' tied at B0 to
the prism's far face (explicit: the tie's six rows are the interface), and
a soft cantilever 'c' (clamped at C1, 200 kg at its tip C0) resting on B0
by a unilateral node-to-node contact (explicit: the contact acts on the
interface DoFs of B0). Initial state = static, no other load.

Reference: the static state is an equilibrium of the discrete equations of
both parts with the interface force Lambda_0 (doc/theory.md 9.5), so the
run stays at rest up to round-off; so does the fully explicit run
(CD-Lagrange at dt = 4e-6 s, below the prism's dt_crit) of the same model,
measured alongside. Checked for m = 1, 5, 10, and at m = 5 with friction
at the contact (mu = 0.5) under gravity tilted by (1, 0.5) m/s^2 in x, y
and the cantilever c free to translate in x, y at C1, so that the contact
also carries a static friction force (c's tilted weight, 232.4 N, to 1e-9;
its peak over the run to 1e-7):
- the largest monitor velocity (m/s, rad/s) over the run against g DT (the
  velocity gravity gives in one macro step), below 1e-5 (measured 6.5e-9
  to 9.9e-8, the fully explicit run 4.1e-7 with its g dt; about 1e-11 m/s:
  the round-off accelerations below act over the structure's periods, so
  the ratio grows as DT shrinks); the largest monitor acceleration against
  g, below 1e-7 (measured 0.9e-9 to 2.1e-9, the fully explicit run
  2.5e-9);
- the contact stays closed: no impact, its force at every history row
  equals the static force within 1e-7 relative (measured 5e-10 to 8e-10);
- the displacements stay at the static state within 1e-7 of their largest
  value (measured 4e-12, the fully explicit run 1.5e-11).
Before the fix of this test's commit the start was not at rest: the
explicit part's lumped gravity moments at B0 were dropped from the static
state (B0 is eliminated in the whole system) and the interface velocity at
the macro-step end left out the contact's impulse on B0: B0 accelerated at
5-7 m/s^2 (velocities 1.2 to 16 g DT, the contact force 24-48 % off its
static value after an impact); with the first corrected alone at
0.06 m/s^2 (6e-3 g); and the static friction force on B0 was left out of
the explicit part's initial contact reaction (the whole system writes the
tangent rows through B0's tie): 0.06 m/s^2 at m = 5 with friction. The
tolerances keep two decades above the round-off measured; the
acceleration's is five below the smaller defects."""
import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("beam_solid_prism.prm")
g = 9.81
MODEL = [
    "Analysis/Initial state=static",
    "Model/Frame/Nodes=A0: -1, 0, 0; A1: 0, 0, 0; B0: 2, 0, 0; B1: 3, 0, 0; "
    "C0: 2, 0, 0.2; C1: 3, 0, 0.2",
    "Model/Frame/Sections=rod: general, 1.2e-2, 2e-4, 1e-4, 2e-4, 5e-3, 5e-3; "
    "thin: general, 1e-3, 2e-7, 2e-7, 4e-7, 5e-4, 5e-4",
    "Model/Frame/Members=a: A0, A1, rod, steel, 4; b: B0, B1, rod, steel, 4; "
    "c: C0, C1, thin, steel, 4",
    "Model/Frame/Supports=A0: clamped; C1: clamped",
    "Model/Frame/Point masses=B1: 200, 20, 20, 20; C0: 200, 1, 1, 1",
    "Model/Frame/Nodal loads=",
    "Model/Frame/Contacts=rest: C0, B0, 0, 0, 1, 0",
    "Model/Frame/Monitor nodes=A1, B0, B1, C0",
    "Loading/Gravity=0, 0, -%g" % g,
    "Time integration/End time=0.01",
    "Output/Output interval=0",
    "Output/History interval=5e-5",
]
TOL, TOL_V = 1e-7, 1e-5


def at_rest(label, out, DT):
    """The checks of the docstring on the run in `out` (macro step DT)."""
    h = read_csv(out + "/history.csv")
    s = read_summary(out)
    names = h.dtype.names
    # (numpy drops the dot of "B0.vz")
    velocity = [n for n in names if n.endswith(("vx", "vy", "vz", "vrx", "vry", "vrz"))]
    displacement = [n for n in names if n.endswith(("ux", "uy", "uz", "urx", "ury", "urz"))]
    assert len(velocity) == len(displacement) == 24, names
    v = max(np.max(np.abs(h[n])) for n in velocity)
    ctx.check(label + ": largest velocity / (g DT)", v / (g * DT), 0.0, abs_tol=TOL_V)
    a = max(p["value"] for p in s["max_absolute_acceleration"].values())
    ctx.check(label + ": largest acceleration / g", a / g, 0.0, abs_tol=TOL)
    u0 = max(abs(h[n][0]) for n in displacement)
    du = max(np.max(np.abs(h[n] - h[n][0])) for n in displacement)
    ctx.check(label + ": largest |u(t) - u(0)| / max |u(0)|", du / u0, 0.0, abs_tol=TOL)
    c = read_csv(out + "/contacts.csv")
    c = c[c["time"] > 0.0]  # CD-Lagrange writes a row at t = 0, before any step
    static = s["static_contact_forces"]["rest"]
    ctx.check_true(label + ": the contact carries the tip (static force > 1 kN)",
                   static > 1e3, "(%.8g N)" % static)
    ctx.check(label + ": contact force / static force, largest deviation",
              np.max(np.abs(c["force"] / static - 1.0)), 0.0, abs_tol=TOL)
    ctx.check(label + ": impacts", s["n_impacts"], 0, abs_tol=0)


# with friction (mu = 0.5), gravity tilted in x and y and the cantilever
# c free to translate in x and y at C1: the contact's tangents hold c's
# translation (a mechanism, doc/theory.md 6.2), so they carry c's whole
# tilted weight as a static friction force, m_c |(1, 0.5)| = 232.4 N (m_c:
# the 200 kg point mass and the 1 m 'thin' member, 7.85 kg)
FRICTION = ["Model/Frame/Contacts=rest: C0, B0, 0, 0, 1, 0, mu=0.5",
            "Model/Frame/Supports=A0: clamped; C1: free, free, fixed, fixed, fixed, fixed",
            "Loading/Gravity=1, 0.5, -%g" % g]
m_c = 200.0 + 7850.0 * 1e-3 * 1.0
friction_reference = m_c * np.hypot(1.0, 0.5)
dt = 1e-5
for tag, label, extra, ratios in (("", "", [], (1, 5, 10)),
                                  ("_friction", ", friction", FRICTION, (5,))):
    ref, _ = ctx.run(prm, "explicit" + tag, MODEL + extra + ["Time integration/Time step=4e-6"])
    at_rest("fully explicit" + label, ref, 4e-6)
    for m in ratios:
        out, _ = ctx.run(prm, "hati_m%d%s" % (m, tag), MODEL + extra + [
            "Time integration/Method=HATI", "Time integration/Time step=%g" % dt,
            "Time integration/HATI/Time step ratio=%d" % m,
            "Model/Decomposition/Explicit members=b, c"])
        s = read_summary(out)
        ctx.check_true("m = %d%s: six interface rows (the tie at B0)" % (m, label),
                       s.get("n_interface_dofs") == 6, str(s.get("n_interface_dofs")))
        if extra:
            ctx.check("m = %d%s: static friction force (N) = m_c |g_t|" % (m, label),
                      s["static_friction_forces"]["rest"], friction_reference, rel=1e-9)
            ctx.check("m = %d%s: peak friction force over the run (N)" % (m, label),
                      s["contacts"]["rest"]["peak_friction_force"], friction_reference,
                      rel=1e-7)
        at_rest("HATI m = %d%s" % (m, label), out, m * dt)
ctx.finish()

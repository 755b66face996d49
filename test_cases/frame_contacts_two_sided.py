#!/usr/bin/python3
"""Node-to-node and two-sided frame contacts (Model/Frame/Contacts), CD-Lagrange.

1. parameter_files/frame_node_to_node.prm: a loaded free column hits the mid
   node of a free beam (node-to-node). The impulses on the two nodes are
   equal and opposite: the lower beam's momentum equals -Lambda(t) (Lambda the
   sum of the impulses so far, from contacts.csv), the upper body's
   -F t + Lambda(t), the total -F t up to a constant (to round-off); first
   impact at the rigid-body time sqrt(2 g0 m_u / F); no approach velocity
   while the contact pushes; discrete energy balance.
2. A clamped column with a tip mass, driven laterally by a sinusoidal base
   acceleration whose quasi-static amplitude is about 4 times the half
   clearance, against a two-sided contact (flange play c): it hits both sides
   alternately (impulses while u_y = +c/2 and while u_y = -c/2), and
   |u_y| <= c/2 + dt v_max, while it does reach c/2 - dt v_max on both sides.
3. One-line errors: a negative gap, a second value that is neither a node
   nor a number, a node-to-node contact naming the same node twice."""
import os
import subprocess

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()

# ---- 1. node to node ------------------------------------------------------
F, g0, dt = 2000.0, 0.005, 2e-6
out, _ = ctx.run(ctx.prm("frame_node_to_node.prm"), "node_to_node")
h = read_csv(out + "/history.csv")
c = read_csv(out + "/contacts.csv")
rho = 7850.0
m_el_beam = rho * 0.05 * 0.1 * 0.5      # one lower element
m_el_post = rho * 0.02 * 0.02 * 0.25    # one upper element
lower = {"l0": m_el_beam / 2, "l1": m_el_beam, "l2": m_el_beam, "l3": m_el_beam,
         "l4": m_el_beam / 2}
upper = {"p": m_el_post / 2, "c": m_el_post, "q": m_el_post / 2 + 20.0}
P_l = sum(m * h[n + "vz"] for n, m in lower.items())
P_u = sum(m * h[n + "vz"] for n, m in upper.items())
t = h["time"]
Lam = np.cumsum(c["impulse"])
ctx.check_true("contacts.csv and history.csv have the same rows",
               len(c) == len(h) and np.allclose(c["time"], t, rtol=0, atol=1e-12))
ctx.check("initial gap of the node-to-node contact (m)", c["gap"][0], g0, abs_tol=1e-15)
ctx.check_true("the contact pushed", Lam[-1] > 0, "(total impulse %.6g N s)" % Lam[-1])
scale = F * t[-1]
ctx.check("max |P_lower + Lambda| / (F T) (equal and opposite)",
          np.max(np.abs(P_l + Lam)) / scale, 0.0, abs_tol=1e-10)
off = P_u - Lam + F * t
ctx.check("spread of P_upper - Lambda + F t / (F T)", (off.max() - off.min()) / scale, 0.0,
          abs_tol=1e-10)
ctx.check("constant offset of the staggered momentum / (F dt)", abs(off[0]) / (F * dt), 0.0,
          abs_tol=1.0)
m_u = sum(upper.values())
first = t[np.argmax(c["impulse"] > 0)]
t0 = np.sqrt(2 * g0 * m_u / F)
# the 0.5 m column shortens elastically under F (F L / EA = 6e-6 m, 0.1 % of
# g0), and its axial wave (period 4 L / c = 0.4 ms) rings: 1 % of t0
ctx.check("first impact time (s) vs rigid-body fall", first, t0, rel=0.01)
pushing = c["impulse"] > 0
ctx.check("min normal velocity while pushing (m/s)", np.min(c["normal_velocity"][pushing]), 0.0,
          abs_tol=1e-12)
s = read_summary(out)
ctx.check("energy balance relative error", s["energy_balance_relative"], 0.0, abs_tol=1e-9)

# ---- 2. two-sided contact -------------------------------------------------
clearance, A, omega, dt2, T2 = 0.002, 3.0, 10.0, 2e-5, 1.5
record = os.path.join(ctx.work, "sine_y.txt")
tt = np.arange(0.0, T2 + 0.01, 1e-3)
np.savetxt(record, np.column_stack((tt, A * np.sin(omega * tt))))
prm = os.path.join(ctx.work, "two_sided.prm")
with open(prm, "w") as f:
    f.write("""subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = base: 0, 0, 0; tip: 0, 0, 1
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = post: rectangle, 0.02, 0.02
    set Members   = col: base, tip, post, steel, 4
    set Supports  = base: clamped
    set Point masses = tip: 10
    set Contacts  = flange: tip, 0, 1, 0, %g, two-sided
    set Monitor nodes = tip
  end
end
subsection Loading
  set Gravity = 0, 0, 0
  set Accelerogram Y = %s
  set Accelerogram units = m/s^2
end
subsection Time integration
  set Method    = CD-Lagrange
  set Time step = %g
  set End time  = %g
end
subsection Output
  set Output interval  = 0
  set History interval = 0
end
""" % (clearance, record, dt2, T2))
out2, _ = ctx.run(prm, "two_sided")
h2 = read_csv(out2 + "/history.csv")
c2 = read_csv(out2 + "/contacts.csv")
s2 = read_summary(out2)
ctx.check("two rows under one name (n_contacts)", s2["n_contacts"], 2, abs_tol=0)
uy, vy = h2["tipuy"], h2["tipvy"]
v_max = np.max(np.abs(vy))
half = clearance / 2
push = c2["impulse"] > 0


def phases(mask):
    return int(np.sum(mask & ~np.concatenate(([False], mask[:-1]))))


plus, minus = phases(push & (uy > 0)), phases(push & (uy < 0))
ctx.check_true("impacts on the +y side (u_y = +c/2)", plus >= 2, "(%d impact phases)" % plus)
ctx.check_true("impacts on the -y side (u_y = -c/2)", minus >= 2, "(%d impact phases)" % minus)
# sides of the successive impact phases, repeats (chatter while the load
# presses the tip against one side) collapsed: 1.5 s of a 0.63 s drive
# period gives at least + - + - (3 side changes)
starts = np.where(push & ~np.concatenate(([False], push[:-1])))[0]
sides = np.sign(uy[starts])
changes = int(np.sum(sides[1:] != sides[:-1]))
ctx.check_true("impacts alternate between the sides", changes >= 3,
               "(%d side changes over %d impact phases)" % (changes, len(starts)))
ctx.check("max u_y (m) <= c/2 + dt v_max", max(uy.max() - half, 0.0), 0.0, abs_tol=dt2 * v_max)
ctx.check("min u_y (m) >= -c/2 - dt v_max", max(-half - uy.min(), 0.0), 0.0, abs_tol=dt2 * v_max)
ctx.check("max u_y (m) reaches c/2", uy.max(), half, abs_tol=dt2 * v_max)
ctx.check("min u_y (m) reaches -c/2", uy.min(), -half, abs_tol=dt2 * v_max)
ctx.check("min gap of the two rows (m)", min(c2["gap"].min(), 0.0), 0.0, abs_tol=dt2 * v_max)
ctx.check("min normal velocity while pushing (m/s)", np.min(c2["normal_velocity"][push]), 0.0,
          abs_tol=1e-12)

# ---- 3. errors ------------------------------------------------------------


def expect_error(what, sets, *fragments):
    p = subprocess.run([ctx.hati, ctx.prm("frame_node_to_node.prm")] +
                       sum((["--set", s] for s in sets), []) +
                       ["--set", "Output/Output directory=" + os.path.join(ctx.work, "err")],
                       capture_output=True, text=True, timeout=120)
    err = p.stderr.strip()
    ok = (p.returncode > 0 and len(err.splitlines()) == 1 and err.startswith("hati: error:")
          and all(f in err for f in fragments))
    ctx.check_true(what, ok, "(exit %d) %s" % (p.returncode, err))


expect_error("negative gap refused", ["Model/Frame/Contacts=hit: p, l2, 0, 0, 1, -0.001"],
             "Model/Frame/Contacts", "hit", "gap", ">= 0")
expect_error("negative clearance refused",
             ["Model/Frame/Contacts=hit: p, 0, 1, 0, -0.001, two-sided"],
             "Model/Frame/Contacts", "hit", "clearance", ">= 0")
expect_error("second value neither a node nor a number",
             ["Model/Frame/Contacts=hit: p, nowhere, 0, 0, 1, 0.001"],
             "Model/Frame/Contacts", "hit", "nowhere")
expect_error("node-to-node contact on one node", ["Model/Frame/Contacts=hit: p, p, 0, 0, 1, 0.001"],
             "Model/Frame/Contacts", "hit", "twice")
ctx.finish()

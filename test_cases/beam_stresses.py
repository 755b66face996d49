#!/usr/bin/python3
"""Beam stresses at the extreme fibres (issue #54, doc/theory.md 15.1,
S1-S3) against the formulas written out here.

Four cantilevers of length L = 2 m, clamped at x = 0, loaded at the tip and
held there in their static state (Initial state = static, Newmark at rest:
the section forces of every row are the static ones to round-off):
- `box_load`: box 0.3 x 0.5 m, 8 / 12 mm walls, tip load P along local z:
  the corner normal stress at the root M c / I = P L (h / 2) / Iy; von Mises
  there with the web shear of Vz = P, Vz / (2 h_m t_web);
- `box_torque`: the same box under a tip torque T alone: Bredt's wall shear
  T / (2 A_m t) in the thinner wall (A_m = b_m h_m), von Mises sqrt(3) tau;
- `rect_load`: a rectangle 0.05 x 0.1 m under P along z and a lateral load
  Q along y: corner stress 6 P L / (b h^2) + 6 Q L / (h b^2);
- `general_load`: a general section with the box's A, I, J and its extreme
  fibre distances c_y, c_z given (the optional last two values) under P:
  P L c_z / Iy.
Each to 1e-10 relative (the static solution is exact for a tip load: the
cubic beam element interpolates it, and the root's section force is P L)."""
import numpy as np

from hati_test import Context, read_summary

ctx = Context()
L, P, Q, T = 2.0, 1.0e4, 2.0e3, 5.0e3
b, h, tw, tf = 0.3, 0.5, 0.008, 0.012
A = b * h - (b - 2 * tw) * (h - 2 * tf)
Iy = (b * h**3 - (b - 2 * tw) * (h - 2 * tf) ** 3) / 12
Iz = (h * b**3 - (h - 2 * tf) * (b - 2 * tw) ** 3) / 12
bm, hm = b - tw, h - tf
J = 2 * tw * tf * bm**2 * hm**2 / (b * tw + h * tf - tw**2 - tf**2)
Asy, Asz = 2 * tf * bm, 2 * tw * hm
rb, rh = 0.05, 0.1

PRM = """subsection Analysis
  set Type          = transient
  set Initial state = static
end
subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = r1: 0, 0, 0; t1: %(L)g, 0, 0; r2: 0, 2, 0; t2: %(L)g, 2, 0; \\
                    r3: 0, 4, 0; t3: %(L)g, 4, 0; r4: 0, 6, 0; t4: %(L)g, 6, 0
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = box: box, %(b)g, %(h)g, %(tw)g, %(tf)g; rect: rectangle, %(rb)g, %(rh)g; \\
                    gen: general, %(A).17g, %(Iy).17g, %(Iz).17g, %(J).17g, %(Asy).17g, %(Asz).17g, %(cy)g, %(cz)g
    set Members   = box_load: r1, t1, box, steel, 4, 0, 1, 0; \\
                    box_torque: r2, t2, box, steel, 4, 0, 1, 0; \\
                    rect_load: r3, t3, rect, steel, 4, 0, 1, 0; \\
                    general_load: r4, t4, gen, steel, 4, 0, 1, 0
    set Supports  = r1: clamped; r2: clamped; r3: clamped; r4: clamped
    set Nodal loads = t1: 0, 0, %(P)g; t2: 0, 0, 0, %(T)g, 0, 0; \\
                      t3: 0, %(Q)g, %(P)g; t4: 0, 0, %(P)g
  end
end
subsection Loading
  set Gravity = 0, 0, 0
end
subsection Time integration
  set Method    = Newmark
  set Time step = 1e-3
  set End time  = 0.005
end
subsection Output
  set History interval = 0
end
""" % dict(L=L, b=b, h=h, tw=tw, tf=tf, rb=rb, rh=rh, A=A, Iy=Iy, Iz=Iz, J=J, Asy=Asy,
           Asz=Asz, cy=b / 2, cz=h / 2, P=P, Q=Q, T=T)
path = ctx.work + "/beam_stresses.prm"
open(path, "w").write(PRM)
out, _ = ctx.run(path, "run")
s = read_summary(out)["beam_stresses"]

sigma = P * L * (h / 2) / Iy
ctx.check("box_load corner normal stress P L c / Iy (Pa)",
          s["box_load"]["max_normal_stress"]["value"], sigma, rel=1e-10)
ctx.check("box_load governs at the root (x, m)", s["box_load"]["max_normal_stress"]["x"],
          0.0, abs_tol=1e-12)
tau_web = P / (2 * hm * tw)
ctx.check("box_load von Mises sqrt(sigma^2 + 3 (Vz / 2 h_m t_web)^2) (Pa)",
          s["box_load"]["max_von_mises"]["value"], np.sqrt(sigma**2 + 3 * tau_web**2),
          rel=1e-10)

tau = T / (2 * bm * hm * min(tw, tf))
ctx.check("box_torque normal stress (Pa): none", s["box_torque"]["max_normal_stress"]["value"],
          0.0, abs_tol=1e-6 * tau)
ctx.check("box_torque von Mises sqrt(3) T / (2 A_m t_min) (Pa)",
          s["box_torque"]["max_von_mises"]["value"], np.sqrt(3) * tau, rel=1e-10)

sigma_rect = 6 * P * L / (rb * rh**2) + 6 * Q * L / (rh * rb**2)
ctx.check("rect_load corner stress 6 P L / b h^2 + 6 Q L / h b^2 (Pa)",
          s["rect_load"]["max_normal_stress"]["value"], sigma_rect, rel=1e-10)

ctx.check("general_load corner stress P L c_z / Iy (Pa)",
          s["general_load"]["max_normal_stress"]["value"], sigma, rel=1e-10)
ctx.finish()

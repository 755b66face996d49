#!/usr/bin/python3
"""Frames read from Gmsh meshes (ASCII formats 2.2 and 4.1): the plane cross
of parameter_files/frame_joints.prm written as a mesh of line elements
(physical curves = members, physical points = named nodes) gives the hand
solution w_C = -P L^3 / (48 E Iy); parameter_files/frame_joints.msh is
checked the same way; a branching member is refused with a message naming
the file."""
import os

from hati_test import Context, read_csv

ctx = Context()
E, Iy, L, P = 2.1e11, 4.1666666666667e-6, 2.0, 1000.0
ends = {"E": (2, 0), "W": (-2, 0), "N": (0, 2), "S": (0, -2)}
members = {"east": "E", "west": "W", "north": "N", "south": "S"}
n_el = 3


def mesh():
    """Nodes, lines per member (physical tag), named points."""
    nodes = [(0.0, 0.0, 0.0)]  # tag 1 = C
    lines = {}
    points = {"C": 1}
    for k, (m, end) in enumerate(members.items()):
        x, y = ends[end]
        chain = [1]
        for i in range(1, n_el + 1):
            nodes.append((x * i / n_el, y * i / n_el, 0.0))
            chain.append(len(nodes))
        points[end] = chain[-1]
        lines[m] = list(zip(chain[:-1], chain[1:]))
    return nodes, lines, points


def write_v2(path, branching=False):
    nodes, lines, points = mesh()
    if branching:  # 'east' gets an extra element off its middle
        nodes.append((0.7, 1.0, 0.0))
        lines["east"].append((lines["east"][0][1], len(nodes)))
    names = list(points) + list(lines)
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(names))
        for i, p in enumerate(points):
            f.write('0 %d "%s"\n' % (i + 1, p))
        for i, m in enumerate(lines):
            f.write('1 %d "%s"\n' % (100 + i, m))
        f.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(nodes))
        for i, x in enumerate(nodes):
            f.write("%d %.17g %.17g %.17g\n" % ((i + 1,) + x))
        elems = [(15, i + 1, [t]) for i, t in enumerate(points.values())]
        elems += [(1, 100 + i, list(l)) for i, m in enumerate(lines) for l in lines[m]]
        f.write("$EndNodes\n$Elements\n%d\n" % len(elems))
        for k, (typ, phys, nn) in enumerate(elems):
            f.write("%d %d 2 %d %d %s\n" % (k + 1, typ, phys, phys, " ".join(map(str, nn))))
        f.write("$EndElements\n")


def write_v4(path):
    nodes, lines, points = mesh()
    with open(path, "w") as f:
        f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
        f.write("$PhysicalNames\n%d\n" % (len(points) + len(lines)))
        for i, p in enumerate(points):
            f.write('0 %d "%s"\n' % (i + 1, p))
        for i, m in enumerate(lines):
            f.write('1 %d "%s"\n' % (100 + i, m))
        f.write("$EndPhysicalNames\n$Entities\n%d %d 0 0\n" % (len(points), len(lines)))
        for i, (p, t) in enumerate(points.items()):
            x = nodes[t - 1]
            f.write("%d %g %g %g 1 %d\n" % (i + 1, x[0], x[1], x[2], i + 1))
        for i, m in enumerate(lines):
            f.write("%d -2 -2 0 2 2 0 1 %d 0\n" % (i + 1, 100 + i))
        f.write("$EndEntities\n")
        # nodes: one block per point entity, then interior nodes on curve 1
        f.write("$Nodes\n%d %d 1 %d\n" % (len(points) + 1, len(nodes), len(nodes)))
        named = set(points.values())
        for i, (p, t) in enumerate(points.items()):
            f.write("0 %d 0 1\n%d\n%.17g %.17g %.17g\n" % ((i + 1, t) + nodes[t - 1]))
        rest = [t for t in range(1, len(nodes) + 1) if t not in named]
        f.write("1 1 0 %d\n" % len(rest))
        for t in rest:
            f.write("%d\n" % t)
        for t in rest:
            f.write("%.17g %.17g %.17g\n" % nodes[t - 1])
        f.write("$EndNodes\n")
        n_el_total = sum(len(l) for l in lines.values())
        f.write("$Elements\n%d %d 1 %d\n" % (len(points) + len(lines), len(points) + n_el_total,
                                             len(points) + n_el_total))
        k = 1
        for i, (p, t) in enumerate(points.items()):
            f.write("0 %d 15 1\n%d %d\n" % (i + 1, k, t))
            k += 1
        for i, m in enumerate(lines):
            f.write("1 %d 1 %d\n" % (i + 1, len(lines[m])))
            for a, b in lines[m]:
                f.write("%d %d %d\n" % (k, a, b))
                k += 1
        f.write("$EndElements\n")


prm = ctx.prm("frame_joints.prm")
props = "Model/Frame/Member properties=" + "; ".join("%s: s, steel" % m for m in members)
common = ["Model/Frame/Nodes=", "Model/Frame/Members=", props]
for tag, writer in (("v2", write_v2), ("v4", write_v4)):
    path = os.path.join(ctx.work, "cross_%s.msh" % tag)
    writer(path)
    out, _ = ctx.run(prm, "cross_" + tag, common + ["Model/Frame/Mesh file=" + path])
    r = read_csv(out + "/history.csv")[0]
    ctx.check("Gmsh %s cross: w_C = -P L^3 / (48 E Iy) (m)" % tag, r["Cuz"],
              -P * L**3 / (48 * E * Iy), rel=1e-9)

# the mesh shipped with the parameter files
shipped = ctx.prm("frame_joints.msh")
out, _ = ctx.run(prm, "shipped", common + ["Model/Frame/Mesh file=" + shipped])
ctx.check("parameter_files/frame_joints.msh: w_C (m)", read_csv(out + "/history.csv")[0]["Cuz"],
          -P * L**3 / (48 * E * Iy), rel=1e-9)

bad = os.path.join(ctx.work, "branching.msh")
write_v2(bad, branching=True)
_, p = ctx.run(prm, "branching", common + ["Model/Frame/Mesh file=" + bad], expect_failure=True)
ctx.check_true("branching member refused", p.returncode != 0 and "branching.msh" in p.stderr
               and "east" in p.stderr, p.stderr.strip())
ctx.finish()

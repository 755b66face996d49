#!/usr/bin/python3
"""A Gmsh hexahedral mesh as a solid ('name: mesh, file.msh, material' of
Model/Frame/Solids, doc/user_guide.md 3.5): the prism of
parameter_files/beam_solid_prism.prm (2 x 0.4 x 0.3 m, 4 x 2 x 2
hexahedra) written here as an ASCII Gmsh file, in format 4.1 (with its
$Entities, the nodes numbered out of order, boundary quadrilaterals of a
surface as Gmsh saves them) and in format 2.2, in place of the 'box':

- static, axial load N at B1: u_x(B1) = N (L_a / (E A_a) + L_p / (E A_p) +
  L_b / (E A_b)), 1e-9 relative (exact, test_cases/beam_solid_prism.py),
  and u_x(B1) of the box solid, 1e-9 relative;
- static, the load of the .prm (shear, bending and torsion through the
  ties): the six displacements of B1 against the box solid's, 1e-9 of the
  largest (the same hexahedra, numbered otherwise: round-off only).
Damaged files are refused in one line naming the file, the line and the
fault (once a segmentation fault for a short node count or a collapsed
hexahedron, deal.II's reader trusting the file in a release build), and
hexahedra turned inside out are mirrored (the same u_x(B1)). Gmsh itself
is not needed."""
import os

from hati_test import Context, read_csv

ctx = Context()
prm = ctx.prm("beam_solid_prism.prm")
E, A_rod, A_prism = 2.1e11, 1.2e-2, 0.4 * 0.3
N = 1e5
x0, x1, cells = (0.0, -0.2, -0.15), (2.0, 0.2, 0.15), (4, 2, 2)


def block(x0, x1, cells):
    """The nodes (tag, x, y, z) and hexahedra (8 tags, Gmsh order) of a
    block; the tags are a permutation of 1..n so that the reader must map
    them."""
    nx, ny, nz = cells
    index = lambda i, j, k: i + (nx + 1) * (j + (ny + 1) * k)
    n = (nx + 1) * (ny + 1) * (nz + 1)
    tag = [1 + (7 * m + 3) % n for m in range(n)]  # 7 and n = 45 are coprime
    assert sorted(tag) == list(range(1, n + 1))
    nodes = []
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                x = [x0[d] + (x1[d] - x0[d]) * c / cells[d] for d, c in enumerate((i, j, k))]
                nodes.append((tag[index(i, j, k)], *x))
    hexes = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                # Gmsh: the face z- counter-clockwise, then the face z+
                corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                           (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
                hexes.append([tag[index(i + a, j + b, k + c)] for a, b, c in corners])
    quads = [[tag[index(0, j + b, k + c)] for b, c in ((0, 0), (0, 1), (1, 1), (1, 0))]
             for k in range(nz) for j in range(ny)]
    return nodes, hexes, quads


def write_msh41(path):
    nodes, hexes, quads = block(x0, x1, cells)
    n = len(nodes)
    with open(path, "w") as f:
        f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
        # one surface (tag 1, the face x = 0) and one volume (tag 1)
        f.write("$Entities\n0 0 1 1\n")
        f.write("1 0 -0.2 -0.15 0 0.2 0.15 0 0\n")
        f.write("1 0 -0.2 -0.15 2 0.2 0.15 0 1 1\n$EndEntities\n")
        f.write("$Nodes\n1 %d 1 %d\n3 1 0 %d\n" % (n, n, n))
        f.writelines("%d\n" % t for t, *_ in nodes)
        f.writelines("%.17g %.17g %.17g\n" % tuple(x) for _, *x in nodes)
        f.write("$EndNodes\n")
        m = len(quads) + len(hexes)
        f.write("$Elements\n2 %d 1 %d\n" % (m, m))
        f.write("2 1 3 %d\n" % len(quads))
        f.writelines("%d %s\n" % (e + 1, " ".join(map(str, q))) for e, q in enumerate(quads))
        f.write("3 1 5 %d\n" % len(hexes))
        f.writelines("%d %s\n" % (len(quads) + e + 1, " ".join(map(str, h)))
                     for e, h in enumerate(hexes))
        f.write("$EndElements\n")


def write_msh22(path):
    nodes, hexes, _ = block(x0, x1, cells)
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write("$Nodes\n%d\n" % len(nodes))
        f.writelines("%d %.17g %.17g %.17g\n" % (t, *x) for t, *x in nodes)
        f.write("$EndNodes\n$Elements\n%d\n" % len(hexes))
        # elm-number elm-type number-of-tags (physical, elementary) nodes
        f.writelines("%d 5 2 1 1 %s\n" % (e + 1, " ".join(map(str, h)))
                     for e, h in enumerate(hexes))
        f.write("$EndElements\n")


def static(tag, solid, load=None):
    sets = ["Analysis/Type=static", "Model/Frame/Solids=" + solid]
    if load is not None:
        sets.append("Model/Frame/Nodal loads=" + load)
    out, p = ctx.run(prm, tag, sets)
    return read_csv(out + "/history.csv"), p


box = "prism: box, %g, %g, %g, %g, %g, %g, %d, %d, %d, steel" % (*x0, *x1, *cells)
axial = "B1: %g, 0, 0" % N
h_box, _ = static("box_axial", box, axial)
g_box, _ = static("box_general", box)
columns = ["B1" + c for c in ("ux", "uy", "uz", "urx", "ury", "urz")]
largest = max(abs(float(g_box[c][0])) for c in columns)
exact = N * (1 / (E * A_rod) + 2 / (E * A_prism) + 1 / (E * A_rod))
ctx.check("box: static u_x(B1) against N sum L/(E A) (m)", float(h_box["B1ux"][0]), exact,
          rel=1e-9)

os.makedirs(ctx.work, exist_ok=True)
for version, write in (("4.1", write_msh41), ("2.2", write_msh22)):
    msh = os.path.join(ctx.work, "prism%s.msh" % version.replace(".", ""))
    write(msh)
    solid = "prism: mesh, %s, steel" % msh
    h, p = static("mesh%s_axial" % version, solid, axial)
    ctx.check_true("Gmsh %s: the terminal describes 16 hexahedra" % version,
                   "16 hexahedra" in p.stdout)
    ctx.check("Gmsh %s: static u_x(B1) against N sum L/(E A) (m)" % version,
              float(h["B1ux"][0]), exact, rel=1e-9)
    ctx.check("Gmsh %s: static u_x(B1) against the box (m)" % version,
              float(h["B1ux"][0]), float(h_box["B1ux"][0]), rel=1e-9)
    g, _ = static("mesh%s_general" % version, solid)
    for c in columns:
        ctx.check("Gmsh %s: %s under the .prm's load against the box" % (version, c),
                  float(g[c][0]), float(g_box[c][0]), abs_tol=1e-9 * largest)

# every hexahedron inside out (its faces z- and z+ swapped): mirrored
text = open(os.path.join(ctx.work, "prism41.msh")).read().split("\n")
lines = list(text)
first = lines.index("3 1 5 16") + 1
for i in range(first, first + 16):
    e, *n = lines[i].split()
    lines[i] = " ".join([e] + n[4:] + n[:4])
inverted = os.path.join(ctx.work, "inverted.msh")
open(inverted, "w").write("\n".join(lines))
h, _ = static("inverted_axial", "prism: mesh, %s, steel" % inverted, axial)
ctx.check("hexahedra inside out: static u_x(B1) against the box (m)", float(h["B1ux"][0]),
          float(h_box["B1ux"][0]), rel=1e-9)


def damaged(name, edit, fragment):
    """The 4.1 file with edit(lines) applied: one line naming the fault."""
    lines = list(text)
    edit(lines)
    path = os.path.join(ctx.work, name + ".msh")
    open(path, "w").write("\n".join(lines))
    _, p = ctx.run(prm, name, ["Analysis/Type=static",
                               "Model/Frame/Solids=prism: mesh, %s, steel" % path],
                   expect_failure=True)
    err = p.stderr.strip()
    ok = (p.returncode == 1 and len(err.splitlines()) == 1
          and err.startswith("hati: error: Model/Frame/Solids: solid 'prism': '%s'" % path)
          and fragment in err)
    ctx.check_true("damaged file refused: " + name, ok, "(exit %d) %s" % (p.returncode, err))


def replace(old, new, count=1):
    def edit(lines):
        k = [i for i, l in enumerate(lines) if l == old][count - 1]
        lines[k] = new
    return edit


hexes = text.index("3 1 5 16")
damaged("short_node_count", replace("1 45 1 45", "1 40 1 45"),
        "line 101: the blocks hold 45 nodes, the header 40")
damaged("long_element_count", replace("2 20 1 20", "2 30 1 30"),
        "the blocks hold 20 elements, the header 30")
damaged("collapsed", lambda l: l.__setitem__(hexes + 1, "5 1 1 3 4 5 6 7 8"),
        "element 5 (a hexahedron) is collapsed or twisted")
damaged("twisted", lambda l: l.__setitem__(
    hexes + 1, " ".join([l[hexes + 1].split()[i] for i in (0, 2, 1, 3, 4, 5, 6, 7, 8)])),
        "is collapsed or twisted: its Jacobian is not positive at every corner")
damaged("unknown_node", lambda l: l.__setitem__(
    hexes + 1, " ".join(l[hexes + 1].split()[:-1] + ["999"])),
        "node 999 is not in $Nodes")
damaged("binary", replace("4.1 0 8", "4.1 1 8"), "a binary Gmsh file")
damaged("format_40", replace("4.1 0 8", "4 0 8"), "Gmsh format 4 is not read")
damaged("second_order", replace("3 1 5 16", "3 1 12 16"), "is of Gmsh type 12")
damaged("cut_short", lambda l: l.__delitem__(slice(hexes + 3, None)),
        "unexpected end of the file")
damaged("twice", lambda l: l.__setitem__(hexes + 2, "6 " + " ".join(l[hexes + 1].split()[1:])),
        "has the same eight nodes as an earlier one")

# issue #59, finding 5: solids stay apart unless a tie joins them. A box
# sharing the prism's face x = 2 keeps its own DoFs there: 3 (9 x 5 x 5) +
# 3 (5 x 5 x 5) = 1050 solid DoFs (merged: 975), and the prism's tie on that
# face still finds the prism's own face; an overlapping box is refused
import subprocess as _sp
two = ("prism: box, 0, -0.2, -0.15, 2, 0.2, 0.15, 4, 2, 2, steel; "
       "p2: box, 2, -0.2, -0.15, 3, 0.2, 0.15, 2, 2, 2, steel")
out, p = ctx.run(prm, "shared_face", ["Analysis/Type=static", "Model/Frame/Solids=" + two,
                                      "Model/Frame/Solid supports=p2: x=3"])
ctx.check_true("two boxes sharing a face: 1050 solid DoFs (kept apart)",
               "2 solids: 24 hexahedra of degree 2, 1050 DoFs" in p.stdout, p.stdout[:600])
over = ("prism: box, 0, -0.2, -0.15, 2, 0.2, 0.15, 4, 2, 2, steel; "
        "p2: box, 1, -0.2, -0.15, 3, 0.2, 0.15, 2, 1, 1, steel")
out, p = ctx.run(prm, "overlap", ["Analysis/Type=static", "Model/Frame/Solids=" + over],
                 expect_failure=True)
ctx.check_true("overlapping solids refused in one line",
               p.returncode == 1 and "solid 'p2' overlaps solid 'prism'" in p.stderr,
               p.stderr.strip())
ctx.finish()

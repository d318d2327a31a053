#!/usr/bin/env python3
"""Planar input as Triangle users write it (issue 12, item 8 and the --convex-hull half of
item 9; design decision 8), through `certimesh mesh` and `certimesh check --domain`. Each case
is a .poly written here; each mesh is read back from its .node/.ele/.edge files and checked
with exact fractions by oracles of this file, not by certimesh:
  * the triangles are counterclockwise and their areas add up to the domain's area (computed
    here from the case's own description);
  * every isolated vertex inside the domain is a mesh vertex, one outside is not;
  * every segment with the domain on a side is a union of mesh edges (the mesh vertices
    exactly on it, in order along it, are joined by mesh edges from one end to the other);
  * a segment eaten by a hole touches no mesh vertex;
  * real regional attributes are the .ele attribute of the triangles of their region, and in
    a region with a maximum area every triangle's area is at most that bound (the decimal
    written in the .poly, as a fraction);
  * markers: the .node marker of a marked vertex and the .edge markers of the pieces of a
    marked segment; Gmsh physical tags of the segments;
  * --convex-hull: the mesh's area is the hull's (monotone chain here), every point a vertex;
  * a hole point outside every face is refused with `error:` naming it, by `mesh` (exit 1)
    and by `check --domain` (exit 1), and no file is written;
  * `check --domain` refuses a mesh that leaves a domain face unmeshed beside an eaten segment
    or an isolated domain vertex out, and accepts one against a domain whose extra segments
    and vertices are all eaten or outside (domains built here with known faces).
Usage: cli_planar_input_test.py CERTIMESH.
"""
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from planar_oracle import FAILURES, area, fail, hull_area, orient, read_mesh  # noqa: E402


def mesh_edges(triangles):
    e = set()
    for t in triangles:
        for i in range(3):
            e.add(frozenset((t[i], t[(i + 1) % 3])))
    return e


def on_closed_segment(p, a, b):
    return orient(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def near_segment(p, a, b):
    """p within rounding of segment ab (design decision 2: a Steiner point is the rounding of an
    exact point of it): |orient| at most 2^-50 |b - a| (|coordinates| + 1), inside its span."""
    scale = max(abs(x) for x in (*a, *b)) + 1
    t = (p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1])
    length = abs(b[0] - a[0]) + abs(b[1] - a[1])
    return abs(orient(a, b, p)) <= F(1, 2**50) * length * scale and 0 <= t <= (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2


def covered_by_edges(points, triangles, a, b):
    """Whether segment ab is a union of mesh edges: the mesh vertices on it (within rounding),
    sorted along it, start at a, end at b, and each consecutive pair is a mesh edge."""
    used = sorted({v for t in triangles for v in t})
    on = [v for v in used if near_segment(points[v], a, b)]
    on.sort(key=lambda v: (points[v][0] - a[0]) * (b[0] - a[0]) + (points[v][1] - a[1]) * (b[1] - a[1]))
    if not on or points[on[0]] != a or points[on[-1]] != b:
        return False
    edges = mesh_edges(triangles)
    return all(frozenset((on[i], on[i + 1])) in edges for i in range(len(on) - 1))


def write_poly(path, points, segments, holes=(), regions=(), point_markers=None, segment_markers=None):
    with open(path, "w") as f:
        f.write(f"{len(points)} 2 0 {1 if point_markers else 0}\n")
        for i, (x, y) in enumerate(points):
            f.write(f"{i + 1} {x} {y}" + (f" {point_markers[i]}" if point_markers else "") + "\n")
        f.write(f"{len(segments)} {1 if segment_markers else 0}\n")
        for i, (a, b) in enumerate(segments):
            f.write(f"{i + 1} {a + 1} {b + 1}" + (f" {segment_markers[i]}" if segment_markers else "") + "\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes):
            f.write(f"{i + 1} {x} {y}\n")
        f.write(f"{len(regions)}\n")
        for i, r in enumerate(regions):
            f.write(f"{i + 1} " + " ".join(str(v) for v in r) + "\n")


def run(*args):
    return subprocess.run(list(args), capture_output=True, text=True, timeout=120)


class Case:
    def __init__(self, certimesh, work, name):
        self.certimesh, self.name = certimesh, name
        self.poly = os.path.join(work, name + ".poly")
        self.out = os.path.join(work, name + "_out")

    def mesh(self, *options):
        r = run(self.certimesh, "mesh", self.poly, "-o", self.out + ".node", "--quiet", *options)
        if r.returncode != 0:
            fail(self.name, f"mesh exit {r.returncode}: {r.stderr.strip()}")
            return None
        check = run(self.certimesh, "check", self.out + ".ele", "--domain", self.poly)
        if check.returncode != 0:
            fail(self.name, f"check --domain of the written mesh against the .poly: {check.stdout.strip()} {check.stderr.strip()}")
        return read_mesh(self.out)

    def basic(self, mesh, domain_area, sloped=False):
        """Counterclockwise triangles whose areas add up to the domain's: exactly, or with
        sloped boundary segments (rounded Steiner points) within 2^-40 of it, relatively."""
        points, _, triangles, _, _ = mesh
        if any(area(points, t) <= 0 for t in triangles):
            fail(self.name, "a triangle is not counterclockwise")
        total = sum(area(points, t) for t in triangles)
        if total != domain_area and not (sloped and abs(total - domain_area) <= domain_area / 2**40):
            fail(self.name, f"the triangles' area is {total}, the domain's {domain_area}")


def square(side):  # corners of [0, side]^2 counterclockwise, and its four sides
    return [(0, 0), (side, 0), (side, side), (0, side)], [(0, 1), (1, 2), (2, 3), (3, 0)]


def vertex_of(points, p):
    return p in set(points)


def case_isolated(c, options):
    pts, segs = square(4)
    inside = [(1, 1), ("2.5", 3), (3, "0.75"), ("0.125", "3.875")]
    outside = [(10, 10)]
    write_poly(c.poly, pts + inside + outside, segs)
    m = c.mesh(*options)
    if not m:
        return
    c.basic(m, F(16))
    for p in inside:
        if not vertex_of(m[0], (F(p[0]), F(p[1]))):
            fail(c.name, f"isolated vertex {p} inside the domain is not a mesh vertex")
    if vertex_of(m[0], (F(10), F(10))):
        fail(c.name, "the vertex outside the domain is in the mesh")


def case_cuts(c, options):
    # A crack from the left side to the middle, and a segment tree floating in the square.
    pts = [(0, 0), (4, 0), (4, 4), (0, 4), (0, 2), (2, 2), (3, 1), (3, "2.5"), ("2.5", 3), ("3.5", 3), (1, 3), (1, "3.5")]
    segs = [(0, 1), (1, 2), (2, 3), (3, 4), (4, 0), (4, 5), (6, 7), (7, 8), (7, 9), (10, 11)]
    write_poly(c.poly, pts, segs)
    m = c.mesh(*options)
    if not m:
        return
    c.basic(m, F(16))
    fp = [(F(x), F(y)) for x, y in pts]
    for a, b in segs:
        if not covered_by_edges(m[0], m[2], fp[a], fp[b]):
            fail(c.name, f"segment {pts[a]}-{pts[b]} is not a union of mesh edges")


def case_eaten(c, options):
    # A square with a square hole; inside the hole a dangling segment and a closed triangle
    # with its own hole point; outside everything a segment. Holes eat what has no domain face.
    pts = [(0, 0), (4, 0), (4, 4), (0, 4), (1, 1), (3, 1), (3, 3), (1, 3),
           ("1.5", "2.5"), ("2.5", "2.5"), ("1.25", "1.25"), ("1.75", "1.25"), ("1.5", "1.75"), (5, 0), (6, 1)]
    segs = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (8, 9), (10, 11), (11, 12), (12, 10), (13, 14)]
    write_poly(c.poly, pts, segs, holes=[(2, 2), ("1.5", "1.4")])
    m = c.mesh(*options)
    if not m:
        return
    c.basic(m, F(12))
    for p in pts[8:]:
        if vertex_of(m[0], (F(p[0]), F(p[1]))):
            fail(c.name, f"vertex {p} of an eaten segment is in the mesh")


def case_island_in_hole(c, options):
    # The neighbour of case_eaten: a closed triangle inside the hole WITHOUT a hole point is a
    # face of the domain (Triangle meshes it): its area counts.
    pts = [(0, 0), (4, 0), (4, 4), (0, 4), (1, 1), (3, 1), (3, 3), (1, 3), ("1.25", "1.25"), ("1.75", "1.25"), ("1.5", "1.75")]
    segs = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (8, 9), (9, 10), (10, 8)]
    write_poly(c.poly, pts, segs, holes=[(2, 2)])
    m = c.mesh(*options)
    if not m:
        return
    c.basic(m, F(12) + F(1, 2) * F(1, 2) * F(1, 2), sloped=True)  # the island's slanted sides


def two_regions(c, left, right, sloped=False):
    # [0,4]^2 split by the interface x = 2 (or, sloped, by the diagonal-ish segment to (3, 4)).
    top = (3, 4) if sloped else (2, 4)
    pts = [(0, 0), (2, 0), (4, 0), (4, 4), top, (0, 4)]
    segs = [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5), (5, 0), (1, 4)]
    write_poly(c.poly, pts, segs, regions=[(1, 1) + left, ("3.5", 1) + right])
    return [(F(x), F(y)) for x, y in pts]


def left_of_interface(points, t, p, q):
    centre = tuple(sum(points[v][k] for v in t) / 3 for k in range(2))
    return orient(p, q, centre) > 0


def case_attributes(c, options):
    fp = two_regions(c, ("0.05",), ("2.5",))
    m = c.mesh(*options)
    if not m:
        return
    c.basic(m, F(16))
    points, _, triangles, attributes, _ = m
    if attributes is None:
        fail(c.name, "the .ele has no attribute column")
        return
    for t, a in zip(triangles, attributes):
        want = F("0.05") if left_of_interface(points, t, fp[1], fp[4]) else F("2.5")
        if F(a) != want:
            fail(c.name, f"triangle {t} has attribute {a}, its region {want}")
            return


def case_max_area(c, options, sloped=False):
    bound = "0.05"
    fp = two_regions(c, (1, bound), (2, -1), sloped)
    m = c.mesh(*options)
    if not m:
        return
    domain_area = F(16)
    c.basic(m, domain_area)
    points, _, triangles, attributes, _ = m
    left = [t for t in triangles if left_of_interface(points, t, fp[1], fp[4])]
    worst = max(area(points, t) for t in left)
    if worst > F(bound):
        fail(c.name, f"a triangle of the bounded region has area {float(worst)} > {bound}")
    right = [t for t in triangles if not left_of_interface(points, t, fp[1], fp[4])]
    if max(area(points, t) for t in right) <= F(bound):
        fail(c.name, "the unbounded region is as fine as the bounded one: the bound leaked (test no longer discriminates)")
    print(f"  {c.name}: {len(left)} triangles in the bounded region, largest area {float(worst):.5f} <= {bound}")


def case_markers(c, options):
    # Triangle's box.poly: a vertex marker 33, segment markers 5 and 10.
    pts = [(0, 0), (0, 3), (3, 0), (3, 3), (1, 1), (1, 2), (2, 1), (2, 2)]
    segs = [(0, 1), (4, 6), (6, 7), (7, 5), (5, 4), (1, 3), (3, 2), (2, 0)]
    write_poly(c.poly, pts, segs, holes=[("1.5", "1.5")], point_markers=[0, 0, 0, 33, 0, 0, 0, 0],
               segment_markers=[5, 0, 0, 10, 0, 0, 0, 0])
    m = c.mesh(*options, "--size", "0.5")
    if not m:
        return
    points, markers, triangles, _, edges = m
    at = {p: i for i, p in enumerate(points)}
    if markers[at[(F(3), F(3))]] != 33:
        fail(c.name, f"vertex (3, 3) has marker {markers[at[(F(3), F(3))]]}, not 33")
    for (a, b), want in (((0, 1), 5), ((7, 5), 10), ((1, 3), 0)):
        pa, pb = (F(pts[a][0]), F(pts[a][1])), (F(pts[b][0]), F(pts[b][1]))
        pieces = [e for e in edges if on_closed_segment(points[e[0]], pa, pb) and on_closed_segment(points[e[1]], pa, pb)]
        if len(pieces) < 2 or any(e[2] != want for e in pieces):
            fail(c.name, f"the {len(pieces)} edges on segment {pts[a]}-{pts[b]} have markers {[e[2] for e in pieces]}, not all {want}")
        inner = {v for e in pieces for v in e[:2]} - {at[pa], at[pb]}
        if want and any(markers[v] != want for v in inner):
            fail(c.name, f"the Steiner vertices on segment {pts[a]}-{pts[b]} do not carry its marker {want}")
    msh = c.out + ".msh"
    r = run(c.certimesh, "mesh", c.poly, "-o", msh, "--quiet", "--size", "0.5", *options)
    if r.returncode != 0:
        fail(c.name, f"mesh to .msh: {r.stderr.strip()}")
        return
    tags = subprocess.run(["/usr/bin/python3", "-c",
                           "import meshio,sys; m=meshio.read(sys.argv[1]); "
                           "print(sorted({int(x) for b, d in zip(m.cells, m.cell_data['gmsh:physical']) if b.type == 'line' for x in d}))",
                           msh], capture_output=True, text=True)
    if tags.returncode != 0 or "5" not in tags.stdout or "10" not in tags.stdout:
        fail(c.name, f"Gmsh physical tags of the lines: {tags.stdout.strip()} {tags.stderr.strip()[-200:]}")


def case_convex_hull(c, options):
    # Interior points, a dangling segment and an open polyline, no closed loop: only the hull
    # bounds a face.
    pts = [(0, 0), ("4.5", "0.5"), (5, 3), (2, "4.25"), ("-0.5", 2), (1, 1), (2, "1.5"), (3, 2), ("1.5", 3), ("3.5", "2.75")]
    segs = [(5, 6), (6, 7), (8, 9)]
    write_poly(c.poly, pts, segs)
    saved = c.out + "_domain.poly"
    r = run(c.certimesh, "mesh", c.poly, "-o", c.out + ".node", "--quiet", "--convex-hull", "--save-domain", saved, *options)
    if r.returncode != 0:
        fail(c.name, f"mesh --convex-hull exit {r.returncode}: {r.stderr.strip()}")
        return
    check = run(c.certimesh, "check", c.out + ".ele", "--domain", saved)
    if check.returncode != 0:
        fail(c.name, f"check --domain against the saved hull domain: {check.stdout.strip()}")
    m = read_mesh(c.out)
    fp = [(F(x), F(y)) for x, y in pts]
    c.basic(m, hull_area(fp), sloped=True)
    for p in fp:
        if not vertex_of(m[0], p):
            fail(c.name, f"point {p} is not a mesh vertex")
    for a, b in segs:
        if not covered_by_edges(m[0], m[2], fp[a], fp[b]):
            fail(c.name, f"segment {pts[a]}-{pts[b]} is not a union of mesh edges")
    # Without --convex-hull the same file bounds nothing: refused, nothing written.
    r = run(c.certimesh, "mesh", c.poly, "-o", c.out + "_plain.node", "--quiet", *options)
    if r.returncode == 0 or "error:" not in r.stderr or os.path.exists(c.out + "_plain.node"):
        fail(c.name, f"the same file without --convex-hull: exit {r.returncode}, {r.stderr.strip()}")


def case_hole_outside(c, options):
    pts, segs = square(4)
    write_poly(c.poly, pts, segs, holes=[(10, "10.5")])
    r = run(c.certimesh, "mesh", c.poly, "-o", c.out + ".node", "--quiet", *options)
    if r.returncode != 1 or "error:" not in r.stderr or "hole point 0" not in r.stderr or "10.5" not in r.stderr:
        fail(c.name, f"mesh: exit {r.returncode}, stderr {r.stderr.strip()!r}")
    if os.path.exists(c.out + ".node"):
        fail(c.name, "a file was written")
    # Neighbours: a hole point on a segment or at a segment's vertex does not say which face it
    # empties (the ring or the inner square): refused by name too.
    for k, hole in enumerate(((2, 1), (3, 3))):
        on = f"{c.poly[:-5]}_on{k}.poly"
        write_poly(on, pts + [(1, 1), (3, 1), (3, 3), (1, 3)], segs + [(4, 5), (5, 6), (6, 7), (7, 4)], holes=[hole])
        r = run(c.certimesh, "mesh", on, "-o", c.out + f"_on{k}.node", "--quiet", *options)
        if r.returncode != 1 or "hole point 0" not in r.stderr or "lies on" not in r.stderr:
            fail(c.name, f"hole point {hole} on a segment: exit {r.returncode}, {r.stderr.strip()!r}")
    good = c.poly[:-5] + "_good.poly"
    write_poly(good, pts, segs)
    r = run(c.certimesh, "mesh", good, "-o", c.out + "_good.node", "--quiet", *options)
    if r.returncode != 0:
        fail(c.name, f"the square without the hole: {r.stderr.strip()}")
        return
    r = run(c.certimesh, "check", c.out + "_good.ele", "--domain", c.poly)
    if r.returncode != 1 or "error:" not in r.stderr or "hole point 0" not in r.stderr or "10.5" not in r.stderr:
        fail(c.name, f"check --domain: exit {r.returncode}, {r.stdout.strip()} {r.stderr.strip()}")


def case_refusals(c, options):
    # Neighbours that stay refused: an isolated vertex inside a segment (a T-junction) and an
    # isolated vertex on another vertex (a duplicate).
    pts, segs = square(4)
    for extra, words in (((2, 0), "lies inside segment"), ((4, 4), "both at")):
        write_poly(c.poly, pts + [extra], segs)
        r = run(c.certimesh, "mesh", c.poly, "-o", c.out + ".node", "--quiet", *options)
        if r.returncode != 1 or "error:" not in r.stderr or words not in r.stderr:
            fail(c.name, f"isolated vertex {extra}: exit {r.returncode}, {r.stderr.strip()!r}")


def case_certificate(c, options):
    """`check --domain` reads the domain by the same rules, and refuses a mesh that leaves out
    what the rules keep: each mesh here is checked against domains whose faces are known by
    construction (a domain face left unmeshed, an isolated vertex that is not a mesh vertex)."""
    pts, segs = square(4)
    plain = c.poly[:-5] + "_plain.poly"
    write_poly(plain, pts, segs)
    holed = c.poly[:-5] + "_holed.poly"
    hole_pts = pts + [(1, 1), (3, 1), (3, 3), (1, 3)]
    hole_segs = segs + [(4, 5), (5, 6), (6, 7), (7, 4)]
    write_poly(holed, hole_pts, hole_segs, holes=[(2, 2)])
    meshes = {}
    for name, poly in (("plain", plain), ("holed", holed)):
        out = f"{c.out}_{name}"
        r = run(c.certimesh, "mesh", poly, "-o", out + ".node", "--quiet", *options)
        if r.returncode != 0:
            fail(c.name, f"mesh {name}: {r.stderr.strip()}")
            return
        meshes[name] = out + ".ele"
    island = [("1.25", "1.25"), ("1.75", "1.25"), ("1.5", "1.75")]
    outside = [(5, 0), (6, 0), (6, 1)]
    verdicts = [  # (mesh, points, segments, holes, valid?, what the refusal names)
        ("plain", pts + outside, segs + [(4, 5), (5, 6), (6, 4)], [], False, "not covered"),
        ("plain", pts + outside, segs + [(4, 5), (5, 6), (6, 4)], [("5.75", "0.25")], True, ""),
        ("plain", pts + [(1, 1)], segs, [], False, "domain vertex 4"),
        ("plain", pts + [(10, 10)], segs, [], True, ""),
        ("plain", pts + [(5, 0), (6, 1)], segs + [(4, 5)], [], True, ""),
        ("holed", hole_pts + island, hole_segs + [(8, 9), (9, 10), (10, 8)], [(2, 2)], False, "not covered"),
        ("holed", hole_pts + island, hole_segs + [(8, 9), (9, 10), (10, 8)], [(2, 2), ("1.5", "1.4")], True, ""),
        ("holed", hole_pts + island[:2], hole_segs + [(8, 9)], [(2, 2)], True, ""),
        ("holed", hole_pts + [("1.5", "1.5")], hole_segs, [(2, 2)], True, ""),
    ]
    for k, (mesh, p, s, h, valid, words) in enumerate(verdicts):
        domain = f"{c.poly[:-5]}_domain{k}.poly"
        write_poly(domain, p, s, holes=h)
        r = run(c.certimesh, "check", meshes[mesh], "--domain", domain)
        if (r.returncode == 0) != valid or (not valid and (r.returncode != 1 or words not in r.stdout)):
            fail(c.name, f"domain {k} against the {mesh} mesh: exit {r.returncode}, {r.stdout.strip()[-200:]}")


def main():
    certimesh = sys.argv[1]
    cases = [case_isolated, case_cuts, case_eaten, case_island_in_hole, case_attributes, case_max_area,
             case_markers, case_convex_hull, case_hole_outside, case_refusals, case_certificate]
    with tempfile.TemporaryDirectory() as work:
        for options in ((), ("--size", "0.4"), ("--algorithm", "delaunay")):
            tag = "_".join(o.strip("-") for o in options) or "default"
            for case in cases:
                c = Case(certimesh, work, f"{case.__name__[5:]}_{tag}")
                case(c, options)
            case_max_area(Case(certimesh, work, f"max_area_sloped_{tag}"), options, sloped=True)
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        return 1
    print("all planar-input cases hold")
    return 0


if __name__ == "__main__":
    sys.exit(main())

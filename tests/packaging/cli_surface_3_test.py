#!/usr/bin/env python3
"""`certimesh mesh SURFACE -o OUT.mesh` for closed surfaces (issue 13, items 4-6), checked with
exact fractions against oracles written here: every tetrahedron positive; the volume of the
tetrahedra equals the volume the surface encloses (the divergence theorem over the input
triangles, by winding: an inward inner shell subtracts its cavity); the boundary faces are the
input triangles, one for one, same orientation, on bit-identical vertices (no Steiner point on
the surface by default); `certimesh check OUT --domain SURFACE` passes. Surfaces: a cube (OFF,
ASCII STL and Medit), Schönhardt's twisted prism (needs an interior Steiner point), a cube with
an inward cavity cube, a finely triangulated cube refined with --size. An open cube and two
boxes that touch are refused with `error:` naming triangles, exit 1, no file; --max-steiner stops the
refinement with exit 4 and a certified mesh; TetGen hole and region points (a cavity made by a hole point, exact volume and labels; points outside, on the surface, or removing everything refused by name, exit 2, no file).
Usage: cli_surface_3_test.py CERTIMESH.
"""
import math
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_report import report  # noqa: E402

FACES = ((1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1))  # outward faces of a positive tetrahedron


def det3(u, v, w):
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def vol6(a, b, c, d):
    return det3([b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)], [d[i] - a[i] for i in range(3)])


def box(lo, hi, inward=False):
    """The 12 triangles of an axis box, outward (or inward), as coordinate triples."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    p = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0), (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    tris = []
    for a, b, c, d in quads:
        tris += [(p[a], p[b], p[c]), (p[a], p[c], p[d])]
    return [(t[0], t[2], t[1]) for t in tris] if inward else tris


def fine_cube(n):
    """The unit cube, each face a grid of n x n squares cut in two: 12 n^2 triangles."""
    tris = []
    def g(i):
        return F(i, n)
    for axis in range(3):
        for side in (0, 1):
            for i in range(n):
                for j in range(n):
                    def pt(u, v):
                        q = [None] * 3
                        q[axis] = F(side)
                        q[(axis + 1) % 3], q[(axis + 2) % 3] = g(u), g(v)
                        return tuple(q)
                    a, b, c, d = pt(i, j), pt(i + 1, j), pt(i + 1, j + 1), pt(i, j + 1)
                    quad = [(a, b, c), (a, c, d)]
                    # outward: (u, v, axis) right-handed for side 1
                    tris += quad if side == 1 else [(t[0], t[2], t[1]) for t in quad]
    return tris


def schonhardt():
    """Schönhardt's prism: a triangle twisted by 30 degrees over another, its quadrilaterals cut
    along their reflex diagonals (no tetrahedralization without a Steiner point)."""
    def ring(z, turn):
        return [(round(math.cos(2 * math.pi * k / 3 + turn), 6), round(math.sin(2 * math.pi * k / 3 + turn), 6), z)
                for k in range(3)]
    b, t = ring(0.0, 0.0), ring(1.0, math.pi / 6)
    tris = [(b[0], b[2], b[1]), (t[0], t[1], t[2])]
    for k in range(3):
        k1 = (k + 1) % 3
        tris += [(b[k], b[k1], t[k1]), (b[k], t[k1], t[k])]
    return tris


def index(tris):
    points, ids, faces = [], {}, []
    for t in tris:
        f = []
        for p in t:
            key = tuple(float(x) for x in p)
            if key not in ids:
                ids[key] = len(points)
                points.append(key)
            f.append(ids[key])
        faces.append(tuple(f))
    return points, faces


def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        for p in points:
            f.write(" ".join(repr(x) for x in p) + "\n")
        for t in faces:
            f.write("3 " + " ".join(map(str, t)) + "\n")


def write_stl(path, points, faces):
    with open(path, "w") as f:
        f.write("solid s\n")
        for t in faces:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for v in t:
                f.write("   vertex " + " ".join(repr(x) for x in points[v]) + "\n")
            f.write("  endloop\n endfacet\n")
        f.write("endsolid s\n")


def write_medit(path, points, faces):
    with open(path, "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n" % len(points))
        for p in points:
            f.write(" ".join(repr(x) for x in p) + " 0\n")
        f.write("Triangles\n%d\n" % len(faces))
        for t in faces:
            f.write(" ".join(str(v + 1) for v in t) + " 0\n")
        f.write("End\n")


def read_medit(path):
    words = open(path).read().split()
    points, tets, i = [], [], 0
    while i < len(words):
        w = words[i]
        if w == "Vertices":
            n = int(words[i + 1]); i += 2
            for _ in range(n):
                points.append(tuple(F(float(x)) for x in words[i:i + 3])); i += 4
        elif w == "Tetrahedra":
            n = int(words[i + 1]); i += 2
            for _ in range(n):
                tets.append(tuple(int(x) - 1 for x in words[i:i + 4])); i += 5
        elif w in ("Triangles", "Edges"):
            n = int(words[i + 1]); i += 2 + n * (4 if w == "Triangles" else 3)
        else:
            i += 1
    return points, tets


def enclosed_volume6(tris):
    origin = (F(0), F(0), F(0))
    return sum(vol6(origin, *[tuple(F(float(x)) for x in p) for p in t]) for t in tris)  # as written


def canonical(face):  # a cyclic triple of coordinate tuples, rotated to start at its least
    k = face.index(min(face))
    return face[k:] + face[:k]


def check(certimesh, tmp, name, tris, ext, failures, *options):
    points, faces = index(tris)
    path = os.path.join(tmp, f"{name}{ext}")
    {".off": write_off, ".stl": write_stl, ".mesh": write_medit}[ext](path, points, faces)
    out = os.path.join(tmp, f"{name}_out.mesh")
    run = subprocess.run([certimesh, "mesh", path, "-o", out, "--quiet", *options], capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        failures.append(f"{name}{ext}: exit {run.returncode}: {run.stderr.strip()}")
        return
    mesh_points, tets = read_medit(out)
    if any(vol6(*(mesh_points[v] for v in t)) <= 0 for t in tets):
        failures.append(f"{name}: a tetrahedron is not positive")
    volume = sum(vol6(*(mesh_points[v] for v in t)) for t in tets)
    if volume != enclosed_volume6(tris):
        failures.append(f"{name}: the tetrahedra hold {volume / 6}, the surface encloses {enclosed_volume6(tris) / 6}")
    held = {}
    for t in tets:
        for f in FACES:
            face = tuple(mesh_points[t[j]] for j in f)
            held.setdefault(frozenset(face), []).append(face)
    boundary = {canonical(fs[0]) for fs in held.values() if len(fs) == 1}
    wanted = {canonical(tuple(tuple(F(float(x)) for x in p) for p in t)) for t in tris}
    if boundary != wanted:
        failures.append(f"{name}: the boundary faces are not the input triangles ({len(boundary)} faces, {len(wanted)} triangles)")
    checked = subprocess.run([certimesh, "check", out, "--domain", path], capture_output=True, text=True, timeout=300)
    if checked.returncode != 0:
        failures.append(f"{name}: check --domain exited {checked.returncode}: {checked.stdout.strip()[-300:]}")
    return len(mesh_points) - len(points), len(tets)


def refused(certimesh, tmp, name, tris, failures):
    points, faces = index(tris)
    path, out = os.path.join(tmp, name + ".off"), os.path.join(tmp, name + "_out.mesh")
    write_off(path, points, faces)
    run = subprocess.run([certimesh, "mesh", path, "-o", out], capture_output=True, text=True, timeout=60)
    if run.returncode != 1 or "error:" not in run.stderr or "triangle" not in run.stderr or os.path.exists(out):
        failures.append(f"{name}: exit {run.returncode}, stderr {run.stderr.strip()!r}, written {os.path.exists(out)}")


def main():
    certimesh = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for ext in (".off", ".stl", ".mesh"):
            check(certimesh, tmp, "cube", box((0, 0, 0), (1, 1, 1)), ext, failures)
        steiner = check(certimesh, tmp, "schonhardt", schonhardt(), ".off", failures)
        if steiner and steiner[0] < 1:
            failures.append("schonhardt: no Steiner point, but the prism has no tetrahedralization without one")
        check(certimesh, tmp, "cavity", box((0, 0, 0), (4, 4, 4)) + box((1, 1, 1), (2, 3, 2), inward=True), ".off", failures)
        fine = check(certimesh, tmp, "fine_cube", fine_cube(6), ".off", failures, "--size", "0.15")
        if fine and fine[1] < 1000:
            failures.append(f"fine_cube --size 0.15: only {fine[1]} tetrahedra")
        # --max-steiner caps the 3D refinement: exit 4, the mesh written and certified.
        points, faces = index(fine_cube(4))
        path, out = os.path.join(tmp, "capped.off"), os.path.join(tmp, "capped_out.mesh")
        write_off(path, points, faces)
        counts = []
        for cap in (50, 60):  # recovery is the same both times: the vertex counts differ by 10
            run = subprocess.run([certimesh, "mesh", path, "-o", out, "--size", "0.01", "--max-steiner", str(cap)],
                                 capture_output=True, text=True, timeout=120)
            counts.append(len(read_medit(out)[0]) if os.path.exists(out) else 0)
            if run.returncode != 4 or "--max-steiner" not in run.stderr:
                failures.append(f"capped at {cap}: exit {run.returncode}, stderr {run.stderr.strip()!r}")
            elif subprocess.run([certimesh, "check", out, "--domain", path], capture_output=True, timeout=120).returncode != 0:
                failures.append(f"capped at {cap}: the written mesh fails check --domain")
        if counts[1] - counts[0] != 10:
            failures.append(f"capped: {counts} vertices at --max-steiner 50 and 60")
        # TetGen hole and region points: a box [0,4]^3 holding a box [1,3]^3 (a .smesh: no
        # orientation, nested shells are an interface); a hole point in the inner box makes a
        # cavity (volume 56 exactly), a region point labels the rest 7, check --domain passes.
        def write_nested_smesh(path, holes, regions):
            corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
            quads = ["0 2 3 1", "4 5 7 6", "0 1 5 4", "2 6 7 3", "0 4 6 2", "1 3 7 5"]
            with open(path, "w") as f:
                f.write("16 3 0 0\n")
                for lo, hi, base in ((0, 4, 0), (1, 3, 8)):
                    for i, c in enumerate(corners):
                        f.write(f"{base + i} " + " ".join(str(lo + (hi - lo) * k) for k in c) + "\n")
                f.write("12 0\n" + "".join("4 " + " ".join(str(int(v) + base) for v in q.split()) + "\n"
                                           for base in (0, 8) for q in quads))
                f.write(f"{len(holes)}\n" + "".join(f"{i} {x} {y} {z}\n" for i, (x, y, z) in enumerate(holes)))
                f.write(f"{len(regions)}\n" + "".join(f"{i} {x} {y} {z} {a} -1\n" for i, (x, y, z, a) in enumerate(regions)))
        smesh, out = os.path.join(tmp, "cavity_by_hole.smesh"), os.path.join(tmp, "cavity_by_hole.mesh")
        write_nested_smesh(smesh, [(2, 2, 2)], [(0.5, 0.5, 0.5, 7)])
        run = subprocess.run([certimesh, "mesh", smesh, "-o", out, "--quiet"], capture_output=True, text=True, timeout=120)
        if run.returncode != 0:
            failures.append(f"cavity_by_hole.smesh: exit {run.returncode}: {run.stderr.strip()}")
        else:
            mesh_points, tets = read_medit(out)
            volume = sum(vol6(*(mesh_points[v] for v in t)) for t in tets)
            labels = set(open(out).read().split("Tetrahedra")[1].split()[1:][4::5][:len(tets)])
            if volume != 6 * 56 or labels != {"7"}:
                failures.append(f"cavity_by_hole.smesh: volume {volume / 6} (want 56), labels {labels} (want 7)")
            if subprocess.run([certimesh, "check", out, "--domain", smesh], capture_output=True, timeout=120).returncode != 0:
                failures.append("cavity_by_hole.smesh: the mesh fails check --domain")
        # Points the regions cannot take: refused by name, exit 2, nothing written.
        for name, holes, regions, says in (("hole_outside", [(9, 9, 9)], [], "outside the solid"),
                                           ("hole_on_surface", [(1, 2, 2)], [], "lies on the surface"),
                                           ("hole_on_surface_vertex", [(1, 1, 1)], [(0.5, 0.5, 0.5, 7)], "lies on the surface"),
                                           ("every_region_a_hole", [(2, 2, 2), (0.5, 0.5, 0.5)], [], "the solid is empty")):
            smesh, out = os.path.join(tmp, name + ".smesh"), os.path.join(tmp, name + ".mesh")
            write_nested_smesh(smesh, holes, regions)
            run = subprocess.run([certimesh, "mesh", smesh, "-o", out], capture_output=True, text=True, timeout=60)
            if run.returncode != 2 or says not in run.stderr or os.path.exists(out):
                failures.append(f"{name}.smesh: exit {run.returncode}, stderr {run.stderr.strip()!r}, written {os.path.exists(out)}")
        refused(certimesh, tmp, "open_cube", box((0, 0, 0), (1, 1, 1))[:-1], failures)
        refused(certimesh, tmp, "touching_boxes", box((0, 0, 0), (1, 1, 1)) + box((1, 0.25, 0.25), (2, 0.75, 0.75)), failures)
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())

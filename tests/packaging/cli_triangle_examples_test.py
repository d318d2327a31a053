#!/usr/bin/env python3
"""Triangle's own example files (tests/packaging/triangle_examples: the .poly and .node files
of Triangle's distribution as John Burkardt's collection carries them, LGPL) meshed by
`certimesh mesh` with default options; each mesh is certified by `certimesh check --domain`
against the file itself, and checked here with exact fractions:
  * every triangle is counterclockwise; every input vertex inside the domain is a mesh vertex
    (for a .node: every point);
  * where the segments form closed loops (every vertex on two segments), the meshed area equals
    the domain's area computed here from the loops, their nesting (exact point-in-polygon) and
    the hole points: a loop's inside minus its children loops counts unless it holds a hole
    point; for a .node, the area of the convex hull (monotone chain here).
box.poly is Triangle's example for -c (its segments alone bound only the hole): without
--convex-hull it is refused as an empty domain, with it the mesh covers the hull minus the
hole; every other .poly is also meshed with --convex-hull and certified against the domain it
saved. Prints the count and time of each. Usage: cli_triangle_examples_test.py CERTIMESH DIR.
"""
import math
import os
import subprocess
import sys
import tempfile
import time
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import planar_oracle  # noqa: E402

from planar_oracle import FAILURES, fail, hull_area, orient, polygon_area, records  # noqa: E402


def read_poly(path):
    rows = records(path)
    n, _, nattr, nmark = (int(x) for x in rows[0][:4])
    first = int(rows[1][0])
    points = [(F(r[1]), F(r[2])) for r in rows[1:1 + n]]
    k = 1 + n
    segments = []
    if path.endswith(".poly"):
        s = int(rows[k][0])
        segments = [(int(r[1]) - first, int(r[2]) - first) for r in rows[k + 1:k + 1 + s]]
        k += 1 + s
    holes = []
    if k < len(rows):
        h = int(rows[k][0])
        holes = [(F(r[1]), F(r[2])) for r in rows[k + 1:k + 1 + h]]
    return points, segments, holes


def read_mesh(base):
    points, _, triangles, _, _ = planar_oracle.read_mesh(base)
    return points, triangles


def inside(p, loop):  # even-odd rule, p off the loop
    c = False
    for i in range(len(loop)):
        a, b = loop[i], loop[(i + 1) % len(loop)]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if x > p[0]:
                c = not c
    return c


def loops_of(points, segments):
    """The closed loops of the segments, or None when some vertex is not on exactly two."""
    around = {}
    for a, b in segments:
        around.setdefault(a, []).append(b)
        around.setdefault(b, []).append(a)
    if any(len(v) != 2 for v in around.values()):
        return None
    seen, loops = set(), []
    for start in sorted(around):
        if start in seen:
            continue
        loop, prev, v = [], None, start
        while v not in seen:
            seen.add(v)
            loop.append(points[v])
            nxt = around[v][0] if around[v][0] != prev else around[v][1]
            prev, v = v, nxt
        loops.append(loop)
    return loops


def domain_area(points, segments, holes):
    loops = loops_of(points, segments)
    if loops is None:
        return None
    contains = [[j for j in range(len(loops)) if j != i and inside(loops[i][0], loops[j])] for i in range(len(loops))]
    total = F(0)
    for i, loop in enumerate(loops):
        children = [j for j in range(len(loops)) if i in contains[j] and len(contains[j]) == len(contains[i]) + 1]
        in_face = lambda p: inside(p, loop) and not any(inside(p, loops[j]) for j in children)
        if any(in_face(h) for h in holes):
            continue
        total += abs(polygon_area(loop)) - sum(abs(polygon_area(loops[j])) for j in children)
    return total


def mesh_one(certimesh, path, work, options=()):
    name = os.path.basename(path) + ("".join(" " + o for o in options))
    out = os.path.join(work, os.path.basename(path).replace(".", "_") + "".join(o.strip("-") for o in options))
    start = time.perf_counter()
    r = subprocess.run([certimesh, "mesh", path, "-o", out + ".node", "--quiet", *options], capture_output=True, text=True, timeout=120)
    seconds = time.perf_counter() - start
    if r.returncode != 0:
        fail(name, f"mesh exit {r.returncode}: {r.stderr.strip()}")
        return
    domain = path
    if options or path.endswith(".node"):  # the hull domain the mesh was made for
        domain = out + "_domain.poly"
        subprocess.run([certimesh, "mesh", path, "-o", out + ".node", "--quiet", "--save-domain", domain, *options], check=True,
                       capture_output=True)
    check = subprocess.run([certimesh, "check", out + ".ele", "--domain", domain], capture_output=True, text=True, timeout=120)
    if check.returncode != 0:
        fail(name, f"check --domain: {check.stdout.strip()[-300:]}")
    points, segments, holes = read_poly(path)
    mesh_points, triangles = read_mesh(out)
    if any(orient(*(mesh_points[v] for v in t)) <= 0 for t in triangles):
        fail(name, "a triangle is not counterclockwise")
    vertices = {mesh_points[v] for t in triangles for v in t}
    on_segments = {v for s in segments for v in s}
    wanted = [points[v] for v in (on_segments if segments and not options else range(len(points)))]
    missing = [p for p in wanted if p not in vertices]
    if missing:
        fail(name, f"{len(missing)} input vertices are not mesh vertices, e.g. {missing[0]}")
    meshed = sum(orient(*(mesh_points[v] for v in t)) for t in triangles) / 2
    expected = hull_area(points) if not segments else (None if options else domain_area(points, segments, holes))
    # Steiner points on sloped segments are roundings (design decision 2): half an ulp per
    # coordinate, so the area may differ by the segments' length times an ulp of the largest
    # coordinate (a missing or extra triangle is far beyond that).
    largest = max(max(abs(F(x)), abs(F(y))) for x, y in points) if points else F(0)
    length = sum(math.hypot(float(points[a][0]) - float(points[b][0]), float(points[a][1]) - float(points[b][1])) for a, b in segments)
    slack = F(length) * F(math.ulp(float(largest)))
    if expected is not None and abs(meshed - expected) > slack:
        fail(name, f"meshed area {float(meshed)} != domain area {float(expected)}")
    print(f"  {name}: {len(triangles)} triangles, {seconds:.2f} s, area {'checked' if expected is not None else 'by the certificate only'}")


def main():
    certimesh, data = sys.argv[1], sys.argv[2]
    files = sorted(f for f in os.listdir(data) if f.endswith((".poly", ".node")))
    with tempfile.TemporaryDirectory() as work:
        for f in files:
            if f == "box.poly":
                continue
            mesh_one(certimesh, os.path.join(data, f), work)
        box = os.path.join(data, "box.poly")
        r = subprocess.run([certimesh, "mesh", box, "-o", os.path.join(work, "box_plain.node"), "--quiet"], capture_output=True, text=True)
        if r.returncode != 1 or "error:" not in r.stderr or "empty" not in r.stderr:
            fail("box.poly", f"without --convex-hull: exit {r.returncode}, {r.stderr.strip()}")
        mesh_one(certimesh, box, work, ("--convex-hull",))
        for f in files:  # Triangle's -c on every .poly: the hull of its points, holes still eat
            if f.endswith(".poly") and f != "box.poly":
                mesh_one(certimesh, os.path.join(data, f), work, ("--convex-hull",))
        pts, _, _ = read_poly(box)
        # the hull of box.poly is [0,3]^2, its hole the square [1,2]^2
        base = os.path.join(work, "box_polyconvex-hull")
        mp, tri = read_mesh(base)
        area = sum(orient(*(mp[v] for v in t)) for t in tri) / 2
        if area != hull_area(pts) - 1:
            fail("box.poly --convex-hull", f"meshed area {area}, the hull minus the hole {hull_area(pts) - 1}")
        for p in pts:
            if p not in {mp[v] for t in tri for v in t}:
                fail("box.poly --convex-hull", f"point {p} is not a mesh vertex")
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        return 1
    print(f"all {len(files)} Triangle examples meshed and certified")
    return 0


if __name__ == "__main__":
    sys.exit(main())

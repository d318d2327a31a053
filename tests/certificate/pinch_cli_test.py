#!/usr/bin/env python3
"""`certimesh mesh` on 2D domains with pinch vertices (design decision 8, issue 12 item 5): two
squares sharing a corner, and a square whose triangular hole touches the outer loop at a
vertex. Each is meshed with both algorithms; the run must succeed (before pinches were
certified, the mesher refused its own mesh: exit 3), and the written mesh is checked here
against oracles in plain Python with exact fractions: every triangle counterclockwise, every
domain vertex a mesh vertex, the pinch vertex in triangles of both parts (no element across
it: the centroid of each triangle there is inside the domain), the area the domain's up to the rounding of
boundary vertices on the sloped hole segments (decision 2); then `certimesh check --domain`
exits 0. Usage: pinch_cli_test.py CERTIMESH WORKDIR.
"""
import os
import subprocess
import sys
from fractions import Fraction as F

def in_box(q, x0, y0, x1, y1):
    return x0 < q[0] < x1 and y0 < q[1] < y1


def in_triangle(q, a, b, c):
    return orient(a, b, q) > 0 and orient(b, c, q) > 0 and orient(c, a, q) > 0


# points, segments, hole points, exact area, pinch vertex, strictly-inside test for a centroid
CORNER = ([(0, 0), (1, 0), (1, 1), (0, 1), (2, 1), (2, 2), (1, 2)],
          [(0, 1), (1, 2), (2, 3), (3, 0), (2, 4), (4, 5), (5, 6), (6, 2)], [], 2, (1, 1),
          lambda q: in_box(q, 0, 0, 1, 1) or in_box(q, 1, 1, 2, 2))
HOLE = ([(0, 0), (1, 0), (4, 0), (4, 4), (0, 4), (2, 1), (1, 1)],
        [(0, 1), (1, 2), (2, 3), (3, 4), (4, 0), (1, 5), (5, 6), (6, 1)], [(1.25, 0.5)], F(31, 2), (1, 0),
        lambda q: in_box(q, 0, 0, 4, 4) and not in_triangle(q, (1, 0), (2, 1), (1, 1)))


def write_poly(path, pts, segs, holes):
    with open(path, "w") as f:
        f.write(f"{len(pts)} 2 0 0\n" + "".join(f"{i + 1} {x} {y}\n" for i, (x, y) in enumerate(pts)))
        f.write(f"{len(segs)} 0\n" + "".join(f"{i + 1} {a + 1} {b + 1}\n" for i, (a, b) in enumerate(segs)))
        f.write(f"{len(holes)}\n" + "".join(f"{i + 1} {x} {y}\n" for i, (x, y) in enumerate(holes)))


def read_medit(path):
    tokens = open(path).read().split()
    pts, tris, i = [], [], 0
    while i < len(tokens):
        if tokens[i] == "Vertices":
            n = int(tokens[i + 1])
            pts = [(F(tokens[i + 2 + 3 * k]), F(tokens[i + 3 + 3 * k])) for k in range(n)]
            i += 2 + 3 * n
        elif tokens[i] == "Triangles":
            n = int(tokens[i + 1])
            tris = [tuple(int(tokens[i + 2 + 4 * k + j]) - 1 for j in range(3)) for k in range(n)]
            i += 2 + 4 * n
        else:
            i += 1
    return pts, tris


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def main():
    certimesh, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []
    for name, (pts, segs, holes, area, pinch, inside) in (("corner", CORNER), ("hole", HOLE)):
        poly = os.path.join(work, name + ".poly")
        write_poly(poly, pts, segs, holes)
        for algorithm in ("front", "delaunay"):
            out = os.path.join(work, f"{name}_{algorithm}.mesh")
            run = subprocess.run([certimesh, "mesh", poly, "-o", out, "--size", "0.25", "--algorithm", algorithm, "--quiet"],
                                 capture_output=True, text=True)
            what = f"{name} {algorithm}"
            if run.returncode != 0:
                failures.append(f"{what}: mesh exit {run.returncode}: {run.stderr.strip()}")
                continue
            mp, mt = read_medit(out)
            if any(orient(mp[a], mp[b], mp[c]) <= 0 for a, b, c in mt):
                failures.append(f"{what}: a triangle is not counterclockwise")
            if not all((F(x), F(y)) in set(mp) for x, y in pts):
                failures.append(f"{what}: a domain vertex is not a mesh vertex")
            total = sum(orient(mp[a], mp[b], mp[c]) for a, b, c in mt) / 2
            if abs(total - area) > F(1, 10 ** 12):
                failures.append(f"{what}: area {float(total)} instead of {float(area)}")
            p = (F(pinch[0]), F(pinch[1]))
            at = [t for t in mt if p in (mp[v] for v in t)]
            if len(at) < 2:
                failures.append(f"{what}: the pinch vertex is in {len(at)} triangle(s)")
            # A triangle at the pinch lies in one part, not across the pinch or in the hole.
            centroid = lambda t: tuple(sum(mp[v][k] for v in t) / 3 for k in range(2))
            if not all(inside(centroid(t)) for t in at):
                failures.append(f"{what}: a triangle at the pinch reaches outside the domain")
            check = subprocess.run([certimesh, "check", out, "--domain", poly], capture_output=True, text=True)
            if check.returncode != 0:
                failures.append(f"{what}: check exit {check.returncode}: {check.stdout.strip().splitlines()[-1:]}")
    for f in failures:
        print("FAIL", f)
    print(f"{4 - len({f.split(':')[0] for f in failures})} passed, {len({f.split(':')[0] for f in failures})} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

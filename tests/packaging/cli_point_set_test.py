#!/usr/bin/env python3
"""`certimesh mesh POINTS.node -o OUT.ele`: the Delaunay triangulation of a 2D point set
(issue 12, item 9), checked against oracles written here in plain Python with exact
fractions: every point a vertex, the triangle count 2n - h - 2 (h: points on the convex hull,
by a monotone chain that keeps collinear hull points), every triangle counterclockwise, every
interior edge locally Delaunay (so the triangulation is Delaunay); and `certimesh check` of the
written mesh. Bad point sets (a repeated point, all points on a line) are refused with
`error:`, exit 2, and no file. Usage: cli_point_set_test.py CERTIMESH.
"""
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_report import report  # noqa: E402


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def hull_size(points):
    pts = sorted(points)
    count = 0
    for chain in (pts, pts[::-1]):
        h = []
        for p in chain:
            while len(h) >= 2 and orient(h[-2], h[-1], p) < 0:
                h.pop()
            h.append(p)
        count += len(h) - 1
    return count


def in_circle(a, b, c, d):  # > 0: d inside the circle through counterclockwise a, b, c
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    m = [(x, y, x * x + y * y) for x, y in rows]
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def write_node(path, points):
    with open(path, "w") as f:
        f.write(f"{len(points)} 2 0 0\n")
        for i, (x, y) in enumerate(points):
            f.write(f"{i + 1} {float(x)!r} {float(y)!r}\n")


def read_ele(path):
    with open(path) as f:
        rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    first_index = 1 if rows[1][1:4] and min(int(x) for r in rows[1:] for x in r[1:4]) == 1 else 0
    return [tuple(int(x) - first_index for x in r[1:4]) for r in rows[1:]]


def main():
    certimesh = sys.argv[1]
    failures = []
    random.seed(20261201)
    # random points, an integer grid (cocircular and collinear everywhere) and points on the
    # hull between others
    points = [(F(random.random()), F(random.random())) for _ in range(400)]
    points += [(F(i, 8), F(j, 8)) for i in range(9) for j in range(9)]
    points += [(F(-1, 2), F(1, 2)), (F(3, 2), F(1, 2))]
    points = list(dict.fromkeys(points))
    with tempfile.TemporaryDirectory() as tmp:
        node, out = os.path.join(tmp, "pts.node"), os.path.join(tmp, "dt.ele")
        write_node(node, points)
        run = subprocess.run([certimesh, "mesh", node, "-o", out], capture_output=True, text=True, timeout=60)
        if run.returncode != 0:
            failures.append(f"mesh exited {run.returncode}: {run.stderr}")
        else:
            tris = read_ele(out)
            n, h = len(points), hull_size(points)
            if len(tris) != 2 * n - h - 2:
                failures.append(f"{len(tris)} triangles, a triangulation of {n} points with {h} on the hull has {2 * n - h - 2}")
            if {v for t in tris for v in t} != set(range(n)):
                failures.append("not every point is a vertex")
            if any(orient(*(points[v] for v in t)) <= 0 for t in tris):
                failures.append("a triangle is not counterclockwise")
            opposite = {}
            for t in tris:
                for i in range(3):
                    opposite.setdefault(frozenset((t[i], t[(i + 1) % 3])), []).append((t, t[(i + 2) % 3]))
            for pair in opposite.values():
                if len(pair) == 2 and in_circle(*(points[v] for v in pair[0][0]), points[pair[1][1]]) > 0:
                    failures.append(f"edge between triangles {pair[0][0]} and {pair[1][0]} is not locally Delaunay")
                    break
            check = subprocess.run([certimesh, "check", out[:-4] + ".node"], capture_output=True, text=True, timeout=60)
            if check.returncode != 0:
                failures.append(f"check of the written mesh exited {check.returncode}: {check.stdout}")
        for name, bad in (("repeated", [(0, 0), (1, 0), (0, 1), (1, 0)]), ("collinear", [(0, 0), (1, 1), (2, 2), (3, 3)])):
            node, out = os.path.join(tmp, name + ".node"), os.path.join(tmp, name + ".ele")
            write_node(node, bad)
            run = subprocess.run([certimesh, "mesh", node, "-o", out], capture_output=True, text=True, timeout=60)
            if run.returncode != 2 or "error:" not in run.stderr or os.path.exists(out):
                failures.append(f"{name} points: exit {run.returncode}, stderr {run.stderr!r}, output written: {os.path.exists(out)}")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())

"""Exact-fraction oracles shared by the planar CLI tests (cli_planar_input_test.py,
cli_triangle_examples_test.py): reading Triangle files as plain text and the geometry on
them, written here without certimesh."""
import os
from fractions import Fraction as F

FAILURES = []


def fail(name, why):
    FAILURES.append(f"{name}: {why}")
    print(f"FAIL {name}: {why}")


def records(path):
    """The records of a Triangle file: fields of each line, comments and blank lines dropped."""
    with open(path) as f:
        return [line.split("#")[0].split() for line in f if line.split("#")[0].strip()]


def read_mesh(base):
    """The .node/.ele/.edge files of `base`: points (fractions), point markers, triangles,
    triangle attributes (strings, or None), edges with markers."""
    node = records(base + ".node")
    n, _, nattr, nmark = (int(x) for x in node[0][:4])
    first = int(node[1][0])
    points = [(F(r[1]), F(r[2])) for r in node[1:1 + n]]
    markers = [int(r[3 + nattr]) if nmark else 0 for r in node[1:1 + n]]
    ele = records(base + ".ele")
    count, _, eattr = (int(x) for x in ele[0][:3])
    triangles = [tuple(int(x) - first for x in r[1:4]) for r in ele[1:1 + count]]
    attributes = [r[4] for r in ele[1:1 + count]] if eattr else None
    edges = []
    if os.path.exists(base + ".edge"):
        edge = records(base + ".edge")
        ecount, emark = int(edge[0][0]), int(edge[0][1])
        edges = [(int(r[1]) - first, int(r[2]) - first, int(r[3]) if emark else 0) for r in edge[1:1 + ecount]]
    return points, markers, triangles, attributes, edges


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def area(points, t):
    return orient(points[t[0]], points[t[1]], points[t[2]]) / 2


def polygon_area(loop):
    return sum(orient(loop[0], loop[i], loop[i + 1]) for i in range(1, len(loop) - 1)) / 2


def hull_area(points):
    """Area of the convex hull (Andrew's monotone chain, exact)."""
    pts = sorted(set(points))
    hull = []
    for seq in (pts, pts[::-1]):
        h = []
        for p in seq:
            while len(h) >= 2 and orient(h[-2], h[-1], p) <= 0:
                h.pop()
            h.append(p)
        hull += h[:-1]
    return polygon_area(hull)

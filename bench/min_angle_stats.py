#!/usr/bin/env python3
"""Helpers of bench/min_angle.sh. `domain NAME OUT.poly OUT.geo H`: writes a domain of
tests/generators/min_angle_test.py as a .poly and as a Gmsh .geo (every point at size H).
`angles MESH`: triangle count, smallest angle and the share of triangles below 20.7 and 30
degrees of a mesh meshio reads (.vtu, .msh)."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "generators"))
import min_angle_test as t  # noqa: E402  (the domains are built there)


def write_geo(path, pts, segs, h):
    # loops: follow the segments (each domain loop is a closed polygon, in order)
    with open(path, "w") as f:
        for i, (x, y) in enumerate(pts):
            f.write(f"Point({i + 1}) = {{{x!r}, {y!r}, 0, {h}}};\n")
        for i, (a, b) in enumerate(segs):
            f.write(f"Line({i + 1}) = {{{a + 1}, {b + 1}}};\n")
        loops, current, start = [], [], None
        for i, (a, b) in enumerate(segs):
            if not current:
                start = a
            current.append(i + 1)
            if b == start:
                loops.append(current)
                current = []
        for i, loop in enumerate(loops):
            f.write(f"Curve Loop({i + 1}) = {{{', '.join(map(str, loop))}}};\n")
        f.write(f"Plane Surface(1) = {{{', '.join(str(i + 1) for i in range(len(loops)))}}};\n")


def angles(path):
    import meshio
    m = meshio.read(path)
    tris = [c.data for c in m.cells if c.type == "triangle"]
    p = m.points
    smallest, below20, below30, n = 180.0, 0, 0, 0
    for block in tris:
        for a, b, c in block:
            n += 1
            worst = 180.0
            for o, u, w in ((a, b, c), (b, c, a), (c, a, b)):
                ux, uy = p[u][0] - p[o][0], p[u][1] - p[o][1]
                wx, wy = p[w][0] - p[o][0], p[w][1] - p[o][1]
                worst = min(worst, math.degrees(math.atan2(abs(ux * wy - uy * wx), ux * wx + uy * wy)))
            smallest = min(smallest, worst)
            below20 += worst < 20.7
            below30 += worst < 30
    print(f"{n} triangles, smallest angle {smallest:.2f}, below 20.7: {below20}, below 30: {below30}")


if __name__ == "__main__":
    if sys.argv[1] == "domain":
        pts, segs, holes = t.DOMAINS[sys.argv[2]]()
        t.write_poly(sys.argv[3], pts, segs, holes)
        write_geo(sys.argv[4], pts, segs, float(sys.argv[5]))
    else:
        angles(sys.argv[2])

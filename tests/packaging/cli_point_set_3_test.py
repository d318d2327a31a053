#!/usr/bin/env python3
"""`certimesh mesh POINTS.node -o OUT.ele` for a .node of dimension 3: the Delaunay
tetrahedralization of the convex hull (issue 13, item 1), checked against oracles written here
with exact fractions -- every point a vertex, every tetrahedron positive, every interior face
locally Delaunay (strictly, the points being in general position), every hull face in one
tetrahedron and the hull closed -- and against TetGen (`tetgen -Q` on the same .node): the
same tetrahedra for points in general position, where the Delaunay tetrahedralization is
unique. With --size (Delaunay refinement, item 5) the input points come first, bit for bit,
every tetrahedron is positive, the hull faces are the unrefined ones (no point on the
boundary) and the volume is the hull's, exactly. On an integer grid (cospherical everywhere) the tetrahedra fill the cube exactly. Every
written mesh passes `certimesh check`. Bad point sets (a NaN, a repeated point, all points in
a plane, three points) are refused with `error:`, a non-zero exit and no file.
Usage: cli_point_set_3_test.py CERTIMESH [TETGEN].
"""
import os
import random
import shutil
import subprocess
import sys
import tempfile
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_report import report  # noqa: E402

FACES = ((1, 3, 2), (0, 2, 3), (0, 3, 1), (0, 1, 2))  # face i counterclockwise seen from corner i


def det3(u, v, w):
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def volume6(a, b, c, d):  # > 0: positive in the Medit sense
    return det3([b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)], [d[i] - a[i] for i in range(3)])


def in_sphere(a, b, c, d, e):  # > 0: e inside the sphere of the positive tetrahedron (a, b, c, d)
    rows = []
    for p in (a, b, c, d):
        q = [p[i] - e[i] for i in range(3)]
        rows.append(q + [q[0] * q[0] + q[1] * q[1] + q[2] * q[2]])
    def det(m):
        if len(m) == 1:
            return m[0][0]
        return sum((-1) ** j * m[0][j] * det([r[:j] + r[j + 1:] for r in m[1:]]) for j in range(len(m)))
    return -det(rows)


def write_node(path, points):
    with open(path, "w") as f:
        f.write(f"{len(points)} 3 0 0\n")
        for i, p in enumerate(points):
            f.write(f"{i + 1} " + " ".join(repr(float(x)) if isinstance(x, F) else str(x) for x in p) + "\n")


def read_rows(path):
    with open(path) as f:
        return [line.split() for line in f if line.strip() and not line.lstrip().startswith("#")]


def read_tets(ele_path):
    """The tetrahedra of an .ele, as 0-based indices of the points of the .node written beside it."""
    node_rows = read_rows(ele_path[:-4] + ".node")
    first = int(node_rows[1][0])
    return [tuple(int(x) - first for x in r[1:5]) for r in read_rows(ele_path)[1:]]


def check_tets(points, tets, strict, failures, name):
    if {v for t in tets for v in t} != set(range(len(points))):
        failures.append(f"{name}: not every point is a vertex")
    if any(volume6(*(points[v] for v in t)) <= 0 for t in tets):
        failures.append(f"{name}: a tetrahedron is not positive")
    faces = {}
    for t in tets:
        for i in range(4):
            faces.setdefault(frozenset(t[j] for j in FACES[i]), []).append((t, t[i]))
    hull = []
    for key, side in faces.items():
        if len(side) > 2:
            failures.append(f"{name}: a face in {len(side)} tetrahedra")
        elif len(side) == 2 and strict:
            (t1, _), (_, apex) = side
            if in_sphere(*(points[v] for v in t1), points[apex]) >= 0:
                failures.append(f"{name}: the face between {t1} and {side[1][0]} is not locally Delaunay")
                break
        elif len(side) == 1:
            hull.append(key)
    edges = {}
    for f in hull:
        for e in ({a, b} for a in f for b in f if a < b):
            edges[frozenset(e)] = edges.get(frozenset(e), 0) + 1
    if any(c != 2 for c in edges.values()):
        failures.append(f"{name}: the hull faces are not closed")
    return sum(volume6(*(points[v] for v in t)) for t in tets)


def mesh(certimesh, node, out, *options):
    return subprocess.run([certimesh, "mesh", node, "-o", out, *options], capture_output=True, text=True, timeout=120)


def read_points(node_path):
    return [tuple(F(x) for x in r[1:4]) for r in read_rows(node_path)[1:]]


def hull_faces(points, tets):
    faces = {}
    for t in tets:
        for i in range(4):
            faces.setdefault(frozenset(points[t[j]] for j in FACES[i]), []).append(t)
    return {f for f, held in faces.items() if len(held) == 1}


def check_refined(certimesh, tmp, node, dt_tets, failures):
    points = [tuple(F(float(x)) for x in p) for p in read_points(node)]  # as the .node says, exactly
    out = os.path.join(tmp, "refined.ele")
    run = mesh(certimesh, node, out, "--size", "0.25")
    if run.returncode != 0:
        failures.append(f"refined: mesh exited {run.returncode}: {run.stderr}")
        return
    written = [tuple(F(float(x)) for x in p) for p in read_points(out[:-4] + ".node")]
    tets = read_tets(out)
    if written[:len(points)] != points:
        failures.append("refined: the input points are not the first vertices, unchanged")
    if len(written) <= len(points) + 50:
        failures.append(f"refined: only {len(written) - len(points)} Steiner points at --size 0.25")
    volume = check_tets(written, tets, False, failures, "refined")
    if volume != sum(volume6(*(points[v] for v in t)) for t in dt_tets):
        failures.append("refined: the volume is not the hull's")
    if hull_faces(written, tets) != hull_faces(points, dt_tets):
        failures.append("refined: the hull faces changed (a point on the boundary?)")
    check = subprocess.run([certimesh, "check", out], capture_output=True, text=True, timeout=60)
    if check.returncode != 0:
        failures.append(f"refined: check exited {check.returncode}: {check.stdout} {check.stderr}")


def main():
    certimesh = sys.argv[1]
    tetgen = sys.argv[2] if len(sys.argv) > 2 else shutil.which("tetgen")
    failures = []
    random.seed(20261202)
    generic = [tuple(F(random.random()) for _ in range(3)) for _ in range(300)]
    side = 6
    grid = [(i, j, k) for i in range(side) for j in range(side) for k in range(side)]
    with tempfile.TemporaryDirectory() as tmp:
        for name, points, strict in (("generic", generic, True), ("grid", grid, False)):
            node, out = os.path.join(tmp, name + ".node"), os.path.join(tmp, name + "_dt.ele")
            write_node(node, points)
            run = mesh(certimesh, node, out)
            if run.returncode != 0:
                failures.append(f"{name}: mesh exited {run.returncode}: {run.stderr}")
                continue
            tets = read_tets(out)
            volume = check_tets(points, tets, strict, failures, name)
            if name == "grid" and volume != 6 * (side - 1) ** 3:
                failures.append(f"grid: the tetrahedra fill {volume}/6, the cube is {(side - 1) ** 3}")
            check = subprocess.run([certimesh, "check", out], capture_output=True, text=True, timeout=60)
            if check.returncode != 0:
                failures.append(f"{name}: check of the written mesh exited {check.returncode}: {check.stdout} {check.stderr}")
            if name == "generic":
                check_refined(certimesh, tmp, node, tets, failures)
                if not tetgen:
                    failures.append("tetgen not found")
                    continue
                peer = subprocess.run([tetgen, "-Q", node], capture_output=True, text=True, timeout=60, cwd=tmp)
                if peer.returncode != 0:
                    failures.append(f"tetgen exited {peer.returncode}")
                    continue
                theirs = read_tets(os.path.join(tmp, name + ".1.ele"))
                if len(theirs) != len(tets):
                    failures.append(f"generic: {len(tets)} tetrahedra, tetgen {len(theirs)}")
                if {frozenset(t) for t in theirs} != {frozenset(t) for t in tets}:
                    failures.append("generic: other tetrahedra than tetgen's")
        bad = {
            "nan": generic[:10] + [("nan", 0.5, 0.5)],
            "repeated": generic[:10] + [generic[3]],
            "coplanar": [(i % 5, i // 5, 2) for i in range(20)],
            "three": generic[:3],
        }
        for name, points in bad.items():
            node, out = os.path.join(tmp, name + ".node"), os.path.join(tmp, name + ".ele")
            write_node(node, points)
            run = mesh(certimesh, node, out)
            if run.returncode == 0 or "error:" not in run.stderr or os.path.exists(out):
                failures.append(f"{name} points: exit {run.returncode}, stderr {run.stderr!r}, output written: {os.path.exists(out)}")
            elif name == "repeated" and "points 3 and 10" not in run.stderr:
                failures.append(f"repeated points: the message does not name them: {run.stderr!r}")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())

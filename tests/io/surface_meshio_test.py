#!/usr/bin/env python3
"""The surface readers against meshio, the independent writer and reader.

  surface_meshio_test.py CERTIMESH WORKDIR

For random triangle soups (with repeated points, -0.0 beside 0.0, and full-precision doubles),
meshio writes .off, ASCII .stl, binary .stl and .mesh; `certimesh convert F out.mesh` reads each
and meshio reads certimesh's .mesh back. Expected, computed here without certimesh:
  .off, .mesh   the points and triangles as written, bit for bit (0-based and 1-based files);
  .stl          the corners welded by equal value (-0.0 == 0.0) in order of first appearance,
                the first appearance's bits kept; binary STL: the float32 rounding of each
                corner (meshio writes float32), ASCII: the doubles as written.
Exit 77 (skipped) when meshio is not importable.
"""
import os
import struct
import subprocess
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:
    print("skipped: %s" % e)
    sys.exit(77)

failures = []


def check(cond, message):
    if not cond:
        failures.append(message)
        print("FAIL:", message)


def bits(values):
    return [struct.pack("<d", float(v)) for v in values]


def weld(points, triangles):
    index, out_points, out_triangles = {}, [], []
    for t in triangles:
        row = []
        for v in t:
            key = tuple(float(x) for x in points[v])  # -0.0 == 0.0 and hash alike
            if key not in index:
                index[key] = len(out_points)
                out_points.append(points[v])
            row.append(index[key])
        out_triangles.append(row)
    return np.array(out_points, dtype=float), np.array(out_triangles)


def soup(rng, n_points=40, n_triangles=60):
    p = rng.standard_normal((n_points, 3)) * 10.0 ** rng.integers(-12, 12)
    p[30:] = p[:10]          # repeated points: separate vertices in .off/.mesh, welded in .stl
    p[5, 1] = 0.0
    p[6] = p[5]
    p[6, 1] = -0.0           # the same point as p[5] by value
    tris = []
    while len(tris) < n_triangles:
        t = rng.choice(n_points, 3, replace=False)
        tris.append(t)
    return p, np.array(tris)


def certimesh_read(certimesh, path, work):
    out = os.path.join(work, "back.mesh")
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run([certimesh, "convert", path, out], capture_output=True, text=True)
    check(r.returncode == 0, "convert %s: exit %d %s" % (path, r.returncode, r.stderr))
    if r.returncode != 0:
        return None, None
    m = meshio.read(out)
    return m.points, m.cells_dict.get("triangle", np.zeros((0, 3), dtype=int))


def compare(name, got_points, got_tris, want_points, want_tris):
    if got_points is None:
        return
    check(len(got_points) == len(want_points), "%s: %d points, expected %d" % (name, len(got_points), len(want_points)))
    check(bits(np.ravel(got_points)) == bits(np.ravel(want_points)), "%s: coordinates differ" % name)
    check(np.array_equal(np.asarray(got_tris), np.asarray(want_tris)), "%s: triangles differ" % name)


def main():
    certimesh, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    rng = np.random.default_rng(20261202)
    for case in range(5):
        p, t = soup(rng)
        mesh = meshio.Mesh(p, [("triangle", t)])
        for ext in (".off", ".mesh"):
            path = os.path.join(work, "soup%d%s" % (case, ext))
            meshio.write(path, mesh)
            compare(path, *certimesh_read(certimesh, path, work), p, t)
        path = os.path.join(work, "soup%d_ascii.stl" % case)
        meshio.write(path, mesh, binary=False)
        compare(path, *certimesh_read(certimesh, path, work), *weld(p, t))
        path = os.path.join(work, "soup%d_binary.stl" % case)
        meshio.write(path, mesh, binary=True)
        compare(path, *certimesh_read(certimesh, path, work), *weld(p.astype(np.float32).astype(float), t))
    if failures:
        print("%d failures" % len(failures))
        return 1
    print("ok: 5 soups x 4 files read as meshio wrote them")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Triangle's own example files (bench/data/planar/triangle, see SOURCES.md there) meshed with
`certimesh mesh` and its default options, checked against oracles computed here in Python with
exact fractions, independently of certimesh: every triangle counterclockwise with positive
area; the triangles' areas sum exactly to the domain's area (the bounded faces of the segment
arrangement minus those holding a hole point, found by bench/planar_examples.py's own face
walk); every input vertex is a mesh vertex; and `certimesh check --domain` certifies the mesh.
Usage: planar_examples_test.py CERTIMESH.
"""
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as F

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import planar_examples as pe  # noqa: E402  (the harness's readers and face walk)

# Small inputs that today's certimesh meshes: a hole, two holes, a hole touching nothing.
INPUTS = ["A.poly", "double_hex2.poly", "double_hex3.poly"]


def exact_area2(points, walk):
    """Twice the signed area of a closed walk of the graph, exactly."""
    return sum(F(points[u][0]) * F(points[v][1]) - F(points[v][0]) * F(points[u][1]) for u, v in walk)


def domain_area2(path):
    graph, faces, domain = pe.poly_domain(path)
    return sum(exact_area2(graph.points, faces[k][0]) + sum(exact_area2(graph.points, c) for c in faces[k][1])
               for k in domain)


def main():
    certimesh = sys.argv[1]
    failures = []
    for name in INPUTS:
        path = os.path.join(ROOT, "bench", "data", "planar", "triangle", name)
        with tempfile.TemporaryDirectory() as work:
            out = os.path.join(work, "mesh.ele")
            r = subprocess.run([certimesh, "mesh", path, "-o", out, "--quiet"], capture_output=True, text=True)
            if r.returncode != 0:
                failures.append("%s: mesh exit %d: %s" % (name, r.returncode, r.stderr.strip()))
                continue
            points, triangles = pe.read_ele_mesh(out[:-4] + ".node", out)
            area2 = F(0)
            for t in triangles:
                a, b, c = (points[v] for v in t)
                d = (F(b[0]) - F(a[0])) * (F(c[1]) - F(a[1])) - (F(b[1]) - F(a[1])) * (F(c[0]) - F(a[0]))
                if d <= 0:
                    failures.append("%s: triangle %s is not counterclockwise" % (name, t))
                area2 += d
            expected = domain_area2(path)
            if area2 != expected:
                failures.append("%s: triangles' area %s, the domain's %s" % (name, float(area2 / 2), float(expected / 2)))
            vertices, _, _, _ = pe.read_poly(path)
            missing = set(vertices.values()) - set(points.values())
            if missing:
                failures.append("%s: input vertices not in the mesh: %s" % (name, sorted(missing)[:3]))
            r = subprocess.run([certimesh, "check", out[:-4] + ".node", "--domain", path],
                               capture_output=True, text=True)
            if r.returncode != 0:
                failures.append("%s: check exit %d: %s" % (name, r.returncode, r.stdout.strip().splitlines()[-1:]))
            print("%s: %d triangles, area %.17g" % (name, len(triangles), float(area2 / 2)))
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

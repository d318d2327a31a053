#!/usr/bin/python3
"""Boundaries whose segments vary in length, meshed by certimesh and by Gmsh in the same run.

Each domain is written twice with the same points and lines: a Triangle .poly for certimesh and
a Gmsh .geo (no characteristic lengths: Gmsh's defaults). Both meshes are read back and measured
with the project's shape quality 12*sqrt(3)*|S|/P^2 (design decision 4); the table goes to
stdout (bench/RESULTS.md, "Graded boundaries").

  /usr/bin/python3 bench/graded_domains.py --certimesh build/bin/certimesh [--out DIR]
      [--only NAME] [--extra "--algorithm delaunay"]
"""
import argparse
import math
import os
import subprocess
import sys
import time

import meshio
import numpy as np


def naca0012(n):
    """Closed-trailing-edge NACA 0012, cosine spacing (dense at both edges), counterclockwise
    from the trailing edge over the upper side; 2n - 2 points."""
    xs = [0.5 * (1 - math.cos(math.pi * i / (n - 1))) for i in range(n)]
    t = lambda x: 0.6 * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    upper = [(x, t(x)) for x in reversed(xs)]  # TE -> LE
    lower = [(x, -t(x)) for x in xs[1:-1]]      # LE -> TE, without both ends
    return upper + lower


def box(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def circle(n, r, cx=0.0, cy=0.0):
    return [(cx + r * math.cos(2 * math.pi * i / n), cy + r * math.sin(2 * math.pi * i / n)) for i in range(n)]


def coin(n, notches):
    """A circle of n short segments with `notches` rectangular notches cut inwards."""
    pts = []
    per = n // notches
    for i in range(n):
        a = 2 * math.pi * i / n
        if i % per == 0:  # a notch: in, along, out
            w = 2 * math.pi / n
            for (r, da) in [(1.0, 0.0), (0.9, 0.0), (0.9, 3 * w), (1.0, 3 * w)]:
                pts.append((r * math.cos(a + da), r * math.sin(a + da)))
        elif i % per in (1, 2, 3):
            continue  # covered by the notch
        else:
            pts.append((math.cos(a), math.sin(a)))
    return pts


def star(n, r0, r1):
    return [((r0 if i % 2 else r1) * math.cos(2 * math.pi * i / n), (r0 if i % 2 else r1) * math.sin(2 * math.pi * i / n))
            for i in range(n)]


def wavy(n):
    """A 10^4-vertex polygon: a circle whose radius wobbles (segments of varying length)."""
    return [((1 + 0.05 * math.sin(37 * 2 * math.pi * i / n)) * math.cos(2 * math.pi * i / n + 0.3 * math.sin(2 * math.pi * i / n)),
             (1 + 0.05 * math.sin(37 * 2 * math.pi * i / n)) * math.sin(2 * math.pi * i / n + 0.3 * math.sin(2 * math.pi * i / n)))
            for i in range(n)]


def domains():
    foil = naca0012(200)
    return {
        "naca0012-box": ([box(-10, -10, 11, 10), foil], [(0.3, 0.0)]),
        "naca0012-circle": ([circle(64, 15, 0.5, 0.0), foil], [(0.3, 0.0)]),
        "naca0012-fine": ([box(-2, -2, 3, 2), naca0012(400)], [(0.3, 0.0)]),
        "coin": ([coin(2000, 8)], []),
        "star-1000": ([star(1000, 0.3, 1.0)], []),
        "wavy-10000": ([wavy(10000)], []),
    }


def write_poly(path, loops, holes):
    points = [p for loop in loops for p in loop]
    with open(path, "w") as f:
        f.write(f"{len(points)} 2 0 0\n")
        for i, (x, y) in enumerate(points):
            f.write(f"{i + 1} {x!r} {y!r}\n")
        f.write(f"{len(points)} 0\n")
        k, base = 1, 0
        for loop in loops:
            for i in range(len(loop)):
                f.write(f"{k} {base + i + 1} {base + (i + 1) % len(loop) + 1}\n")
                k += 1
            base += len(loop)
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes):
            f.write(f"{i + 1} {x!r} {y!r}\n")


def write_geo(path, loops):
    with open(path, "w") as f:
        k, base, loop_ids = 1, 0, []
        for loop in loops:
            for i, (x, y) in enumerate(loop):
                f.write(f"Point({base + i + 1}) = {{{x!r}, {y!r}, 0}};\n")
            for i in range(len(loop)):
                f.write(f"Line({base + i + 1}) = {{{base + i + 1}, {base + (i + 1) % len(loop) + 1}}};\n")
            f.write(f"Curve Loop({len(loop_ids) + 1}) = {{{', '.join(str(base + i + 1) for i in range(len(loop)))}}};\n")
            loop_ids.append(len(loop_ids) + 1)
            base += len(loop)
        f.write(f"Plane Surface(1) = {{{', '.join(map(str, loop_ids))}}};\n")


def quality(path):
    m = meshio.read(path)
    tri = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
    p = m.points[:, :2]
    a, b, c = p[tri[:, 0]], p[tri[:, 1]], p[tri[:, 2]]
    area = 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    per = np.linalg.norm(b - a, axis=1) + np.linalg.norm(c - b, axis=1) + np.linalg.norm(a - c, axis=1)
    q = 12 * math.sqrt(3) * area / per**2
    return len(tri), float(q.min()), float(q.mean())


def timed(cmd, timeout):
    start = time.perf_counter()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        r = subprocess.CompletedProcess(cmd, 124, "", f"timed out after {timeout} s")
    return time.perf_counter() - start, r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--certimesh", required=True)
    ap.add_argument("--out", default="build/graded_domains")
    ap.add_argument("--only", default="")
    ap.add_argument("--extra", default="")
    ap.add_argument("--gmsh", default="gmsh")
    ap.add_argument("--timeout", type=float, default=300)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    print("| domain | boundary points | certimesh triangles | worst | mean | s | gmsh triangles | worst | mean | s | count ratio |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, (loops, holes) in domains().items():
        if args.only and name not in args.only.split(","):
            continue
        base = os.path.join(args.out, name)
        write_poly(base + ".poly", loops, holes)
        write_geo(base + ".geo", loops)
        t_c, r = timed([args.certimesh, "mesh", base + ".poly", "-o", base + ".certimesh.msh", "--quiet"] + args.extra.split(), args.timeout)
        if r.returncode != 0:
            print(f"| {name} | certimesh failed: {r.stderr.strip()[:200]} |")
            continue
        nc, wc, mc = quality(base + ".certimesh.msh")
        row = f"| {name} | {sum(len(l) for l in loops)} | {nc} | {wc:.3f} | {mc:.3f} | {t_c:.2f} |"
        if args.gmsh != "none":
            t_g, r = timed([args.gmsh, "-2", base + ".geo", "-o", base + ".gmsh.msh", "-format", "msh4"], args.timeout)
            if r.returncode != 0:
                row += " gmsh failed |"
            else:
                ng, wg, mg = quality(base + ".gmsh.msh")
                row += f" {ng} | {wg:.3f} | {mg:.3f} | {t_g:.2f} | {nc / ng:.2f} |"
        print(row, flush=True)


if __name__ == "__main__":
    sys.exit(main())

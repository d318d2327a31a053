#!/usr/bin/env python3
"""Meshes written by another tool (Gmsh), certified by `certimesh check` (issue 12, item 7).

Gmsh places boundary nodes on sloped segments in its own floating point, so they are off
the segment by more than half an ulp: the exact rule must refuse them with the vertex, the
segment and the distance named, and `--boundary-tolerance` must accept them, stating how far
the boundary lies from the domain. The expectations come from the geometry here (which
segments are sloped), not from certimesh. Usage: peer_meshes_test.py CERTIMESH WORKDIR.
Exits 77 (skipped) when gmsh is absent.
"""
import os
import re
import shutil
import subprocess
import sys

# (name, vertices, segments as index pairs, loops as segment numbers (outer first), holes):
# every domain has a sloped segment.
DOMAINS = [
    ("triangle", [(0, 0), (3, 0), (0, 1)], [(0, 1), (1, 2), (2, 0)], [[0, 1, 2]], []),
    ("skew_quad_with_hole", [(0, 0), (5, 1), (4, 4), (-1, 3), (1, 1), (3, 1.5), (2, 2.5)],
     [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 4)], [[0, 1, 2, 3], [4, 5, 6]], [(2, 1.7)]),
]


def write_geo(path, vertices, segments, loops, size):
    with open(path, "w") as f:
        for i, (x, y) in enumerate(vertices):
            f.write(f"Point({i + 1}) = {{{x!r}, {y!r}, 0, {size}}};\n")
        for i, (a, b) in enumerate(segments):
            f.write(f"Line({i + 1}) = {{{a + 1}, {b + 1}}};\n")
        for i, loop in enumerate(loops):
            f.write(f"Curve Loop({i + 1}) = {{{', '.join(str(s + 1) for s in loop)}}};\n")
        f.write(f"Plane Surface(1) = {{{', '.join(str(i + 1) for i in range(len(loops)))}}};\n")


def write_poly(path, vertices, segments, holes):
    with open(path, "w") as f:
        f.write(f"{len(vertices)} 2 0 0\n")
        for i, (x, y) in enumerate(vertices):
            f.write(f"{i + 1} {x!r} {y!r}\n")
        f.write(f"{len(segments)} 0\n")
        for i, (a, b) in enumerate(segments):
            f.write(f"{i + 1} {a + 1} {b + 1}\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes):
            f.write(f"{i + 1} {x!r} {y!r}\n")


def check(certimesh, *args):
    run = subprocess.run([certimesh, "check", *args], capture_output=True, text=True, timeout=120)
    return run.returncode, run.stdout + run.stderr


def main():
    certimesh, work = sys.argv[1], sys.argv[2]
    if shutil.which("gmsh") is None:
        print("skipped: gmsh is not installed")
        return 77
    os.makedirs(work, exist_ok=True)
    failures = 0
    for name, vertices, segments, loops, holes in DOMAINS:
        geo, msh, poly = (os.path.join(work, name + ext) for ext in (".geo", ".msh", ".poly"))
        write_geo(geo, vertices, segments, loops, 0.2)
        write_poly(poly, vertices, segments, holes)
        subprocess.run(["gmsh", "-2", geo, "-o", msh, "-format", "msh41"], check=True,
                       capture_output=True, timeout=120)
        rc, out = check(certimesh, msh, "--domain", poly)
        found = re.search(r"boundary vertex \d+ \(.*\) is on no domain segment: the nearest, (\d+), is (\S+) away", out)
        if rc != 1 or found is None:
            print(f"FAIL {name}: the exact rule should refuse Gmsh's rounded nodes (exit {rc}):\n{out}")
            failures += 1
        elif not (0 < float(found.group(2)) < 1e-12):
            print(f"FAIL {name}: the named distance {found.group(2)} is not a rounding error")
            failures += 1
        rc, out = check(certimesh, msh, "--domain", poly, "--boundary-tolerance", "1e-12")
        if rc != 0 or "tiles exactly the polygon through its own boundary vertices" not in out:
            print(f"FAIL {name}: with --boundary-tolerance 1e-12 the mesh should be certified (exit {rc}):\n{out}")
            failures += 1
        rc, out = check(certimesh, msh, "--domain", poly, "--boundary-tolerance", "1e-20")
        if rc != 1:
            print(f"FAIL {name}: a tolerance of 1e-20 is below Gmsh's deviations (exit {rc})")
            failures += 1
    print(f"{3 * len(DOMAINS) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

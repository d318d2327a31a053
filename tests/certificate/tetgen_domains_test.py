#!/usr/bin/env python3
"""TetGen .poly/.smesh domains (issue 12, item 6): TetGen meshes them, `certimesh check
--domain` certifies TetGen's output, and refuses the same meshes broken on purpose.

The oracles are independent of certimesh: TetGen itself (the peer that made the mesh from the
domain), and the volume of every domain, derived by hand below and compared with the sum of
TetGen's tetrahedron volumes in exact rational arithmetic (Python fractions). The broken meshes
are built here from TetGen's output: a cavity filled back in, a region label swapped, a
tetrahedron removed, an internal facet the mesh does not follow.
Usage: tetgen_domains_test.py CERTIMESH WORKDIR. Exits 77 (skipped) when tetgen is absent.
"""
import os
import re
import shutil
import subprocess
import sys
from fractions import Fraction


def box_points(x0, y0, z0, x1, y1, z1):
    return [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
            (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]


def box_quads(first):
    q = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    return [[tuple(first + i for i in quad)] for quad in q]


# Each domain: points, facets (each a list of polygons, 0-based), facet holes per facet index,
# volume holes, regions (x, y, z, attribute), the volume of the solid by hand, tetgen switches.
def domains():
    out = {}
    out["box"] = dict(points=box_points(0, 0, 0, 2, 2, 2), facets=box_quads(0), facet_holes={}, holes=[], regions=[],
                      volume=Fraction(8), switches="-pqa0.05")
    out["cavity"] = dict(points=box_points(0, 0, 0, 4, 4, 4) + box_points(1, 1, 1, 3, 3, 3),
                         facets=box_quads(0) + box_quads(8), facet_holes={}, holes=[(2, 2, 2)], regions=[],
                         volume=Fraction(64 - 8), switches="-pqa0.5")
    # Two unit-by-2 boxes side by side: x in [0,1] and [1,2], the wall x = 1 an internal facet.
    pts = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1, 2)]
    idx = {p: i for i, p in enumerate(pts)}
    def q(*ps):
        return [tuple(idx[p] for p in ps)]
    two = [q((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)), q((1, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0)),
           q((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)), q((1, 0, 1), (2, 0, 1), (2, 1, 1), (1, 1, 1)),
           q((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)), q((1, 0, 0), (2, 0, 0), (2, 0, 1), (1, 0, 1)),
           q((0, 1, 0), (1, 1, 0), (1, 1, 1), (0, 1, 1)), q((1, 1, 0), (2, 1, 0), (2, 1, 1), (1, 1, 1)),
           q((0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)), q((2, 0, 0), (2, 1, 0), (2, 1, 1), (2, 0, 1)),
           q((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1))]  # the wall, last
    out["two_regions"] = dict(points=pts, facets=two, facet_holes={}, holes=[],
                              regions=[(0.5, 0.5, 0.5, 1), (1.5, 0.5, 0.5, 2)], volume=Fraction(2), switches="-pqa0.02A")
    # A 4 x 4 x 2 box with a pocket [1,3]^2 x [1,2] open at the top: the top facet has the
    # pocket's mouth as a facet hole.
    pocket_pts = box_points(0, 0, 0, 4, 4, 2) + [(1, 1, 2), (3, 1, 2), (3, 3, 2), (1, 3, 2),
                                                  (1, 1, 1), (3, 1, 1), (3, 3, 1), (1, 3, 1)]
    pocket = box_quads(0)
    pocket[1] = [(4, 5, 6, 7), (8, 9, 10, 11)]
    pocket += [[(12, 13, 14, 15)], [(8, 9, 13, 12)], [(9, 10, 14, 13)], [(10, 11, 15, 14)], [(11, 8, 12, 15)]]
    out["pocket"] = dict(points=pocket_pts, facets=pocket, facet_holes={1: [(2, 2, 2)]}, holes=[], regions=[],
                         volume=Fraction(32 - 4), switches="-pqa0.2")
    # TetGen's example.poly's trick, written anew: a wall facet with a window (facet hole) that
    # is itself a facet of a closed tunnel box marked as a volume hole, so the window facet has
    # void on both sides and TetGen removes it; a slanted top (Steiner points off its plane).
    win_pts = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 4), (2, 0, 4), (2, 2, 3), (0, 2, 3),
               (0.5, 0, 1), (1.5, 0, 1), (1.5, 0, 2), (0.5, 0, 2), (0.5, 1, 1), (1.5, 1, 1), (1.5, 1, 2), (0.5, 1, 2)]
    window = [[(0, 1, 2, 3)], [(4, 5, 6, 7)], [(0, 1, 5, 4), (8, 9, 10, 11)], [(1, 2, 6, 5)], [(2, 3, 7, 6)], [(3, 0, 4, 7)],
              [(8, 9, 10, 11)], [(12, 13, 14, 15)], [(8, 9, 13, 12)], [(9, 10, 14, 13)], [(10, 11, 15, 14)], [(11, 8, 12, 15)]]
    out["window"] = dict(points=win_pts, facets=window, facet_holes={2: [(1, 0, 1.5)]}, holes=[(1, 0.5, 1.5)],
                         regions=[], volume=Fraction(2 * 2 * 3) + Fraction(2 * 2, 2) - 1, switches="-pq")
    # A slanted top z = 1 + x/3 + y/3, exact at its corners: TetGen's Steiner points on it are
    # rounded off its plane, so the exact rule refuses them and --boundary-tolerance accepts them.
    out["slanted"] = dict(points=[(0, 0, 0), (3, 0, 0), (3, 3, 0), (0, 3, 0), (0, 0, 1), (3, 0, 2), (3, 3, 3), (0, 3, 2)],
                          facets=box_quads(0), facet_holes={}, holes=[], regions=[], volume=Fraction(18),
                          switches="-pqa0.05")
    return out


def write_poly(path, d):
    with open(path, "w") as f:
        f.write(f"{len(d['points'])} 3 0 0\n")
        for i, p in enumerate(d["points"]):
            f.write(f"{i + 1} {p[0]!r} {p[1]!r} {p[2]!r}\n")
        f.write(f"{len(d['facets'])} 1\n")
        for i, polygons in enumerate(d["facets"]):
            holes = d["facet_holes"].get(i, [])
            f.write(f"{len(polygons)} {len(holes)} {i + 1}\n")
            for poly in polygons:
                f.write(f"{len(poly)} {' '.join(str(v + 1) for v in poly)}\n")
            for k, h in enumerate(holes):
                f.write(f"{k + 1} {h[0]!r} {h[1]!r} {h[2]!r}\n")
        f.write(f"{len(d['holes'])}\n")
        for k, h in enumerate(d["holes"]):
            f.write(f"{k + 1} {h[0]!r} {h[1]!r} {h[2]!r}\n")
        f.write(f"{len(d['regions'])}\n")
        for k, r in enumerate(d["regions"]):
            f.write(f"{k + 1} {r[0]!r} {r[1]!r} {r[2]!r} {r[3]} -1\n")


def read_records(path):
    rows = []
    for line in open(path):
        line = line.split("#")[0].split()
        if line:
            rows.append(line)
    return rows


def read_mesh(stem):
    node = read_records(stem + ".node")
    points = [tuple(Fraction(x) for x in r[1:4]) for r in node[1:1 + int(node[0][0])]]
    ele = read_records(stem + ".ele")
    attrs = int(ele[0][2])
    tets = [[int(v) - 1 for v in r[1:5]] for r in ele[1:1 + int(ele[0][0])]]
    labels = [r[5] for r in ele[1:1 + int(ele[0][0])]] if attrs else None
    return points, tets, labels


def write_mesh(stem, points, tets, labels):
    with open(stem + ".node", "w") as f:
        f.write(f"{len(points)} 3 0 0\n")
        for i, p in enumerate(points):
            f.write(f"{i + 1} {float(p[0])!r} {float(p[1])!r} {float(p[2])!r}\n")
    with open(stem + ".ele", "w") as f:
        f.write(f"{len(tets)} 4 {1 if labels else 0}\n")
        for i, t in enumerate(tets):
            f.write(f"{i + 1} {' '.join(str(v + 1) for v in t)}" + (f" {labels[i]}" if labels else "") + "\n")


def volume6(points, t):
    a, b, c, d = (points[v] for v in t)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    w = [d[k] - a[k] for k in range(3)]
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])


def check(certimesh, mesh, domain, *extra):
    r = subprocess.run([certimesh, "check", mesh, "--domain", domain, *extra], capture_output=True, text=True, timeout=120)
    return r.returncode, r.stdout + r.stderr


failures = []


def expect(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def tetgen(work, stem, switches):
    r = subprocess.run(["tetgen", *switches.split(), "-Q", stem + ".poly"], cwd=work, capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        raise SystemExit(f"tetgen {switches} {stem}.poly failed: {r.stdout}{r.stderr}")
    return os.path.join(work, stem + ".1")


def main():
    certimesh, work = sys.argv[1], sys.argv[2]
    if shutil.which("tetgen") is None:
        print("tetgen not found: skipped")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    meshes = {}
    for name, d in domains().items():
        write_poly(os.path.join(work, name + ".poly"), d)
        stem = tetgen(work, name, d["switches"])
        points, tets, labels = read_mesh(stem)
        meshes[name] = (stem, points, tets, labels)
        vol = sum(abs(volume6(points, t)) for t in tets) / 6
        # TetGen rounds its Steiner points, so its mesh's volume is that of the polyhedron
        # through them: equal to the domain's when they lie exactly on the facets.
        code, out = check(certimesh, stem + ".ele", os.path.join(work, name + ".poly"))
        exact = code == 0
        if not exact:  # Steiner points off a slanted facet: the tolerance must accept them
            expect("vertex_off_domain_boundary" in out, f"{name}: refused for another reason than rounding: {out}")
            code, out = check(certimesh, stem + ".ele", os.path.join(work, name + ".poly"), "--boundary-tolerance", "1e-12")
        expect(code == 0 and "valid:" in out, f"{name}: TetGen's mesh not certified: {out}")
        m = re.search(r"boundary vertices on the domain boundary: (\d+) exactly, (\d+) within", out)
        rounded = int(m.group(2)) if m else -1
        if exact and rounded == 0:  # every boundary vertex exactly on its facet: the volume is exact
            expect(vol == d["volume"], f"{name}: TetGen's tetrahedra have volume {vol}, the domain {d['volume']}")
        else:
            expect(abs(vol - d["volume"]) < Fraction(1, 10**9), f"{name}: volume {float(vol)} far from {d['volume']}")
        print(f"{name}: {len(tets)} tetrahedra, volume {float(vol)}, {rounded} boundary vertices only within their rounding box,"
              f" {'exact rule' if exact else '--boundary-tolerance 1e-12'}: certified")

    def broken(name, label, points, tets, labels, want):
        stem = os.path.join(work, f"{name}_{label}")
        write_mesh(stem, points, tets, labels)
        code, out = check(certimesh, stem + ".ele", os.path.join(work, name + ".poly"))
        expect(code == 1 and want in out, f"{name} {label}: expected exit 1 and {want}, got {code}: {out}")

    # TetGen's slanted mesh written with 12 significant digits (as converters and Gmsh's 14
    # digits do): the Steiner points on the slanted top move off it by more than half an ulp;
    # the exact rule refuses naming a vertex, the tolerance accepts and says how far they lie.
    stem, points, tets, _ = meshes["slanted"]
    short = os.path.join(work, "slanted_12digits")
    with open(short + ".node", "w") as f:
        f.write(f"{len(points)} 3 0 0\n")
        for i, p in enumerate(points):
            f.write(f"{i + 1} {float(p[0]):.12g} {float(p[1]):.12g} {float(p[2]):.12g}\n")
    shutil.copy(stem + ".ele", short + ".ele")
    code, out = check(certimesh, short + ".ele", os.path.join(work, "slanted.poly"))
    expect(code == 1 and "vertex_off_domain_boundary" in out and "away" in out, f"slanted 12 digits, exact rule: {code}: {out}")
    code, out = check(certimesh, short + ".ele", os.path.join(work, "slanted.poly"), "--boundary-tolerance", "1e-9")
    expect(code == 0 and "within the boundary tolerance" in out, f"slanted 12 digits, tolerance 1e-9: {code}: {out}")
    print("slanted, 12 digits: refused by the exact rule, certified with --boundary-tolerance 1e-9")
    # The cavity filled back in: TetGen meshes the cavity from the mesh's own triangles on its
    # walls (facet markers 7 to 12 in the .face file; -Y: no new points on them), and those
    # tetrahedra join the mesh.
    stem, points, tets, labels = meshes["cavity"]
    faces = read_records(stem + ".face")
    walls = [[int(v) - 1 for v in r[1:4]] for r in faces[1:1 + int(faces[0][0])] if int(r[4]) >= 7]
    with open(os.path.join(work, "inner.smesh"), "w") as f:
        f.write(f"{len(points)} 3 0 0\n")
        for i, p in enumerate(points):
            f.write(f"{i + 1} {float(p[0])!r} {float(p[1])!r} {float(p[2])!r}\n")
        f.write(f"{len(walls)} 0\n")
        for w in walls:
            f.write(f"3 {w[0] + 1} {w[1] + 1} {w[2] + 1}\n")
        f.write("0\n0\n")
    r = subprocess.run(["tetgen", "-pYQ", "inner.smesh"], cwd=work, capture_output=True, text=True, timeout=120)
    expect(r.returncode == 0, f"tetgen on the cavity: {r.stdout}{r.stderr}")
    ip, it, _ = read_mesh(os.path.join(work, "inner.1"))
    at = {p: i for i, p in enumerate(points)}
    merged = list(points)
    for p in ip:
        if p not in at:
            at[p] = len(merged)
            merged.append(p)
    filled = tets + [[at[ip[v]] for v in t] for t in it]
    broken("cavity", "filled", merged, filled, None, "hole_covered")
    # A region's label swapped on one tetrahedron.
    stem, points, tets, labels = meshes["two_regions"]
    swapped = list(labels)
    swapped[0] = "2" if swapped[0] == "1" else "1"
    broken("two_regions", "swapped", points, tets, swapped, "region_label_mismatch")
    # A tetrahedron removed (the first one that has a face on the domain boundary or not: any).
    broken("two_regions", "removed", points, tets[1:], labels[1:], "invalid:")
    # The internal facet not followed: TetGen meshes the same box without its wall, the labels
    # are given by the side of x = 1 each tetrahedron's centroid is on.
    nowall = dict(domains()["two_regions"])
    nowall["facets"] = [[(0, 1, 2, 5, 4, 3)], [(6, 7, 8, 11, 10, 9)], [(0, 1, 2, 8, 7, 6)], [(3, 4, 5, 11, 10, 9)],
                        [(0, 3, 9, 6)], [(2, 5, 11, 8)]]
    nowall["regions"] = []
    write_poly(os.path.join(work, "nowall.poly"), nowall)
    np_, nt, _ = read_mesh(tetgen(work, "nowall", "-pqa0.02"))
    side = ["1" if sum(np_[v][0] for v in t) < 4 else "2" for t in nt]
    broken("two_regions", "nowall", np_, nt, side, "invalid:")
    # Bad domains: exit 2 with error: for what the reader refuses, exit 1 invalid_domain for
    # what the certificate refuses, each naming the problem.
    box_stem = meshes["box"][0] + ".ele"
    def bad(label, text, code_wanted, want):
        path = os.path.join(work, f"bad_{label}.poly")
        with open(path, "w") as f:
            f.write(text)
        code, out = check(certimesh, box_stem, path)
        expect(code == code_wanted and want in out, f"bad domain {label}: expected {code_wanted} and {want!r}, got {code}: {out}")
    good = open(os.path.join(work, "box.poly")).read()
    bad("nonplanar", good.replace("\n8 0.0 2.0 2.0\n", "\n8 0.0 2.0 2.5\n").replace("\n8 0 2 2\n", "\n8 0 2 2.5\n"), 1, "is not planar")
    bad("repeated_corner", good.replace("4 1 2 3 4", "4 1 2 3 1"), 2, "repeats corner 1")
    bad("out_of_range", good.replace("4 1 2 3 4", "4 1 2 3 9"), 2, "corner 9 does not exist")
    bad("hole_outside", good.rstrip("\n").rsplit("\n", 2)[0] + "\n1\n1 5 5 5\n0\n", 1, "outside the solid")
    bad("truncated", good[: good.index("1 0 3")], 2, "error:")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""`certimesh mesh DOMAIN --min-angle A` (issue 12, item 11): every inside triangle's smallest
angle is at least A degrees, or the triangle is exempt, checked here against an oracle that
shares nothing with the code under test:

- angles from the written coordinates in exact rational arithmetic (Python fractions): the
  angle at o of triangle (o, u, w) is >= A iff dot <= 0 or dot^2 <= cos^2(A) |ou|^2 |ow|^2, with
  cos^2(A) from 50-digit decimals and A lowered by 1e-9 degrees (the mesher measures angles
  with atan2 in double, a few ulps);
- the exemption recomputed from the input geometry, exactly as docs/min_angle.md and
  `certimesh mesh --help` define it: a shortest edge (u, w) of the triangle (exact squared
  lengths) joins two vertices that are not input vertices, u on input segment s1 and w on
  input segment s2 != s1 (on = the segment meets the vertex's rounding box, half-way to the
  neighbouring doubles, as the certificate decides), s1 and s2 share an end point z, the angle
  between s1 and s2 at z is below 60 degrees (exact), and |uz|^2, |wz|^2 agree within a factor
  1.001;
- termination (a timeout) and exit status 0 (4 would mean the Steiner cap stopped it);
- `certimesh check OUT --domain DOMAIN` certifies every mesh (a second, independent run of the
  certificate on the written file).

The domains are built here: the unit square (alone, and with --size 0.07), NACA 0012 with a sharp trailing edge (about 16.5
degrees) and a thinner one (about 5 degrees), each as the airfoil itself and as a box with the
airfoil as a hole, a fan of cuts meeting at one vertex at 1 ... 10 degrees, a square with thin
slits, a square whose bottom is a nearly collinear zigzag chain, an "A" letter with a hole, and
eight random star-shaped 40-gons (input angles down to 0.25 degrees), and a square cut into two
regions (labels checked on each side of the interface).
Usage: min_angle_test.py CERTIMESH DOMAIN [ALGORITHM]
"""
import math
import os
import random
import subprocess
import sys
import tempfile
from decimal import Decimal, getcontext
from fractions import Fraction as F

ANGLES = (20.0, 20.7, 25.0, 30.0)
EXTRA_OPTIONS = {"square_sized": ["--size", "0.07"], "two_regions": ["--size", "0.13"]}  # a size that is no power of two


# ---------------------------------------------------------------- domains
def polygon_segments(first, count):
    return [(first + i, first + (i + 1) % count) for i in range(count)]


def square():
    pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    return pts, polygon_segments(0, 4), []


def naca(thickness, n=48):
    def half(x):
        return 5 * thickness * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x ** 3 - 0.1036 * x ** 4)
    xs = [(1 - math.cos(math.pi * i / n)) / 2 for i in range(n + 1)]  # 0 ... 1
    upper = [(x, half(x)) for x in reversed(xs[1:-1])]                 # from the trailing edge to the nose
    lower = [(x, -half(x)) for x in xs[1:-1]]
    return [(1.0, 0.0)] + upper + [(0.0, 0.0)] + lower


def airfoil(thickness):
    pts = naca(thickness)
    return pts, polygon_segments(0, len(pts)), []


def airfoil_in_box(thickness):
    box = [(-1.0, -1.0), (2.0, -1.0), (2.0, 1.0), (-1.0, 1.0)]
    foil = naca(thickness)
    return box + foil, polygon_segments(0, 4) + polygon_segments(4, len(foil)), [(0.3, 0.0)]


def fan():
    # cuts from the centre at gaps of 1, 2, ..., 10 degrees, inside a 36-gon through their ends
    cut_angles, a = [0.0], 0.0
    for gap in range(1, 11):
        a += gap
        cut_angles.append(a)
    ring = sorted(set(cut_angles + [float(d) for d in range(60, 360, 10)]))
    pts = [(0.0, 0.0)] + [(math.cos(math.radians(d)), math.sin(math.radians(d))) for d in ring]
    segs = polygon_segments(1, len(ring))
    segs += [(0, 1 + ring.index(d)) for d in cut_angles]
    return pts, segs, []


def slits():
    pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    segs = polygon_segments(0, 4)
    holes = []
    for k, (y, w) in enumerate(((0.3, 2.0 ** -10), (0.6, 2.0 ** -14))):
        first = len(pts)
        pts += [(0.2, y), (0.8, y), (0.8, y + w), (0.2, y + w)]
        segs += polygon_segments(first, 4)
        holes.append((0.5, y + w / 2))
    return pts, segs, holes


def zigzag():
    bottom = [(k / 20, (1e-4 if k % 2 else 0.0)) for k in range(21)]
    pts = bottom + [(1.0, 1.0), (0.0, 1.0)]
    return pts, polygon_segments(0, len(pts)), []


def letter_a():
    outer = [(0.0, 0.0), (0.2, 0.0), (0.32, 0.3), (0.68, 0.3), (0.8, 0.0), (1.0, 0.0), (0.6, 1.2), (0.4, 1.2)]
    hole = [(0.38, 0.45), (0.62, 0.45), (0.5, 0.85)]
    return outer + hole, polygon_segments(0, 8) + polygon_segments(8, 3), [(0.5, 0.6)]


def star(seed, n=40):
    """A random star-shaped 40-gon around (0.5, 0.5): spikes with input angles down to 0.25 degrees."""
    rng = random.Random(seed)
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    pts = [(0.5 + r * math.cos(a), 0.5 + r * math.sin(a)) for a in angles for r in [rng.uniform(0.05, 0.5)]]
    return pts, polygon_segments(0, n), []


def two_regions():
    """The unit square cut at x = 0.5 into regions 1 and 2 (an interface the splits must keep
    apart: every triangle's label must be its side's)."""
    pts = [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (1.0, 1.0), (0.5, 1.0), (0.0, 1.0)]
    return pts, polygon_segments(0, 6) + [(1, 4)], []


REGIONS = {"two_regions": ([(0.25, 0.5, 1), (0.75, 0.5, 2)], lambda x, y: 1 if x < 0.5 else 2)}


DOMAINS = {
    "square": square,
    "square_sized": square,
    "naca0012": lambda: airfoil(0.12),
    "naca0012_box": lambda: airfoil_in_box(0.12),
    "naca_5deg": lambda: airfoil(0.036),
    "naca_5deg_box": lambda: airfoil_in_box(0.036),
    "fan": fan,
    "slits": slits,
    "zigzag": zigzag,
    "letter_a": letter_a,
    "two_regions": two_regions,
}
for _seed in range(8):
    DOMAINS[f"star{_seed}"] = lambda seed=_seed: star(seed)


def write_poly(path, pts, segs, holes, regions=()):
    with open(path, "w") as f:
        f.write(f"{len(pts)} 2 0 0\n")
        for i, (x, y) in enumerate(pts):
            f.write(f"{i + 1} {x!r} {y!r}\n")
        f.write(f"{len(segs)} 0\n")
        for i, (a, b) in enumerate(segs):
            f.write(f"{i + 1} {a + 1} {b + 1}\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes):
            f.write(f"{i + 1} {x!r} {y!r}\n")
        if regions:
            f.write(f"{len(regions)}\n")
            for i, (x, y, label) in enumerate(regions):
                f.write(f"{i + 1} {x!r} {y!r} {label} 0\n")


# ---------------------------------------------------------------- reading the mesh
def read_rows(path):
    with open(path) as f:
        return [line.split("#")[0].split() for line in f if line.split("#")[0].strip()]


def read_mesh(node_path):
    rows = read_rows(node_path)
    n = int(rows[0][0])
    first = int(rows[1][0])
    pts = [None] * n
    for r in rows[1:1 + n]:
        pts[int(r[0]) - first] = (float(r[1]), float(r[2]))
    erows = read_rows(node_path[:-5] + ".ele")
    tris = [tuple(int(x) - first for x in r[1:4]) for r in erows[1:1 + int(erows[0][0])]]
    labels = [float(r[4]) if len(r) > 4 else None for r in erows[1:1 + int(erows[0][0])]]
    return pts, tris, labels


# ---------------------------------------------------------------- the oracle
def cos2(angle_degrees):
    getcontext().prec = 50
    # cos by its Taylor series in 50-digit decimals
    x = Decimal(angle_degrees) * Decimal("3.14159265358979323846264338327950288419716939937510") / 180
    term, total, k = Decimal(1), Decimal(1), 0
    while abs(term) > Decimal(10) ** -48:
        k += 2
        term = -term * x * x / (k * (k - 1))
        total += term
    return F(total * total)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1]


def angle_at_least(o, u, w, c2):
    a, b = sub(u, o), sub(w, o)
    d = dot(a, b)
    return d <= 0 or d * d <= c2 * dot(a, a) * dot(b, b)


def rounding_box(p):
    return [((F(math.nextafter(c, -math.inf)) + F(c)) / 2, (F(c) + F(math.nextafter(c, math.inf))) / 2) for c in p]


def segment_meets_box(a, b, box):
    (x0, x1), (y0, y1) = box
    if max(a[0], b[0]) < x0 or min(a[0], b[0]) > x1 or max(a[1], b[1]) < y0 or min(a[1], b[1]) > y1:
        return False
    signs = set()
    for cx in (x0, x1):
        for cy in (y0, y1):
            s = (b[0] - a[0]) * (cy - a[1]) - (b[1] - a[1]) * (cx - a[0])
            signs.add((s > 0) - (s < 0))
    return not (signs == {1} or signs == {-1})


class Exemption:
    def __init__(self, pts, segs):
        self.input = {p for p in pts}
        self.segs = [(tuple(map(F, pts[a])), tuple(map(F, pts[b])), a, b) for a, b in segs]
        self.pts = pts
        self.cache = {}

    def segments_of(self, p):
        if p not in self.cache:
            box = rounding_box(p)
            self.cache[p] = [i for i, (a, b, _, _) in enumerate(self.segs) if segment_meets_box(a, b, box)]
        return self.cache[p]

    def small_input_angle(self, s1, s2):
        a1, b1, i1, j1 = self.segs[s1]
        a2, b2, i2, j2 = self.segs[s2]
        shared = {i1, j1} & {i2, j2}
        if not shared:
            return None
        z = shared.pop()
        pz = tuple(map(F, self.pts[z]))
        f1 = b1 if i1 == z else a1
        f2 = b2 if i2 == z else a2
        u, v = sub(f1, pz), sub(f2, pz)
        d = dot(u, v)
        return pz if d > 0 and 4 * d * d > dot(u, u) * dot(v, v) else None  # angle below 60 degrees

    def exempt(self, corners):
        exact = [tuple(map(F, c)) for c in corners]
        sides = [(dot(sub(exact[(i + 1) % 3], exact[(i + 2) % 3]), sub(exact[(i + 1) % 3], exact[(i + 2) % 3])), i)
                 for i in range(3)]
        shortest = min(s for s, _ in sides)
        for length, i in sides:
            if length > shortest * (1 + F(1, 10 ** 9)):
                continue
            u, w = corners[(i + 1) % 3], corners[(i + 2) % 3]
            if u in self.input or w in self.input:
                continue
            for s1 in self.segments_of(u):
                for s2 in self.segments_of(w):
                    if s1 == s2:
                        continue
                    z = self.small_input_angle(s1, s2)
                    if z is None:
                        continue
                    du = dot(sub(exact[(i + 1) % 3], z), sub(exact[(i + 1) % 3], z))
                    dw = dot(sub(exact[(i + 2) % 3], z), sub(exact[(i + 2) % 3], z))
                    if du < F(1001, 1000) * dw and dw < F(1001, 1000) * du:
                        return True
        return False


def smallest_input_angle(pts, segs):
    at = {}
    for a, b in segs:
        at.setdefault(a, []).append(b)
        at.setdefault(b, []).append(a)
    best = 180.0
    for z, ends in at.items():
        for i in range(len(ends)):
            for j in range(i + 1, len(ends)):
                u, v = sub(pts[ends[i]], pts[z]), sub(pts[ends[j]], pts[z])
                best = min(best, math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), dot(u, v))))
    return best


# ---------------------------------------------------------------- the runs
def count_below(mesh_pts, tris, angle, oracle):
    c2 = cos2(angle - 1e-9)
    exempt = below = 0
    for t in tris:
        exact = [tuple(map(F, mesh_pts[v])) for v in t]
        if all(angle_at_least(exact[i], exact[(i + 1) % 3], exact[(i + 2) % 3], c2) for i in range(3)):
            continue
        if oracle.exempt([mesh_pts[v] for v in t]):
            exempt += 1
        else:
            below += 1
    return exempt, below


def cap_run(certimesh, tmp):
    """--max-steiner stops the refinement short: exit 4, a warning that counts exactly the
    triangles the oracle finds below the angle and not exempt, and a written, certified mesh.
    And a point set with --min-angle is refused (exit 2, nothing written)."""
    pts, segs, holes = fan()
    poly = os.path.join(tmp, "fan.poly")
    write_poly(poly, pts, segs, holes)
    out = os.path.join(tmp, "fan_cap.node")
    run = subprocess.run([certimesh, "mesh", poly, "-o", out, "--min-angle", "30", "--max-steiner", "5", "--quiet"],
                         capture_output=True, text=True, timeout=300)
    failures = []
    if run.returncode != 4:
        failures.append(f"cap: exit {run.returncode}, expected 4")
    if not os.path.exists(out):
        return failures + ["cap: no mesh written"]
    _, below = count_below(*read_mesh(out)[:2], 30.0, Exemption(pts, segs))
    if f"warning: --min-angle 30 not met: {below} triangles below it" not in run.stderr or below == 0:
        failures.append(f"cap: the oracle finds {below} triangles below 30 degrees; stderr says: {run.stderr.strip()}")
    check = subprocess.run([certimesh, "check", out, "--domain", poly], capture_output=True, text=True, timeout=300)
    if check.returncode != 0:
        failures.append(f"cap: certimesh check refuses the mesh: {check.stdout.strip()}")
    print(f"cap: exit {run.returncode}, {below} triangles below 30 degrees reported")
    # a point set (.node, no segments) is not refined: --min-angle is refused, not ignored
    node = os.path.join(tmp, "points.node")
    with open(node, "w") as f:
        f.write("4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 0.9 0.9\n")
    refused = os.path.join(tmp, "points_out.ele")
    run = subprocess.run([certimesh, "mesh", node, "-o", refused, "--min-angle", "20"], capture_output=True, text=True,
                         timeout=60)
    if run.returncode != 2 or "error:" not in run.stderr or os.path.exists(refused):
        failures.append(f"point set with --min-angle: exit {run.returncode}, stderr {run.stderr.strip()!r}")
    return failures


def scale_run(certimesh, tmp):
    """Scaling the input by 2^-30 and 2^40 scales the --min-angle mesh exactly (shells are powers
    of two, Steiner points exact-then-rounded): same triangles, coordinates times the scale."""
    pts, segs, holes = airfoil_in_box(0.036)
    failures, meshes = [], {}
    for k in (0, -30, 40):
        scaled = [(math.ldexp(x, k), math.ldexp(y, k)) for x, y in pts]
        poly = os.path.join(tmp, f"scaled{k}.poly")
        write_poly(poly, scaled, segs, [(math.ldexp(x, k), math.ldexp(y, k)) for x, y in holes])
        out = os.path.join(tmp, f"scaled{k}.node")
        run = subprocess.run([certimesh, "mesh", poly, "-o", out, "--min-angle", "30", "--algorithm", "delaunay",
                              "--quiet"], capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            return [f"scale 2^{k}: exit {run.returncode}: {run.stderr.strip()}"]
        meshes[k] = read_mesh(out)[:2]
    base_pts, base_tris = meshes[0]
    for k in (-30, 40):
        p, tris = meshes[k]
        same = tris == base_tris and p == [(math.ldexp(x, k), math.ldexp(y, k)) for x, y in base_pts]
        print(f"scale 2^{k}: {len(tris)} triangles, {'identical up to the scale' if same else 'DIFFERENT'}")
        if not same:
            failures.append(f"scale 2^{k}: the mesh is not the scaled mesh ({len(tris)} vs {len(base_tris)} triangles)")
    return failures


def main():
    certimesh, name = sys.argv[1], sys.argv[2]
    if name in ("cap", "scale"):
        with tempfile.TemporaryDirectory() as tmp:
            failures = (cap_run if name == "cap" else scale_run)(certimesh, tmp)
        for f in failures:
            print(f"FAIL {f}")
        return 1 if failures else 0
    algorithm = sys.argv[3] if len(sys.argv) > 3 else "delaunay"
    pts, segs, holes = DOMAINS[name]()
    oracle = Exemption(pts, segs)
    failures = []
    print(f"{name}: {len(pts)} vertices, smallest input angle {smallest_input_angle(pts, segs):.2f} degrees")
    with tempfile.TemporaryDirectory() as tmp:
        poly = os.path.join(tmp, name + ".poly")
        regions, side = REGIONS.get(name, ((), None))
        write_poly(poly, pts, segs, holes, regions)
        for angle in ANGLES:
            out = os.path.join(tmp, f"{name}_{angle}.node")
            run = subprocess.run([certimesh, "mesh", poly, "-o", out, "--min-angle", str(angle), "--algorithm",
                                  algorithm, "--quiet"] + EXTRA_OPTIONS.get(name, []), capture_output=True, text=True, timeout=300)
            if run.returncode != 0:
                failures.append(f"A={angle}: exit {run.returncode}: {run.stderr.strip()}")
                continue
            check = subprocess.run([certimesh, "check", out, "--domain", poly], capture_output=True, text=True,
                                   timeout=300)
            if check.returncode != 0:
                failures.append(f"A={angle}: certimesh check refuses the mesh: {check.stdout.strip()} {check.stderr.strip()}")
            mesh_pts, tris, labels = read_mesh(out)
            exempt, below = count_below(mesh_pts, tris, angle, oracle)
            if side is not None:
                wrong = sum(1 for t, label in zip(tris, labels)
                            if label != side(sum(mesh_pts[v][0] for v in t) / 3, sum(mesh_pts[v][1] for v in t) / 3))
                if wrong:
                    failures.append(f"A={angle}: {wrong} triangles carry the other region's label")
            print(f"  A={angle}: {len(tris)} triangles, {exempt} exempt, {below} below the bound")
            if below:
                failures.append(f"A={angle}: {below} triangles below {angle} degrees and not exempt")
    for f in failures:
        print(f"FAIL {name} ({algorithm}): {f}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

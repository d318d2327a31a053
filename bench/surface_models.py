#!/usr/bin/python3
"""Real closed surfaces: certimesh beside `tetgen -pYq1.414` and `gmsh -3` (issue 13).

For every surface of the corpus (bench/data/surfaces/SOURCES.md: CGAL and OpenCASCADE models,
small ones in the repository, big ones fetched into bench/data/surfaces/cache by
bench/fetch_surfaces.py):
  the surface  checked here first: every edge in exactly two triangles, consistently oriented,
               no zero-area triangle, no repeated vertex or triangle; `tetgen -d` for
               self-intersections. A model that fails is reported and not meshed.
  certimesh    `certimesh mesh MODEL -o OUT.mesh --quiet` (default options; MODEL is the
               surface file as fetched, .off or .stl) and `certimesh check OUT.mesh --domain MODEL`
               (certified yes/no);
  TetGen       `tetgen -pYq1.414 MODEL.smesh`, the .smesh written here from the welded surface
               with round-trip (17-digit) coordinates, so that it holds the same doubles;
  Gmsh         `gmsh -3 MODEL.geo`: the .geo merges the surface written here as an MSH 2.2
               discrete surface (17-digit coordinates) and makes one volume of it
               (Surface Loop{1}; Volume{1}): Gmsh meshes the inside and keeps the surface mesh.
Every command has a timeout; a failure (exit status, first error line, timeout, signal) is a
row of the table, never fatal.

Measured here, from the output files, with the same code for the three tools: tetrahedra,
Steiner points (output vertices beyond the input's), worst tetrahedron quality
6^4*sqrt(2)*|V|/P^3 (P the sum of the six edge lengths; 1 for the regular tetrahedron, design
decision 4), the smallest dihedral angle, inverted or flat tetrahedra, the volume against the
surface's enclosed volume, and whether the output's boundary is exactly the input surface: the
boundary faces (faces of one tetrahedron) are the input triangles, one for one, on vertices
with bit-identical coordinates.

The unit cube row: a cube surface with 2 x N x N triangles per face (written here, N = 40 by
default) meshed by `certimesh mesh cube.off --size S` and `tetgen -pYq1.414aV`, S and V chosen
to give about 10^6 tetrahedra; tetrahedra per second for both (wall clock, whole command).

/usr/bin/python3 with numpy (Debian's python3-numpy); failures are reported, never fatal.
Usage:
  python3 bench/fetch_surfaces.py                  # the big models into the cache
  /usr/bin/python3 bench/surface_models.py --certimesh build/bin/certimesh \
      --out bench/results/surface_models.md [--only NAME ...] [--timeout 300] [--no-cube]
"""

import argparse
import datetime
import hashlib
import math
import os
import platform
import re
import resource
import shlex
import struct
import subprocess
import sys
import tempfile
import time

import numpy as np

import planar_examples  # its record of the run (provenance)

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data", "surfaces")
CACHE = os.path.join(DATA, "cache")
QUALITY_SCALE = 6.0 ** 4 * math.sqrt(2.0)


# ---------------------------------------------------------------------------------------------
# The corpus

def read_sources(path=os.path.join(DATA, "SOURCES.md")):
    """The corpus table of SOURCES.md: [{name, file, kind, sha256, status}] for rows marked kept."""
    rows = []
    with open(path) as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) >= 7 and cells[0].startswith("`") and cells[0].endswith("`"):
                rows.append({"file": cells[0].strip("`"), "kind": cells[1], "collection": cells[2],
                             "where": cells[3], "sha256": cells[5].strip("`"), "status": cells[6]})
    return rows


def model_path(row):
    """The model's file: in bench/data/surfaces/ when small, else in the cache."""
    for directory in (DATA, CACHE):
        path = os.path.join(directory, row["file"])
        if os.path.exists(path):
            return path
    return None


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


# ---------------------------------------------------------------------------------------------
# Reading surfaces (vertices welded by identical coordinates) and meshes

class Surface:
    """A triangulated surface: vertices (n x 3 float64) and triangles (m x 3 int64, 0-based)."""

    def __init__(self, vertices, triangles):
        self.vertices = np.asarray(vertices, dtype=np.float64).reshape(-1, 3)
        self.triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)


def read_off(path):
    with open(path) as f:
        tokens = f.read().split("\n")
    words = []
    for line in tokens:
        words.extend(line.split("#", 1)[0].split())
    if not words or not words[0].endswith("OFF"):
        raise ValueError("%s: not an OFF file" % path)
    nv, nf = int(words[1]), int(words[2])
    at = 4
    vertices = np.array(words[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    triangles = []
    for face in range(nf):
        k = int(words[at])
        if k != 3:
            raise ValueError("%s: face %d has %d vertices (triangles only)" % (path, face, k))
        triangles.append([int(w) for w in words[at + 1:at + 4]])
        at += 1 + k
    return Surface(vertices, triangles)


def read_stl(path):
    """ASCII or binary STL; vertices welded by identical coordinates (float32 read exactly)."""
    with open(path, "rb") as f:
        data = f.read()
    corners = None
    if len(data) >= 84:
        n = struct.unpack_from("<I", data, 80)[0]
        if 84 + 50 * n == len(data):
            records = np.frombuffer(data, dtype=np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)),
                                                         ("attr", "<u2")]), count=n, offset=84)
            corners = records["v"].astype(np.float64).reshape(-1, 3)
    if corners is None:
        values = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
        corners = np.array([[float(x) for x in v] for v in values], dtype=np.float64)
    vertices, inverse = np.unique(corners, axis=0, return_inverse=True)
    # Keep the first-appearance order, as the readers of certimesh and meshio do.
    first = np.full(len(vertices), len(inverse), dtype=np.int64)
    np.minimum.at(first, inverse.reshape(-1), np.arange(len(inverse)))
    order = np.argsort(first)
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    return Surface(vertices[order], rank[inverse.reshape(-1)].reshape(-1, 3))


def read_surface(path):
    return read_stl(path) if path.lower().endswith(".stl") else read_off(path)


def numbers(path, skip_comments=True):
    with open(path) as f:
        text = f.read()
    if skip_comments:
        text = re.sub(r"#[^\n]*", "", text)
    return text.split()


def read_tetgen(stem):
    """TetGen .node/.ele: points (n x 3) and tetrahedra (m x 4, 0-based)."""
    w = numbers(stem + ".node")
    n, dim, attrs, marker = (int(x) for x in w[:4])
    width = 1 + dim + attrs + (1 if marker else 0)
    rows = np.array(w[4:4 + n * width], dtype=np.float64).reshape(n, width)
    first = int(rows[0, 0]) if n else 0
    points = rows[:, 1:4]
    w = numbers(stem + ".ele")
    m, per, region = (int(x) for x in w[:3])
    width = 1 + per + (1 if region else 0)
    cells = np.array(w[3:3 + m * width], dtype=np.int64).reshape(m, width)[:, 1:5] - first
    return points, cells


def read_medit(path):
    """Medit .mesh (ASCII): points and tetrahedra (0-based)."""
    w = numbers(path)
    points, tets, i = None, np.zeros((0, 4), dtype=np.int64), 0
    while i < len(w):
        key = w[i]
        if key == "Vertices":
            n = int(w[i + 1])
            points = np.array(w[i + 2:i + 2 + 4 * n], dtype=np.float64).reshape(n, 4)[:, :3]
            i += 2 + 4 * n
        elif key in ("Triangles", "Edges", "Tetrahedra", "Corners", "RequiredVertices", "Ridges"):
            n = int(w[i + 1])
            per = {"Triangles": 4, "Edges": 3, "Tetrahedra": 5}.get(key, 1)
            if key == "Tetrahedra":
                tets = np.array(w[i + 2:i + 2 + per * n], dtype=np.int64).reshape(n, per)[:, :4] - 1
            i += 2 + per * n
        elif key == "Dimension":
            i += 2
        else:
            i += 1
    if points is None:
        raise ValueError("%s: no Vertices" % path)
    return points, tets


def read_msh22_tets(path):
    """Gmsh MSH 2.2 ASCII: points and the 4-node tetrahedra (0-based)."""
    with open(path) as f:
        lines = f.read().split("\n")
    i, tags, coords, tets = 0, [], [], []
    while i < len(lines):
        if lines[i] == "$Nodes":
            n = int(lines[i + 1])
            block = np.array(" ".join(lines[i + 2:i + 2 + n]).split(), dtype=np.float64).reshape(n, 4)
            tags, coords = block[:, 0].astype(np.int64), block[:, 1:4]
            i += 2 + n
        elif lines[i] == "$Elements":
            n = int(lines[i + 1])
            for line in lines[i + 2:i + 2 + n]:
                t = line.split()
                if t[1] == "4":
                    tets.append(t[3 + int(t[2]):7 + int(t[2])])
            i += 2 + n
        else:
            i += 1
    index = np.full(int(tags.max()) + 1 if len(tags) else 1, -1, dtype=np.int64)
    index[tags] = np.arange(len(tags))
    cells = index[np.array(tets, dtype=np.int64).reshape(-1, 4)]
    return coords, cells


# ---------------------------------------------------------------------------------------------
# The surface's own checks

def surface_problems(s):
    """Why the surface is not a closed oriented 2-manifold without repeats, or []."""
    problems = []
    t = s.triangles
    if len(t) == 0:
        return ["no triangles"]
    if t.min() < 0 or t.max() >= len(s.vertices):
        return ["a triangle index out of range"]
    if len(np.unique(s.vertices, axis=0)) != len(s.vertices):
        problems.append("repeated vertices")
    if np.any((t[:, 0] == t[:, 1]) | (t[:, 1] == t[:, 2]) | (t[:, 0] == t[:, 2])):
        problems.append("a triangle with a repeated vertex")
    p = s.vertices
    area = np.linalg.norm(np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]]), axis=1)
    if np.any(area == 0.0):
        problems.append("%d zero-area triangles (in double)" % int(np.sum(area == 0.0)))
    if len(np.unique(np.sort(t, axis=1), axis=0)) != len(t):
        problems.append("repeated triangles")
    directed = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    undirected = np.sort(directed, axis=1)
    _, counts = np.unique(undirected, axis=0, return_counts=True)
    if np.any(counts == 1):
        problems.append("open: %d edges in one triangle" % int(np.sum(counts == 1)))
    if np.any(counts > 2):
        problems.append("non-manifold: %d edges in 3 or more triangles" % int(np.sum(counts > 2)))
    if np.all(counts == 2):
        _, dcounts = np.unique(directed, axis=0, return_counts=True)
        if np.any(dcounts > 1):
            problems.append("inconsistent orientation (%d directed edges twice)" % int(np.sum(dcounts > 1)))
    return problems


def enclosed_volume(s):
    """The signed volume the oriented surface encloses (divergence theorem, in double)."""
    p = s.vertices[s.triangles]
    return float(np.sum(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2]))) / 6.0)


def self_intersections(smesh, timeout):
    """`tetgen -d` on the surface: (True, what it says) when facets intersect, (False, None) when
    it finds none, (None, why) when it gave no answer (the model is then meshed, with a note)."""
    r, _, failure = run(["tetgen", "-d", smesh], timeout, cwd=os.path.dirname(smesh))
    if failure:
        return None, "tetgen -d: " + failure
    text = r.stdout + r.stderr
    if "No faces are intersecting" in text:
        return False, None
    found = re.search(r"(\d+)\s+(pairs of faces|faces) (are )?intersect\w*", text)
    if found:
        return True, "tetgen -d: " + found.group(0)
    return None, "tetgen -d gave no verdict: " + first_error(r)


# ---------------------------------------------------------------------------------------------
# Writing the surface for each tool

def write_off(s, path):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(s.vertices), len(s.triangles)))
        for p in s.vertices:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in s.triangles:
            f.write("3 %d %d %d\n" % tuple(t))


def write_smesh(s, path):
    with open(path, "w") as f:
        f.write("# written by bench/surface_models.py: 17-digit coordinates\n")
        f.write("%d 3 0 0\n" % len(s.vertices))
        for i, p in enumerate(s.vertices):
            f.write("%d %.17g %.17g %.17g\n" % (i, *p))
        f.write("%d 0\n" % len(s.triangles))
        for t in s.triangles:
            f.write("3 %d %d %d\n" % tuple(t))
        f.write("0\n0\n")


def write_gmsh_geo(s, work):
    msh = os.path.join(work, "surface.msh")
    with open(msh, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(s.vertices))
        for i, p in enumerate(s.vertices):
            f.write("%d %.17g %.17g %.17g\n" % (i + 1, *p))
        f.write("$EndNodes\n$Elements\n%d\n" % len(s.triangles))
        for i, t in enumerate(s.triangles):
            f.write("%d 2 2 1 1 %d %d %d\n" % (i + 1, t[0] + 1, t[1] + 1, t[2] + 1))
        f.write("$EndElements\n")
    geo = os.path.join(work, "volume.geo")
    with open(geo, "w") as f:
        f.write('Merge "surface.msh";\nSurface Loop(1) = {1};\nVolume(1) = {1};\n')
    return geo


# ---------------------------------------------------------------------------------------------
# Measures, computed here for every mesh with one formula

def tetra_measures(points, tets):
    """Counts, worst quality 6^4 sqrt(2)|V|/P^3, smallest dihedral angle, volume, inverted."""
    if len(tets) == 0:
        return {"tets": 0}
    p = points[tets]                     # m x 4 x 3
    a, b, c, d = p[:, 0], p[:, 1], p[:, 2], p[:, 3]
    six_v = np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))   # det[b-a, c-a, d-a]
    edges = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    perimeter = sum(np.linalg.norm(p[:, i] - p[:, j], axis=1) for i, j in edges)
    with np.errstate(divide="ignore", invalid="ignore"):
        quality = np.where(perimeter > 0, QUALITY_SCALE * np.abs(six_v) / 6.0 / perimeter ** 3, 0.0)
    # Face k is opposite vertex k; its normal is turned away from vertex k. The dihedral angle at
    # the edge shared by faces k and l is pi minus the angle between their outer normals.
    faces = [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)]
    normals = []
    for k, (i, j, l) in enumerate(faces):
        n = np.cross(p[:, j] - p[:, i], p[:, l] - p[:, i])
        away = np.einsum("ij,ij->i", n, p[:, k] - p[:, i])
        n = np.where((away > 0)[:, None], -n, n)
        normals.append(n / np.maximum(np.linalg.norm(n, axis=1), 1e-300)[:, None])
    smallest = np.full(len(tets), math.pi)
    for k in range(4):
        for l in range(k + 1, 4):
            cosine = np.clip(-np.einsum("ij,ij->i", normals[k], normals[l]), -1.0, 1.0)
            smallest = np.minimum(smallest, np.arccos(cosine))
    smallest = np.where(six_v == 0, 0.0, smallest)
    return {"tets": len(tets), "points": len(points), "worst": float(quality.min()),
            "mean": float(quality.mean()), "min_dihedral": math.degrees(float(smallest.min())),
            "volume": float(np.abs(six_v).sum() / 6.0),
            "inverted": int(np.sum(six_v <= 0)), "negative": int(np.sum(six_v < 0))}


def boundary_is_input(points, tets, surface, digits=None):
    """Whether the faces of exactly one tetrahedron are the input triangles, one for one, on
    output vertices bit-identical to the input's (or equal when both are printed with `digits`
    significant digits); (answer, reason)."""
    faces = np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 2, 3]], tets[:, [0, 1, 3]], tets[:, [0, 1, 2]]])
    faces = np.sort(faces, axis=1)
    unique, counts = np.unique(faces, axis=0, return_counts=True)
    boundary = unique[counts == 1]
    def key(q):
        return q if digits is None else tuple("%.*g" % (digits, x) for x in q)
    where = {}
    for i, q in enumerate(map(tuple, points.tolist())):
        where.setdefault(key(q), i)
    missing_vertices = 0
    image = np.empty(len(surface.vertices), dtype=np.int64)
    for i, q in enumerate(map(tuple, surface.vertices.tolist())):
        image[i] = where.get(key(q), -1)
        missing_vertices += image[i] < 0
    if missing_vertices:
        return False, "%d input vertices not in the output (bit for bit)" % missing_vertices
    wanted = np.sort(image[surface.triangles], axis=1)
    wanted_set = set(map(tuple, wanted.tolist()))
    boundary_set = set(map(tuple, boundary.tolist()))
    missing = len(wanted_set - boundary_set)
    extra = len(boundary_set - wanted_set)
    if missing or extra:
        return False, "%d input triangles not boundary faces, %d other boundary faces" % (missing, extra)
    return True, ""


# ---------------------------------------------------------------------------------------------
# Running the tools

def run(command, timeout, cwd=None):
    """(completed process with .cpu, its user + system seconds; wall seconds; failure or None)."""
    start = time.perf_counter()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        r = subprocess.run(command, capture_output=True, text=True, timeout=timeout, cwd=cwd,
                           errors="replace")
    except subprocess.TimeoutExpired:
        return None, timeout, "timeout: no answer after %g s" % timeout
    except OSError as e:
        return None, 0.0, "could not run %s: %s" % (command[0], e)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    r.cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return r, time.perf_counter() - start, None


def first_error(r):
    for line in (r.stderr + "\n" + r.stdout).splitlines():
        s = line.strip()
        if s.lower().startswith("error") or "invalid:" in s or s.startswith("Abort") or "failed" in s.lower():
            return s
    lines = (r.stderr or r.stdout).strip().splitlines()
    if r.returncode < 0:
        return "killed by signal %d%s" % (-r.returncode, " (last line: %s)" % lines[-1].strip() if lines else "")
    return "exit %d: %s" % (r.returncode, lines[-1] if lines else "(no output)")


def measured(result, points, tets, surface):
    if len(tets) == 0 or len(points) == 0:
        result["error"] = "the output holds no tetrahedra"
        return result
    if tets.min() < 0 or tets.max() >= len(points):
        result["error"] = "the output's tetrahedra name vertices it does not hold"
        return result
    result.update(tetra_measures(points, tets))
    result["steiner"] = len(points) - len(surface.vertices)
    result["exact_boundary"], reason = boundary_is_input(points, tets, surface)
    if reason and "not in the output" in reason:
        # Gmsh writes MSH 2.2 coordinates with 16 significant digits, which need not give the
        # same double back: compare at 16 digits too, and say which test passed.
        close, _ = boundary_is_input(points, tets, surface, digits=16)
        if close:
            result["boundary_16_digits"] = True
    if reason:
        result["boundary_note"] = reason
    return result


def run_certimesh(certimesh, model, surface, work, timeout, options=(), check_domain=""):
    """`certimesh mesh` then `certimesh check OUT --domain D` (D: the model unless given; None:
    no --domain)."""
    out = os.path.join(work, "certimesh.mesh")
    r, seconds, failure = run([certimesh, "mesh", model, "-o", out, "--quiet"] + list(options), timeout)
    result = {"seconds": seconds, "cpu": getattr(r, "cpu", None)}
    if failure or r.returncode != 0 or not os.path.exists(out):
        result["error"] = failure or first_error(r)
        return result
    points, tets = read_medit(out)
    measured(result, points, tets, surface)
    domain = model if check_domain == "" else check_domain
    r, _, failure = run([certimesh, "check", out] + (["--domain", domain] if domain else []), timeout)
    result["certified"] = bool(r) and r.returncode == 0
    if not result["certified"]:
        result["check_error"] = failure or first_error(r)
    return result


def run_tetgen(smesh, surface, timeout, switches="-pYq1.414"):
    r, seconds, failure = run(["tetgen", switches, smesh], timeout, cwd=os.path.dirname(smesh))
    stem = smesh[:-len(".smesh")] + ".1"
    result = {"seconds": seconds, "cpu": getattr(r, "cpu", None)}
    if failure or r.returncode != 0 or not os.path.exists(stem + ".ele"):
        result["error"] = failure or first_error(r)
        return result
    points, tets = read_tetgen(stem)
    return measured(result, points, tets, surface)


def run_gmsh(geo, surface, work, timeout):
    out = os.path.join(work, "gmsh.msh")
    r, seconds, failure = run(["gmsh", "-3", geo, "-o", out, "-format", "msh22",
                               "-setnumber", "Mesh.SaveAll", "1"], timeout, cwd=work)
    result = {"seconds": seconds, "cpu": getattr(r, "cpu", None)}
    if failure or r.returncode != 0 or not os.path.exists(out):
        result["error"] = failure or first_error(r)
        return result
    points, tets = read_msh22_tets(out)
    if len(tets) == 0:
        result["error"] = "no tetrahedra: " + first_error(r)
        return result
    return measured(result, points, tets, surface)


# ---------------------------------------------------------------------------------------------
# One model

def measure(row, certimesh, tools, timeout):
    out = {"name": row["file"], "kind": row["kind"], "collection": row["collection"], "notes": []}
    path = model_path(row)
    if path is None:
        out["skip"] = "not fetched (run bench/fetch_surfaces.py)"
        return out
    if row["sha256"] and sha256(path) != row["sha256"]:
        out["notes"].append("SHA-256 differs from SOURCES.md")
    try:
        surface = read_surface(path)
    except (ValueError, IndexError, OSError) as e:
        out["skip"] = "unreadable: %s" % e
        return out
    out["vertices"], out["triangles"] = len(surface.vertices), len(surface.triangles)
    out["enclosed"] = enclosed_volume(surface)
    with tempfile.TemporaryDirectory(prefix="surface-") as work:
        smesh = os.path.join(work, "model.smesh")
        write_smesh(surface, smesh)
        problems = surface_problems(surface)
        if not problems:
            crossing, message = self_intersections(smesh, timeout)
            if crossing:
                problems.append(message)
            elif message:
                out["notes"].append("self-intersections not checked: " + message)
        if problems:
            out["skip"] = "invalid surface: " + "; ".join(problems)
            return out
        for tool in tools:
            try:
                if tool == "certimesh":
                    out[tool] = run_certimesh(certimesh, path, surface, work, timeout)
                elif tool == "tetgen":
                    out[tool] = run_tetgen(smesh, surface, timeout)
                else:
                    out[tool] = run_gmsh(write_gmsh_geo(surface, work), surface, work, timeout)
            except Exception as e:  # a harness failure is reported in the row, never fatal
                out[tool] = {"error": "harness: %s: %s" % (type(e).__name__, e)}
    return out


# ---------------------------------------------------------------------------------------------
# The unit cube

def cube_surface(n):
    """The boundary of [0,1]^3, each face an n x n grid of squares cut into two triangles,
    oriented outward; grid coordinates i/n rounded once."""
    index, vertices, triangles = {}, [], []

    def vertex(q):
        if q not in index:
            index[q] = len(vertices)
            vertices.append([v / n for v in q])
        return index[q]

    for axis in range(3):
        for side in (0, n):
            u, w = [a for a in range(3) if a != axis]
            for i in range(n):
                for j in range(n):
                    def at(di, dj):
                        q = [0, 0, 0]
                        q[axis], q[u], q[w] = side, i + di, j + dj
                        return vertex(tuple(q))
                    a, b, c, d = at(0, 0), at(1, 0), at(1, 1), at(0, 1)
                    # (u, w, axis) is a right-handed frame for axis 0 and 2, left-handed for 1.
                    outward = (side == n) == (axis != 1)
                    if outward:
                        triangles += [[a, b, c], [a, c, d]]
                    else:
                        triangles += [[a, c, b], [a, d, c]]
    return Surface(vertices, triangles)


def measure_cube(certimesh, tools, n, size, volume, timeout, point_set=True):
    surface = cube_surface(n)
    out = {"name": "unit cube, 2x%dx%d triangles a face" % (n, n), "notes": [],
           "vertices": len(surface.vertices), "triangles": len(surface.triangles), "enclosed": 1.0}
    problems = surface_problems(surface)
    if problems or abs(enclosed_volume(surface) - 1.0) > 1e-12:
        out["skip"] = "harness: the cube surface is wrong: %s" % problems
        return out
    with tempfile.TemporaryDirectory(prefix="surface-cube-") as work:
        off = os.path.join(work, "cube.off")
        write_off(surface, off)
        smesh = os.path.join(work, "cube.smesh")
        write_smesh(surface, smesh)
        node = os.path.join(work, "cube_vertices.node")
        with open(node, "w") as f:
            f.write("%d 3 0 0\n" % len(surface.vertices))
            for i, p in enumerate(surface.vertices):
                f.write("%d %.17g %.17g %.17g\n" % (i, *p))
        runs = {"certimesh": lambda: run_certimesh(certimesh, off, surface, work, timeout, ["--size", repr(size)]),
                "tetgen": lambda: run_tetgen(smesh, surface, timeout, "-pYq1.414a%g" % volume),
                "certimesh_points": lambda: run_certimesh(certimesh, node, surface, work, timeout,
                                                          ["--size", repr(size)], check_domain=None)}
        for tool in runs:
            if tool.split("_")[0] not in tools or (tool == "certimesh_points" and not point_set):
                continue
            try:
                out[tool] = runs[tool]()
            except Exception as e:  # a harness failure is reported in the row, never fatal
                out[tool] = {"error": "harness: %s: %s" % (type(e).__name__, e)}
    out["cube"] = {"size": size, "volume": volume}
    return out


# ---------------------------------------------------------------------------------------------
# The table

TOOLS = ("certimesh", "tetgen", "gmsh")


def without_paths(message):
    message = message.replace(DATA + os.sep, "").replace(CACHE + os.sep, "")
    return re.sub(r"\S*surface-[^/\s]*/", "", message).replace("|", "\\|")


def seconds(d):
    """Wall seconds, and in parentheses the command's CPU seconds (user + system)."""
    if "seconds" not in d:
        return ""
    return "%.2f (%.2f)" % (d["seconds"], d["cpu"]) if d.get("cpu") is not None else "%.2f" % d["seconds"]


def tool_cells(d, with_certified):
    if not d:
        return ["—"] * (8 if with_certified else 7)
    if "error" in d:
        cells = ["**no**", seconds(d), "", "", "", ""]
        return cells + ([""] if with_certified else []) + [""]
    cells = ["yes", seconds(d), "%d" % d["tets"], "%d" % d["steiner"],
             "%.3g" % d["worst"], "%.3g" % d["min_dihedral"]]
    if with_certified:
        cells.append("yes" if d.get("certified") else "**no**")
    cells.append("yes" if d.get("exact_boundary") else "to 16 digits" if d.get("boundary_16_digits") else "no")
    return cells


def ratio(a, b, key):
    x, y = (a or {}).get(key), (b or {}).get(key)
    if x is not None and y and "error" not in a and "error" not in b:
        return "%.2f" % (x / y)
    return ""


def table(rows):
    head = ["model", "kind", "V / T in"]
    for tool in TOOLS:
        head += ["%s ok" % tool, "s (CPU s)", "tets", "Steiner", "worst q", "min dih °"]
        if tool == "certimesh":
            head.append("certified")
        head.append("surface kept")
    head += ["CPU c/t", "tets c/t", "worst q c/t"]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for row in rows:
        if "skip" in row:
            continue
        cells = [row["name"], row.get("kind", ""), "%d / %d" % (row["vertices"], row["triangles"])]
        for tool in TOOLS:
            cells += tool_cells(row.get(tool), tool == "certimesh")
        c, t = row.get("certimesh"), row.get("tetgen")
        cells += [ratio(c, t, "cpu"), ratio(c, t, "tets"), ratio(c, t, "worst")]
        out.append("| " + " | ".join(cells) + " |")
    notes = []
    for row in rows:
        if "skip" in row:
            notes.append("- `%s` not meshed: %s" % (row["name"], without_paths(row["skip"])))
            continue
        for tool in TOOLS:
            d = row.get(tool) or {}
            if "error" in d:
                notes.append("- `%s` %s: %s" % (row["name"], tool, without_paths(d["error"])))
            if "check_error" in d:
                notes.append("- `%s` certimesh check: %s" % (row["name"], without_paths(d["check_error"])))
            if "boundary_note" in d:
                notes.append("- `%s` %s boundary: %s" % (row["name"], tool, d["boundary_note"]))
            if d.get("inverted"):
                notes.append("- `%s` %s: %d tetrahedra of volume <= 0 (%d negative)"
                             % (row["name"], tool, d["inverted"], d["negative"]))
            if "volume" in d and abs(d["volume"] - abs(row["enclosed"])) > 1e-6 * abs(row["enclosed"]):
                notes.append("- `%s` %s: mesh volume %.12g, the surface encloses %.12g"
                             % (row["name"], tool, d["volume"], abs(row["enclosed"])))
        for note in row["notes"]:
            notes.append("- `%s`: %s" % (row["name"], note))
    return "\n".join(out) + "\n\nErrors and notes:\n\n" + ("\n".join(notes) if notes else "(none)") + "\n"


CUBE_TOOLS = (("certimesh", "certimesh mesh cube.off --size %(size)g"),
              ("tetgen", "tetgen -pYq1.414a%(volume)g cube.smesh"),
              ("certimesh_points", "certimesh mesh cube_vertices.node --size %(size)g"))


def cube_table(row):
    if row is None:
        return ""
    out = ["| tool | command | ok | s (CPU s) | tetrahedra | tetrahedra per CPU s | per wall s "
           "| worst q | min dih ° | surface kept | certified |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for tool, command in CUBE_TOOLS:
        d = row.get(tool)
        if not d:
            continue
        command = command % row["cube"]
        if "error" in d:
            out.append("| %s | `%s` | **no** | %s | | | | | | | |" % (tool, command, seconds(d)))
            continue
        certified = ("yes" if d["certified"] else "**no**") if "certified" in d else "—"
        out.append("| %s | `%s` | yes | %s | %d | %s | %.0f | %.3g | %.3g | %s | %s |" % (
            tool, command, seconds(d), d["tets"], "%.0f" % (d["tets"] / d["cpu"]) if d.get("cpu") else "",
            d["tets"] / d["seconds"], d["worst"], d["min_dihedral"], "yes" if d.get("exact_boundary") else "no",
            certified))
    c, t = row.get("certimesh") or {}, row.get("tetgen") or {}
    text = "%s (%d vertices, %d triangles).\n\n" % (row["name"], row["vertices"], row["triangles"]) + "\n".join(out)
    if c.get("cpu") and t.get("cpu") and "tets" in c and "tets" in t:
        text += "\n\nTetrahedra per CPU second, certimesh / TetGen: **%.2f** (per wall second %.2f).\n" % (
            (c["tets"] / c["cpu"]) / (t["tets"] / t["cpu"]), (c["tets"] / c["seconds"]) / (t["tets"] / t["seconds"]))
    if "certimesh_points" in row:
        text += ("\n\n`certimesh_points` is not the issue's command: the cube surface's vertices as a point "
                 "set, whose convex hull is the cube, meshed by certimesh's 3D point-set path with the "
                 "same --size (its hull triangulation of the faces need not be the input's). It runs "
                 "where `certimesh mesh cube.off` does not yet, and shows the refinement's rate.\n")
    for tool, _ in CUBE_TOOLS:
        d = row.get(tool) or {}
        if "error" in d:
            text += "\n- %s: %s\n" % (tool, without_paths(d["error"]))
        if "check_error" in d:
            text += "\n- %s, certimesh check: %s\n" % (tool, without_paths(d["check_error"]))
    return text + "\n"


def provenance(certimesh):
    """The run's date, tool versions, load and machine (planar_examples' record, TetGen added)."""
    info = planar_examples.provenance(certimesh)
    try:
        version = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "tetgen"], capture_output=True,
                                 text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        version = "?"
    info["tetgen"] = "TetGen %s (Debian package)" % (version or "?")
    return info


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--certimesh", default="build/bin/certimesh")
    parser.add_argument("--out", help="write the Markdown report here (default: stdout only)")
    parser.add_argument("--only", nargs="*", help="models whose file name contains one of these")
    parser.add_argument("--tools", default="certimesh,tetgen,gmsh", help="comma-separated subset")
    parser.add_argument("--timeout", type=float, default=300.0, help="per command, seconds")
    parser.add_argument("--all", action="store_true", help="the dropped models too (to show why)")
    parser.add_argument("--no-cube", action="store_true", help="skip the unit cube row")
    parser.add_argument("--cube-n", type=int, default=40, help="cube face grid: 2 n^2 triangles a face")
    parser.add_argument("--cube-size", type=float, default=0.033, help="certimesh --size for the cube "
                        "(0.033: about 10^6 tetrahedra by the point-set path of 2026-12-02)")
    parser.add_argument("--cube-volume", type=float, default=1.7e-6, help="TetGen -a for the cube "
                        "(1.7e-6: about 10^6 tetrahedra)")
    parser.add_argument("--no-cube-points", action="store_true",
                        help="skip the cube's point-set stand-in row")
    parser.add_argument("--describe", help="what certimesh is (default: its --version and commit)")
    args = parser.parse_args()
    tools = [t for t in args.tools.split(",") if t in TOOLS]
    load_before = provenance(args.certimesh)["load"]
    rows = []
    for source in read_sources():
        if not args.all and not source["status"].startswith("kept"):
            continue
        if args.only and not any(o in source["file"] for o in args.only):
            continue
        row = measure(source, args.certimesh, tools, args.timeout)
        rows.append(row)
        print(row["name"], row.get("skip", "") or " ".join(
            "%s:%s" % (t, "fail" if "error" in row.get(t, {}) else "ok") for t in tools),
            file=sys.stderr, flush=True)
    cube = None
    if not args.no_cube and (not args.only or any(o in "cube" for o in args.only)):
        cube = measure_cube(args.certimesh, tools, args.cube_n, args.cube_size, args.cube_volume, args.timeout,
                            not args.no_cube_points)
        print(cube["name"], file=sys.stderr, flush=True)
    info = provenance(args.certimesh)
    if args.describe:
        info["certimesh"] = args.describe
    command = "/usr/bin/python3 bench/surface_models.py " + shlex.join(sys.argv[1:])
    text = ("Run %s; certimesh %s; %s; %s; load average %s before, %s after; %s.\n\n"
            "```sh\n%s\n```\n\n" % (info["date"], info["certimesh"], info["gmsh"].replace("\n", " "),
                                  info["tetgen"], load_before, info["load"], info["machine"], command)
            + "Seconds are wall clock for the whole command (reading, meshing, writing; not the "
              "separate `certimesh check`), in parentheses its CPU time (user + system, from "
              "getrusage: what the shared machine's load changes least). c/t: certimesh over "
              "TetGen, CPU for time. \"surface kept\": the boundary faces are the input triangles, one for one, "
              "on bit-identical vertices.\n\n"
            + table(rows) + "\n" + cube_table(cube))
    planar_examples.publish(text, args.out)


if __name__ == "__main__":
    main()

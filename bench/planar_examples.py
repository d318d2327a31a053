#!/usr/bin/python3
"""Planar examples: Triangle's example files and Gmsh's 2D benchmarks, certimesh beside Gmsh.

For every input in bench/data/planar/ (see SOURCES.md there):
  certimesh  `certimesh mesh INPUT -o OUT.ele` with default options: wall time, triangles,
             `certimesh check OUT.node --domain DOMAIN` (certified yes/no), worst and mean
             quality, smallest angle;
  Gmsh       `gmsh -2` with its defaults on the same domain, the same measures.

Same domain:
  Triangle .poly  -> a .geo written here: Points, Lines, one Plane Surface per bounded face of
                     the segment arrangement that holds no hole point (Curve Loops for its outer
                     boundary and its holes), dangling segments `Curve{..} In Surface{..}`,
                     isolated vertices `Point{..} In Surface{..}`.
  Triangle .node  -> a point set: Gmsh has no equivalent, so its column is empty and the table
                     shows the Delaunay count 2n - h - 2 instead (h points on the hull boundary);
                     certimesh's mesh is checked against the convex hull computed here.
  Gmsh .geo       -> certimesh gets the .poly of Gmsh's own boundary discretization (its 1D mesh
                     of every curve that bounds or lies in a meshed surface, curved boundaries
                     hence as polygons), with a hole point in every face Gmsh leaves empty.

Quality is computed here, for both meshes with the same formula: the project's shape quality
12*sqrt(3)*area / perimeter^2 (topology/quality.h, monograph (2.1.3)), and the smallest angle.

Standard library only (and /usr/bin/python3); failures are reported, never fatal.
Usage:
  python3 bench/planar_examples.py --certimesh build/bin/certimesh \
      --out bench/results/planar_examples.md [--only NAME ...] [--timeout 120]
"""

import argparse
import datetime
import math
import os
import platform
import re
import shlex
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data", "planar")
SQRT3 = math.sqrt(3.0)


# ---------------------------------------------------------------------------------------------
# Reading files

def data_lines(path):
    """Non-empty lines of a Triangle file, comments (#...) removed, as lists of tokens."""
    with open(path) as f:
        for line in f:
            tokens = line.split("#", 1)[0].split()
            if tokens:
                yield tokens


def read_node(path):
    """Triangle .node: {index: (x, y)} and the first index."""
    rows = data_lines(path)
    header = next(rows)
    n = int(header[0])
    points = {}
    for _ in range(n):
        t = next(rows)
        points[int(t[0])] = (float(t[1]), float(t[2]))
    return points


def read_poly(path):
    """Triangle .poly: vertices {index: (x, y)}, segments [(a, b)], holes [(x, y)], regions."""
    rows = data_lines(path)
    header = next(rows)
    n = int(header[0])
    if n == 0:
        vertices = read_node(path[:-5] + ".node")
    else:
        vertices = {}
        for _ in range(n):
            t = next(rows)
            vertices[int(t[0])] = (float(t[1]), float(t[2]))
    ns = int(next(rows)[0])
    segments = []
    for _ in range(ns):
        t = next(rows)
        segments.append((int(t[1]), int(t[2])))
    holes = []
    t = next(rows, None)
    if t:
        for _ in range(int(t[0])):
            h = next(rows)
            holes.append((float(h[1]), float(h[2])))
    regions = []
    t = next(rows, None)
    if t:
        for _ in range(int(t[0])):
            regions.append(next(rows)[1:])
    return vertices, segments, holes, regions


def read_ele_mesh(node_path, ele_path):
    """Triangle .node/.ele: points {index: (x, y)}, triangles [(a, b, c)]."""
    points = read_node(node_path)
    rows = data_lines(ele_path)
    n = int(next(rows)[0])
    triangles = []
    for _ in range(n):
        t = next(rows)
        triangles.append((int(t[1]), int(t[2]), int(t[3])))
    return points, triangles


def read_msh22(path):
    """Gmsh MSH 2.2 ASCII: nodes {tag: (x, y, z)} and elements by type {type: [node tags]}."""
    nodes, elements = {}, {}
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if line == "$Nodes":
            for _ in range(int(next(lines))):
                t = next(lines).split()
                nodes[int(t[0])] = (float(t[1]), float(t[2]), float(t[3]))
        elif line == "$Elements":
            for _ in range(int(next(lines))):
                t = [int(v) for v in next(lines).split()]
                kind, ntags = t[1], t[2]
                elements.setdefault(kind, []).append(tuple(t[3 + ntags:]))
    return nodes, elements


# ---------------------------------------------------------------------------------------------
# Quality, computed here for every mesh with one formula

def triangle_measures(a, b, c):
    """(shape quality 12*sqrt(3)*area/perimeter^2, smallest angle in degrees, signed area)."""
    ab = math.dist(a, b)
    bc = math.dist(b, c)
    ca = math.dist(c, a)
    area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    perimeter = ab + bc + ca
    if perimeter == 0.0:
        return 0.0, 0.0, 0.0
    quality = 12.0 * SQRT3 * (abs(area2) / 2.0) / (perimeter * perimeter)

    def angle(opposite, s1, s2):  # law of cosines, clamped
        if s1 == 0.0 or s2 == 0.0:
            return 0.0
        cosine = (s1 * s1 + s2 * s2 - opposite * opposite) / (2.0 * s1 * s2)
        return math.degrees(math.acos(max(-1.0, min(1.0, cosine))))

    smallest = min(angle(bc, ab, ca), angle(ca, ab, bc), angle(ab, bc, ca))
    return quality, smallest, area2 / 2.0


def mesh_measures(points, triangles):
    worst, mean, min_angle, area = 1.0, 0.0, 180.0, 0.0
    for t in triangles:
        q, angle, signed_area = triangle_measures(points[t[0]], points[t[1]], points[t[2]])
        area += abs(signed_area)
        worst = min(worst, q)
        min_angle = min(min_angle, angle)
        mean += q
    mean = mean / len(triangles) if triangles else float("nan")
    return {"triangles": len(triangles), "worst": worst, "mean": mean, "min_angle": min_angle, "area": area}


# ---------------------------------------------------------------------------------------------
# Planar straight-line graphs: faces of the segment arrangement

def orient(a, b, c):
    """Exact sign of the orientation of three double points."""
    ax, ay = Fraction(a[0]), Fraction(a[1])
    d = (Fraction(b[0]) - ax) * (Fraction(c[1]) - ay) - (Fraction(b[1]) - ay) * (Fraction(c[0]) - ax)
    return (d > 0) - (d < 0)


def strictly_between(p, a, b):
    """p lies in the open segment ab (exactly)."""
    if orient(a, b, p) != 0 or p == a or p == b:
        return False
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def proper_crossing(a, b, c, d):
    return (orient(a, b, c) * orient(a, b, d) < 0) and (orient(c, d, a) * orient(c, d, b) < 0)


class Pslg:
    """Vertices (distinct points) and undirected segments between them, no crossings."""

    def __init__(self, points, segments):
        # Merge coincident vertices, drop repeated and zero-length segments.
        index_of, self.points, remap = {}, [], {}
        for key, p in points.items():
            if p not in index_of:
                index_of[p] = len(self.points)
                self.points.append(p)
            remap[key] = index_of[p]
        seen = set()
        self.segments = []
        for a, b in segments:
            a, b = remap[a], remap[b]
            if a != b and (min(a, b), max(a, b)) not in seen:
                seen.add((min(a, b), max(a, b)))
                self.segments.append((a, b))
        self.remap = remap
        self._split_at_vertices()

    def _split_at_vertices(self):
        """A vertex in the open interior of a segment splits it (Triangle does the same)."""
        result = []
        used = set(v for s in self.segments for v in s)
        for a, b in self.segments:
            pa, pb = self.points[a], self.points[b]
            lo = (min(pa[0], pb[0]), min(pa[1], pb[1]))
            hi = (max(pa[0], pb[0]), max(pa[1], pb[1]))
            inner = [v for v in used if v not in (a, b)
                     and lo[0] <= self.points[v][0] <= hi[0] and lo[1] <= self.points[v][1] <= hi[1]
                     and strictly_between(self.points[v], pa, pb)]
            inner.sort(key=lambda v: math.dist(pa, self.points[v]))
            chain = [a] + inner + [b]
            result.extend(zip(chain, chain[1:]))
        self.segments = list(dict.fromkeys((min(a, b), max(a, b)) for a, b in result))

    def crossing(self):
        """A pair of segments that cross in their interiors, or None (sweep over x-order)."""
        order = sorted(range(len(self.segments)),
                       key=lambda i: min(self.points[v][0] for v in self.segments[i]))
        active = []
        for i in order:
            a, b = self.segments[i]
            xmin = min(self.points[a][0], self.points[b][0])
            active = [j for j in active if max(self.points[v][0] for v in self.segments[j]) >= xmin]
            for j in active:
                c, d = self.segments[j]
                if len({a, b, c, d}) == 4 and proper_crossing(
                        self.points[a], self.points[b], self.points[c], self.points[d]):
                    return self.segments[i], self.segments[j]
            active.append(i)
        return None

    def cycles(self):
        """Closed walks around the faces, each face on the left; every half-edge once."""
        neighbours = {}
        for a, b in self.segments:
            neighbours.setdefault(a, []).append(b)
            neighbours.setdefault(b, []).append(a)
        for v, ns in neighbours.items():
            p = self.points[v]
            ns.sort(key=lambda w: math.atan2(self.points[w][1] - p[1], self.points[w][0] - p[0]))
        position = {(v, w): k for v, ns in neighbours.items() for k, w in enumerate(ns)}
        visited, cycles = set(), []
        for a, b in self.segments:
            for start in ((a, b), (b, a)):
                if start in visited:
                    continue
                walk, edge = [], start
                while edge not in visited:
                    visited.add(edge)
                    walk.append(edge)
                    u, v = edge
                    ns = neighbours[v]
                    edge = (v, ns[(position[(v, u)] - 1) % len(ns)])
                cycles.append(walk)
        return cycles

    def smallest_angle(self):
        """The smallest angle, in degrees, between two segments at a common vertex."""
        directions = {}
        for a, b in self.segments:
            for u, v in ((a, b), (b, a)):
                p, q = self.points[u], self.points[v]
                directions.setdefault(u, []).append(math.atan2(q[1] - p[1], q[0] - p[0]))
        smallest = 360.0
        for angles in directions.values():
            angles.sort()
            for k in range(len(angles)):
                gap = (angles[(k + 1) % len(angles)] - angles[k]) % (2 * math.pi)
                if len(angles) > 1:
                    smallest = min(smallest, math.degrees(gap))
        return smallest

    def components(self):
        """Connected component of every vertex on a segment (union-find)."""
        parent = {}

        def root(v):
            while parent.setdefault(v, v) != v:
                parent[v] = parent[parent[v]]
                v = parent[v]
            return v
        for a, b in self.segments:
            parent[root(a)] = root(b)
        return {v: root(v) for v in list(parent)}

    def area(self, walk):
        return 0.5 * sum(self.points[u][0] * self.points[v][1] - self.points[v][0] * self.points[u][1]
                         for u, v in walk)

    def inside(self, p, walk):
        """p strictly inside the closed walk (crossing parity; repeated edges cancel)."""
        crossings = 0
        for u, v in walk:
            (x1, y1), (x2, y2) = self.points[u], self.points[v]
            if (y1 > p[1]) != (y2 > p[1]):
                if x1 + (p[1] - y1) * (x2 - x1) / (y2 - y1) > p[0]:
                    crossings += 1
        return crossings % 2 == 1

    def faces(self):
        """Bounded faces: [(outer walk, [inner walks])], outer counter-clockwise."""
        cycles = self.cycles()
        component = self.components()
        outers = [c for c in cycles if self.area(c) > 0]
        faces = [(c, []) for c in outers]
        for c in cycles:
            if self.area(c) > 0:
                continue
            # The outer boundary of a connected component lies in a face of another component.
            p = self.points[c[0][0]]
            containing = [k for k, o in enumerate(outers)
                          if component[o[0][0]] != component[c[0][0]] and self.inside(p, o)]
            if containing:
                k = min(containing, key=lambda k: self.area(outers[k]))
                faces[k][1].append(c)
        return faces

    def in_face(self, p, face):
        outer, inners = face
        return self.inside(p, outer) and not any(self.inside(p, c) for c in inners)

    def face_of(self, p, faces):
        holding = [k for k, f in enumerate(faces) if self.in_face(p, f)]
        return min(holding, key=lambda k: self.area(faces[k][0])) if holding else None

    def interior_point(self, face):
        """A point strictly inside the face: the middle of the widest span of a scan line."""
        edges = [e for walk in [face[0]] + face[1] for e in walk]
        undirected = {}
        for u, v in edges:
            key = (min(u, v), max(u, v))
            undirected[key] = undirected.get(key, 0) + 1
        boundary = [e for e, count in undirected.items() if count == 1]
        ys = sorted(set(self.points[v][1] for e in boundary for v in e))
        gaps = sorted(((ys[i + 1] - ys[i], i) for i in range(len(ys) - 1)), reverse=True)
        for _, i in gaps[:8]:
            y = 0.5 * (ys[i] + ys[i + 1])
            xs = []
            for u, v in boundary:
                (x1, y1), (x2, y2) = self.points[u], self.points[v]
                if (y1 > y) != (y2 > y):
                    xs.append(x1 + (y - y1) * (x2 - x1) / (y2 - y1))
            xs.sort()
            spans = [(xs[k + 1] - xs[k], k) for k in range(0, len(xs) - 1, 2)]
            if spans:
                _, k = max(spans)
                p = (0.5 * (xs[k] + xs[k + 1]), y)
                if self.in_face(p, face):
                    return p
        return None


def simple_loops(walk):
    """Split a closed walk into simple loops: first drop edges walked both ways (dangling
    segments), then cut at repeated vertices (pinch vertices)."""
    directed = set(walk)
    kept = [e for e in walk if (e[1], e[0]) not in directed]
    loops, stack = [], []
    for u, v in kept:
        stack.append((u, v))
        starts = [k for k, e in enumerate(stack) if e[0] == v]
        if starts:
            k = starts[0]
            loops.append(stack[k:])
            del stack[k:]
    return loops


# ---------------------------------------------------------------------------------------------
# A Triangle .poly as a Gmsh .geo

def poly_domain(path):
    """The .poly's graph, its bounded faces and which of them are domain (not holes)."""
    vertices, segments, holes, _ = read_poly(path)
    graph = Pslg(vertices, segments)
    cross = graph.crossing()
    if cross:
        raise ValueError("segments %s and %s cross (not written as a .geo)" % cross)
    faces = graph.faces()
    hole_faces = set()
    for h in holes:
        k = graph.face_of(h, faces)
        if k is not None:
            hole_faces.add(k)
    domain = [k for k in range(len(faces)) if k not in hole_faces]
    return graph, faces, domain


def geo_of_poly(path, geo_path):
    """Write the .geo of a Triangle .poly; returns notes on what was embedded."""
    graph, faces, domain = poly_domain(path)
    notes = []
    out = ["// written by bench/planar_examples.py from %s" % os.path.basename(path)]
    for k, (x, y) in enumerate(graph.points):
        out.append("Point(%d) = {%r, %r, 0};" % (k + 1, x, y))
    line_id = {}
    for k, (a, b) in enumerate(graph.segments):
        line_id[(a, b)] = k + 1
        line_id[(b, a)] = -(k + 1)
        out.append("Line(%d) = {%d, %d};" % (k + 1, a + 1, b + 1))
    on_segment = set(v for s in graph.segments for v in s)
    isolated = [v for v in range(len(graph.points)) if v not in on_segment]
    loop_count, surface_count = 0, 0
    for k in domain:
        outer, inners = faces[k]
        loops = [l for walk in [outer] + inners for l in simple_loops(walk)]
        outers = [l for l in loops if graph.area(l) > 0]
        holes = [l for l in loops if graph.area(l) < 0]
        for o in outers:
            mine = [h for h in holes if graph.inside(graph.points[h[0][0]], o)]
            ids = []
            for l in [o] + mine:
                loop_count += 1
                out.append("Curve Loop(%d) = {%s};" % (loop_count, ", ".join(str(line_id[e]) for e in l)))
                ids.append(loop_count)
            surface_count += 1
            out.append("Plane Surface(%d) = {%s};" % (surface_count, ", ".join(map(str, ids))))
            walked = set(e for walk in [outer] + inners for e in walk)
            dangling = sorted(set(abs(line_id[e]) for e in walked if (e[1], e[0]) in walked))
            if dangling:
                out.append("Curve{%s} In Surface{%d};" % (", ".join(map(str, dangling)), surface_count))
                notes.append("%d dangling segments embedded" % len(dangling))
            inside = [v for v in isolated if graph.in_face(graph.points[v], faces[k])
                      and graph.inside(graph.points[v], o)]
            if inside:
                out.append("Point{%s} In Surface{%d};" % (", ".join(str(v + 1) for v in inside), surface_count))
                notes.append("%d isolated vertices embedded" % len(inside))
    with open(geo_path, "w") as f:
        f.write("\n".join(out) + "\n")
    return notes, graph.smallest_angle()


# ---------------------------------------------------------------------------------------------
# A Gmsh mesh's boundary as a Triangle .poly

def poly_of_gmsh_mesh(nodes, elements, poly_path):
    """The .poly of the curves Gmsh meshed inside or around its triangles, with hole points in
    the faces it left empty. Returns the number of hole points."""
    triangles = elements.get(2, [])
    triangle_edges = set()
    for t in triangles:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            triangle_edges.add((min(a, b), max(a, b)))
    segments = [(a, b) for a, b in (e[:2] for e in elements.get(1, []))
                if (min(a, b), max(a, b)) in triangle_edges]
    on_segment = set(v for s in segments for v in s)
    in_triangles = set(v for t in triangles for v in t)
    isolated = sorted(set(e[0] for e in elements.get(15, []))
                      & in_triangles - on_segment)
    used = sorted(on_segment | set(isolated))
    points = {v: nodes[v][:2] for v in used}
    graph = Pslg(points, segments)
    faces = graph.faces()
    holes, angle = [], graph.smallest_angle()
    for face in faces:
        p = graph.interior_point(face)
        if p is None:
            raise ValueError("no interior point found for a face")
        if not any(point_in_triangle(p, [nodes[v][:2] for v in t]) for t in triangles):
            holes.append(p)
    number = {v: k + 1 for k, v in enumerate(used)}
    with open(poly_path, "w") as f:
        f.write("# Gmsh's boundary discretization, written by bench/planar_examples.py\n")
        f.write("%d 2 0 0\n" % len(used))
        for v in used:
            f.write("%d %r %r\n" % (number[v], nodes[v][0], nodes[v][1]))
        f.write("%d 0\n" % len(segments))
        for k, (a, b) in enumerate(segments):
            f.write("%d %d %d\n" % (k + 1, number[a], number[b]))
        f.write("%d\n" % len(holes))
        for k, (x, y) in enumerate(holes):
            f.write("%d %r %r\n" % (k + 1, x, y))
    return len(holes), angle


def point_in_triangle(p, t):
    a, b, c = t
    d1 = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    d2 = (c[0] - b[0]) * (p[1] - b[1]) - (c[1] - b[1]) * (p[0] - b[0])
    d3 = (a[0] - c[0]) * (p[1] - c[1]) - (a[1] - c[1]) * (p[0] - c[0])
    return (d1 >= 0 and d2 >= 0 and d3 >= 0) or (d1 <= 0 and d2 <= 0 and d3 <= 0)


# ---------------------------------------------------------------------------------------------
# Point sets: convex hull, for the check and the Delaunay count

def hull(points):
    """Strict convex hull (monotone chain, exact orientation), counter-clockwise."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and orient(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and orient(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def on_hull_boundary(points, corners):
    ring = list(zip(corners, corners[1:] + corners[:1]))
    return sum(1 for p in set(points)
               if any(p == a or strictly_between(p, a, b) for a, b in ring))


def write_poly_with_hull(path, out):
    """The .poly with its convex hull added as segments: the domain of Triangle's -c."""
    vertices, segments, holes, _ = read_poly(path)
    keys = {p: k for k, p in vertices.items()}
    corners = hull(list(vertices.values()))
    # As Triangle's -c: every vertex on a hull edge splits it, and a hull piece that is already
    # a segment is not repeated (a repeated or overlapping segment is an invalid domain).
    present = set(frozenset(s) for s in segments)
    for a, b in zip(corners, corners[1:] + corners[:1]):
        inside = sorted((p for p in vertices.values() if strictly_between(p, a, b)),
                        key=lambda p: (p[0] - a[0]) ** 2 + (p[1] - a[1]) ** 2)
        chain = [keys[p] for p in [a] + inside + [b]]
        for u, w in zip(chain, chain[1:]):
            if frozenset((u, w)) not in present:
                segments.append((u, w))
                present.add(frozenset((u, w)))
    with open(out, "w") as f:
        f.write("# %s with its convex hull, written by bench/planar_examples.py\n" % os.path.basename(path))
        f.write("%d 2 0 0\n" % len(vertices))
        for k, (x, y) in vertices.items():
            f.write("%d %r %r\n" % (k, x, y))
        f.write("%d 0\n" % len(segments))
        for k, (a, b) in enumerate(segments):
            f.write("%d %d %d\n" % (k + 1, a, b))
        f.write("%d\n" % len(holes))
        for k, (x, y) in enumerate(holes):
            f.write("%d %r %r\n" % (k + 1, x, y))


def write_hull_poly(corners, path):
    with open(path, "w") as f:
        f.write("# convex hull, written by bench/planar_examples.py\n%d 2 0 0\n" % len(corners))
        for k, (x, y) in enumerate(corners):
            f.write("%d %r %r\n" % (k + 1, x, y))
        f.write("%d 0\n" % len(corners))
        for k in range(len(corners)):
            f.write("%d %d %d\n" % (k + 1, k + 1, (k + 1) % len(corners) + 1))
        f.write("0\n")


# ---------------------------------------------------------------------------------------------
# Running the tools

def run(command, timeout):
    start = time.perf_counter()
    try:
        r = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, timeout, "timeout: no answer after %g s" % timeout
    return r, time.perf_counter() - start, None


def first_error(r):
    for line in (r.stderr + "\n" + r.stdout).splitlines():
        if line.startswith("error:") or line.startswith("Error") or "invalid:" in line:
            return line.strip()
    if r.returncode < 0:
        return "killed by signal %d" % -r.returncode
    lines = (r.stderr or r.stdout).strip().splitlines()
    return "exit %d: %s" % (r.returncode, lines[-1] if lines else "")


def run_certimesh(certimesh, domain, check_domain, work, timeout, options=()):
    stem = os.path.join(work, "certimesh")
    result = {}
    r, seconds, failure = run([certimesh, "mesh", domain, "-o", stem + ".ele", "--quiet"] + list(options),
                              timeout)
    result["seconds"] = seconds
    if failure or r.returncode != 0:
        result["error"] = failure or first_error(r)
        return result
    points, triangles = read_ele_mesh(stem + ".node", stem + ".ele")
    result.update(mesh_measures(points, triangles))
    command = [certimesh, "check", stem + ".node"] + (["--domain", check_domain] if check_domain else [])
    r, _, failure = run(command, timeout)
    result["certified"] = bool(r) and r.returncode == 0
    if not result["certified"]:
        result["check_error"] = failure or first_error(r)
    return result


def run_gmsh(geo, work, timeout):
    """`gmsh -2` with the defaults; the mesh is saved whole (Mesh.SaveAll) in MSH 2.2 to be read
    here, which does not change how it is made."""
    out = os.path.join(work, "gmsh.msh")
    r, seconds, failure = run(["gmsh", "-2", geo, "-o", out, "-format", "msh22",
                               "-setnumber", "Mesh.SaveAll", "1"], timeout)
    result = {"seconds": seconds}
    if failure or r.returncode != 0 or not os.path.exists(out):
        result["error"] = failure or first_error(r)
        return result, None
    nodes, elements = read_msh22(out)
    others = sorted(k for k in elements if k not in (1, 2, 15))
    if others:
        result["error"] = "Gmsh made elements of types %s, not only triangles" % others
        return result, None
    if any(abs(z) > 0 for (_, _, z) in nodes.values()):
        result["error"] = "not planar (z != 0)"
        return result, None
    if not elements.get(2):
        result["error"] = "Gmsh made no triangles"
        return result, None
    points = {k: v[:2] for k, v in nodes.items()}
    result.update(mesh_measures(points, elements.get(2, [])))
    return result, (nodes, elements)


# ---------------------------------------------------------------------------------------------
# One input

# Inputs meshed a second time with options: Triangle's box.poly is an example of -c (its
# segments bound no face that is not a hole, so without -c its domain is empty).
VARIANTS = {"triangle/box.poly": [["--convex-hull"]]}


def inputs(only):
    """(path, certimesh options) for every input."""
    found = []
    for folder in ("triangle", "gmsh"):
        directory = os.path.join(DATA, folder)
        for name in sorted(os.listdir(directory)):
            if name.endswith((".poly", ".geo")) or (
                    name.endswith(".node") and not os.path.exists(os.path.join(directory, name[:-5] + ".poly"))):
                key = folder + "/" + name
                if not only or any(o in key for o in only):
                    found.append((os.path.join(directory, name), []))
                    found.extend((os.path.join(directory, name), v) for v in VARIANTS.get(key, []))
    # double_hex3.node is also the vertex list of double_hex3.poly: meshed as a point set too.
    extra = os.path.join(DATA, "triangle", "double_hex3.node")
    if os.path.exists(extra) and (not only or any(o in "triangle/double_hex3.node" for o in only)):
        found.append((extra, []))
    return found


def measure(path, options, certimesh, timeout):
    name = " ".join([os.path.relpath(path, DATA)] + options)
    row = {"name": name, "notes": []}
    with tempfile.TemporaryDirectory(prefix="planar-") as work:
        try:
            if path.endswith(".poly"):
                domain = path
                if "--convex-hull" in options:
                    domain = os.path.join(work, "with_hull.poly")
                    write_poly_with_hull(path, domain)
                geo = os.path.join(work, "domain.geo")
                try:
                    notes, row["input_angle"] = geo_of_poly(domain, geo)
                    row["notes"] += notes
                    row["gmsh"], _ = run_gmsh(geo, work, timeout)
                except ValueError as e:
                    row["gmsh"] = {"error": "no .geo: %s" % e}
                row["certimesh"] = run_certimesh(certimesh, path, domain, work, timeout, options)
            elif path.endswith(".node"):
                pts = list(read_node(path).values())
                corners = hull(pts)
                row["delaunay"] = 2 * len(set(pts)) - on_hull_boundary(pts, corners) - 2
                hull_poly = os.path.join(work, "hull.poly")
                write_hull_poly(corners, hull_poly)
                row["certimesh"] = run_certimesh(certimesh, path, hull_poly, work, timeout)
                row["gmsh"] = {"error": "a point set: no Gmsh input; Delaunay count %d" % row["delaunay"]}
            else:
                row["gmsh"], mesh = run_gmsh(path, work, timeout)
                if mesh is None:
                    row["certimesh"] = {"error": "no domain (Gmsh did not mesh it)"}
                else:
                    poly = os.path.join(work, "gmsh_boundary.poly")
                    holes, angle = poly_of_gmsh_mesh(mesh[0], mesh[1], poly)
                    row["input_angle"] = angle
                    if holes:
                        row["notes"].append("%d hole points" % holes)
                    row["certimesh"] = run_certimesh(certimesh, poly, poly, work, timeout)
        except Exception as e:  # a harness failure is reported in the row, never fatal
            row.setdefault("certimesh", {})["error"] = "harness: %s: %s" % (type(e).__name__, e)
            row.setdefault("gmsh", {})
    return row


# ---------------------------------------------------------------------------------------------
# The table

def verdict(row, time_limit):
    c, g = row["certimesh"], row["gmsh"]
    if "the domain is empty" in c.get("error", "") and g.get("error") == "Gmsh made no triangles":
        return "n/a: empty domain (Gmsh makes no triangles either)"  # box.poly without -c
    if "error" in c:
        return "fail: error"
    reasons = []
    if c["seconds"] >= time_limit:
        reasons.append("time")
    if not c.get("certified"):
        reasons.append("not certified")
    # Both qualities are computed here by one formula in double; the same triangle written with
    # its vertices in another order may differ in the last bits, hence the relative 1e-9.
    if "worst" in g and c["worst"] < g["worst"] * (1 - 1e-9):
        reasons.append("worst q")
    if "delaunay" in row and c["triangles"] != row["delaunay"]:
        reasons.append("count")
    return "fail: " + ", ".join(reasons) if reasons else "pass"


def without_paths(message):
    """Error messages name files by their path; the table names them relative to the data."""
    message = message.replace(DATA + os.sep, "")
    return re.sub(r"\S*planar-[^/\s]*/", "", message).replace("|", "\\|")


def cell(d, key, fmt):
    return fmt % d[key] if key in d else ""


def table(rows, time_limit):
    head = ("| input | input angle ° | certimesh s | triangles | certified | worst q | min angle ° "
            "| gmsh s | triangles | worst q | min angle ° | worst q ratio | verdict |")
    out = [head, "|" + "---|" * 13]
    for row in rows:
        c, g = row["certimesh"], row["gmsh"]
        ratio = "%.2f" % (c["worst"] / g["worst"]) if "worst" in c and "worst" in g and g["worst"] > 0 else ""
        certified = ("yes" if c.get("certified") else "no") if "certified" in c else ""
        gcount = cell(g, "triangles", "%d") if "triangles" in g else (
            "(Delaunay %d)" % row["delaunay"] if "delaunay" in row else "")
        out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            row["name"], cell(row, "input_angle", "%.1f"), cell(c, "seconds", "%.2f"), cell(c, "triangles", "%d"), certified,
            cell(c, "worst", "%.3f"), cell(c, "min_angle", "%.1f"),
            cell(g, "seconds", "%.2f") if "triangles" in g else "", gcount,
            cell(g, "worst", "%.3f"), cell(g, "min_angle", "%.1f"), ratio,
            verdict(row, time_limit)))
    notes = []
    for row in rows:
        c, g = row["certimesh"], row["gmsh"]
        for label, d in (("certimesh", c), ("gmsh", g)):
            if "error" in d:
                notes.append("- `%s` %s: %s" % (row["name"], label, without_paths(d["error"])))
        if "check_error" in c:
            notes.append("- `%s` certimesh check: %s" % (row["name"], without_paths(c["check_error"])))
        if "area" in c and "area" in g and abs(c["area"] - g["area"]) > 1e-9 * max(c["area"], g["area"]):
            notes.append("- `%s`: the meshes cover different areas: certimesh %.12g, Gmsh %.12g"
                         % (row["name"], c["area"], g["area"]))
        if row["notes"]:
            notes.append("- `%s`: %s" % (row["name"], "; ".join(row["notes"])))
    passed = sum(1 for row in rows if verdict(row, time_limit) == "pass")
    empty = sum(1 for row in rows if verdict(row, time_limit).startswith("n/a"))
    summary = "%d of %d inputs pass (< %g s, certified, worst quality >= Gmsh's)%s." % (
        passed, len(rows) - empty, time_limit, "; %d more with an empty domain for both tools" % empty if empty else "")
    return "\n".join(out) + "\n\n" + summary + "\n\nErrors and notes:\n\n" + "\n".join(notes) + "\n"


def provenance(certimesh):
    def output(command):
        try:
            r = subprocess.run(command, capture_output=True, text=True, timeout=30)
            return (r.stdout + r.stderr).strip()
        except (OSError, subprocess.SubprocessError):
            return "?"
    source = os.path.dirname(os.path.abspath(certimesh))
    while source != "/" and not os.path.exists(os.path.join(source, ".git")):
        source = os.path.dirname(source)
    commit = output(["git", "-C", source, "log", "-1", "--format=%h %cd", "--date=iso"])
    dirty = output(["git", "-C", source, "status", "--porcelain", "--untracked-files=no"])
    return {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "certimesh": "%s (%s%s)" % (output([certimesh, "--version"]), commit,
                                    ", modified working tree" if dirty else ""),
        "gmsh": "gmsh " + output(["gmsh", "--version"]),
        "load": " ".join(open("/proc/loadavg").read().split()[:3]) if os.path.exists("/proc/loadavg") else "?",
        "machine": "%s, %d cores" % (platform.processor() or platform.machine(), os.cpu_count() or 0),
    }


def publish(text, out):
    """Print the report, and write it to `out` too when given."""
    print(text)
    if out:
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        with open(out, "w") as f:
            f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--certimesh", default="build/bin/certimesh")
    parser.add_argument("--out", help="write the Markdown table here (default: stdout only)")
    parser.add_argument("--only", nargs="*", help="inputs whose name contains one of these")
    parser.add_argument("--timeout", type=float, default=120.0, help="per command, seconds")
    parser.add_argument("--describe", help="what certimesh is (default: its --version and the git "
                        "commit of the checkout holding the binary)")
    parser.add_argument("--time-limit", type=float, default=2.0, help="the issue's bound, seconds")
    args = parser.parse_args()
    rows = []
    load_before = provenance(args.certimesh)["load"]
    for path, options in inputs(args.only):
        row = measure(path, options, args.certimesh, args.timeout)
        rows.append(row)
        print(row["name"], verdict(row, args.time_limit), file=sys.stderr, flush=True)
    info = provenance(args.certimesh)
    if args.describe:
        info["certimesh"] = args.describe
    command = "python3 bench/planar_examples.py " + shlex.join(sys.argv[1:])
    text = ("Run %s; certimesh %s; %s; load average %s before, %s after; %s.\n\n"
            "```sh\n%s\n```\n\n" % (info["date"], info["certimesh"], info["gmsh"].replace("\n", " "),
                                  load_before, info["load"], info["machine"], command)
            + table(rows, args.time_limit))
    publish(text, args.out)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes the certificate's fixed corpus (tests/certificate/corpus/*.mesh, *.poly, MANIFEST.tsv).

Run from this folder: `python3 make_corpus.py`. The cases are small, unjittered (so every
coordinate is an exact small dyadic and every sign is obvious by hand) and each breaks
exactly one condition; ../README.md says why each expected defect is the first one in
defect.h's order. Nothing here uses certimesh: it is plain Python, so the expected outcomes
are not produced by the code under test.
"""
import math

ROWS = []  # (file, domain, exit code, defect(s), elements)


# ---- meshes as plain lists: points (tuples), elements (0-based vertex tuples) ----

def kuhn_2d(nx, ny):
    pts = [(float(i), float(j)) for j in range(ny + 1) for i in range(nx + 1)]
    vid = lambda i, j: j * (nx + 1) + i
    tris = []
    for j in range(ny):
        for i in range(nx):
            tris += [(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)), (vid(i, j), vid(i + 1, j + 1), vid(i, j + 1))]
    return pts, tris


AXIS_ORDERS = [(0, 1, 2), (1, 2, 0), (2, 0, 1), (0, 2, 1), (2, 1, 0), (1, 0, 2)]  # last 3 odd


def kuhn_3d(n, skip=lambda i, j, k: False):
    pts = [(float(i), float(j), float(k)) for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
    vid = lambda a: (a[2] * (n + 1) + a[1]) * (n + 1) + a[0]
    tets = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                if skip(i, j, k):
                    continue
                for o, order in enumerate(AXIS_ORDERS):
                    at = [i, j, k]
                    tet = [vid(at)]
                    for axis in order:
                        at[axis] += 1
                        tet.append(vid(at))
                    if o >= 3:
                        tet[2], tet[3] = tet[3], tet[2]
                    tets.append(tuple(tet))
    return compact(pts, tets)


def compact(pts, elements):
    used = sorted({v for e in elements for v in e})
    new = {v: i for i, v in enumerate(used)}
    return [pts[v] for v in used], [tuple(new[v] for v in e) for e in elements]


def without_cells_2d(nx, ny, removed):
    pts, tris = kuhn_2d(nx, ny)
    keep = [t for c, t in enumerate(tris) if (c // 2 % nx, c // 2 // nx) not in removed]
    return compact(pts, keep)


def num(x):
    x = float(x)
    return str(int(x)) if x == int(x) and abs(x) < 2 ** 53 else repr(x)


def write_medit(name, pts, elements=(), surface=()):
    dim = len(pts[0]) if pts else 2
    out = ["MeshVersionFormatted 2", "", f"Dimension {dim}", "", "Vertices", str(len(pts))]
    out += [" ".join(num(c) for c in p) + " 0" for p in pts]
    tris = surface if dim == 3 else elements
    if dim == 2 or surface:
        out += ["", "Triangles", str(len(tris))] + [" ".join(str(v + 1) for v in t) + " 0" for t in tris]
    if dim == 3 and not surface:
        out += ["", "Tetrahedra", str(len(elements))] + [" ".join(str(v + 1) for v in t) + " 0" for t in elements]
    out += ["", "End", ""]
    with open(name, "w") as f:
        f.write("\n".join(out))


def write_poly(name, pts, segments, holes=()):
    out = [f"{len(pts)} 2 0 0"] + [f"{i + 1} {num(x)} {num(y)}" for i, (x, y) in enumerate(pts)]
    out += [f"{len(segments)} 0"] + [f"{i + 1} {a + 1} {b + 1}" for i, (a, b) in enumerate(segments)]
    out += [str(len(holes))] + [f"{i + 1} {num(x)} {num(y)}" for i, (x, y) in enumerate(holes)]
    with open(name, "w") as f:
        f.write("\n".join(out) + "\n")


def case(file, domain, code, defect, elements):
    ROWS.append((file, domain or "-", code, defect, elements))


def squares_poly(squares):
    pts, segs = [], []
    for (x0, y0, x1, y1) in squares:
        b = len(pts)
        pts += [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        segs += [(b + s, b + (s + 1) % 4) for s in range(4)]
    return pts, segs


def box_surface(lo, hi, inward=False, base=0):
    pts = [tuple(hi if (c >> a) & 1 else lo for a in range(3)) for c in range(8)]
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = []
    for q in faces:
        for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            t = (t[0], t[2], t[1]) if inward else t
            tris.append(tuple(base + v for v in t))
    return pts, tris


def facets(elements):
    """facet (sorted) -> list of elements"""
    table = {}
    for e, s in enumerate(elements):
        for o in range(len(s)):
            table.setdefault(tuple(sorted(s[:o] + s[o + 1:])), []).append(e)
    return table


def boundary_vertices(elements):
    return {v for f, owners in facets(elements).items() if len(owners) == 1 for v in f}


def main():
    # ---- domains ----
    write_poly("square4.poly", *squares_poly([(0, 0, 4, 4)]))
    p, s = squares_poly([(0, 0, 4, 4), (1, 1, 3, 3)])
    write_poly("square4_hole.poly", p, s, [(2, 2)])
    write_poly("square4_inner_region.poly", p, s)
    write_poly("two_squares.poly", *squares_poly([(0, 0, 4, 4), (5, 5, 6, 6)]))
    write_poly("bowtie.poly", [(0, 0), (4, 0), (0, 4), (4, 4)], [(0, 1), (1, 2), (2, 3), (3, 0)])
    cube_pts, cube_tris = box_surface(0, 2)
    write_medit("cube2_surface.mesh", cube_pts, surface=cube_tris)
    write_medit("cube2_surface_open.mesh", cube_pts, surface=cube_tris[:-1])
    q, t = box_surface(3, 4, base=8)
    write_medit("two_cubes_surface.mesh", cube_pts + q, surface=cube_tris + t)
    cube4_pts, cube4_tris = box_surface(0, 4)
    q, t = box_surface(1, 3, inward=True, base=8)
    write_medit("cube4_with_inner_box.mesh", cube4_pts + q, surface=cube4_tris + t)
    q, t = box_surface(1, 3, inward=False, base=8)
    write_medit("cube4_with_inner_box_outward.mesh", cube4_pts + q, surface=cube4_tris + t)

    # ---- valid ----
    pts, tris = kuhn_2d(4, 4)
    write_medit("valid_square4_2d.mesh", pts, tris)
    case("valid_square4_2d.mesh", None, 0, "none", 32)
    case("valid_square4_2d.mesh", "square4.poly", 0, "none", 32)
    hp, ht = without_cells_2d(4, 4, {(1, 1), (2, 1), (1, 2), (2, 2)})
    write_medit("valid_square4_hole_2d.mesh", hp, ht)
    case("valid_square4_hole_2d.mesh", None, 0, "none", 24)
    case("valid_square4_hole_2d.mesh", "square4_hole.poly", 0, "none", 24)
    write_medit("valid_triangle_2d.mesh", [(0, 0), (1, 0), (0, 1)], [(0, 1, 2)])
    case("valid_triangle_2d.mesh", None, 0, "none", 1)
    cp, ct = kuhn_3d(2)
    write_medit("valid_cube2_3d.mesh", cp, ct)
    case("valid_cube2_3d.mesh", None, 0, "none", 48)
    case("valid_cube2_3d.mesh", "cube2_surface.mesh", 0, "none", 48)
    write_medit("valid_tetrahedron_3d.mesh", [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [(0, 1, 2, 3)])
    case("valid_tetrahedron_3d.mesh", None, 0, "none", 1)

    # Exact maps: the same valid meshes and domains scaled by 2^600 (squared coordinates
    # overflow) and 2^-1000 (products underflow to subnormals or zero). Still valid.
    for e in (600, -1000):
        tag = "huge" if e > 0 else "tiny"
        sp = lambda pts: [tuple(math.ldexp(x, e) for x in p) for p in pts]
        write_medit(f"valid_square4_{tag}_2d.mesh", sp(pts), tris)
        write_poly(f"square4_{tag}.poly", *(lambda p, s: (sp(p), s))(*squares_poly([(0, 0, 4, 4)])))
        case(f"valid_square4_{tag}_2d.mesh", f"square4_{tag}.poly", 0, "none", 32)
        write_medit(f"valid_cube2_{tag}_3d.mesh", sp(cp), ct)
        write_medit(f"cube2_{tag}_surface.mesh", sp(cube_pts), surface=cube_tris)
        case(f"valid_cube2_{tag}_3d.mesh", f"cube2_{tag}_surface.mesh", 0, "none", 48)

    # ---- input defects ----
    write_medit("no_elements_2d.mesh", [(0, 0), (1, 0), (0, 1)], [])
    case("no_elements_2d.mesh", None, 1, "no_elements", 0)
    write_medit("no_elements_3d.mesh", [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [])
    case("no_elements_3d.mesh", None, 1, "no_elements", 0)
    # Two triangles of the unit square, the second naming a copy of vertex 2.
    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    write_medit("duplicate_vertex_2d.mesh", sq + [(1, 1)], [(0, 1, 2), (0, 4, 3)])
    case("duplicate_vertex_2d.mesh", None, 1, "duplicate_vertex", 2)
    tet2 = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 0, -1)]
    write_medit("duplicate_vertex_3d.mesh", tet2 + [(0, 0, 0)], [(0, 1, 2, 3), (5, 2, 1, 4)])
    case("duplicate_vertex_3d.mesh", None, 1, "duplicate_vertex", 2)
    write_medit("unused_vertex_2d.mesh", sq + [(5, 5)], [(0, 1, 2), (0, 2, 3)])
    case("unused_vertex_2d.mesh", None, 1, "unused_vertex", 2)
    write_medit("unused_vertex_3d.mesh", tet2 + [(5, 5, 5)], [(0, 1, 2, 3), (0, 2, 1, 4)])
    case("unused_vertex_3d.mesh", None, 1, "unused_vertex", 2)
    write_medit("repeated_vertex_2d.mesh", sq, [(0, 1, 2), (0, 2, 3), (1, 1, 3)])
    case("repeated_vertex_2d.mesh", None, 1, "repeated_vertex", 3)
    write_medit("repeated_vertex_3d.mesh", tet2, [(0, 1, 2, 3), (0, 2, 1, 4), (1, 1, 3, 4)])
    case("repeated_vertex_3d.mesh", None, 1, "repeated_vertex", 3)
    write_medit("duplicate_element_2d.mesh", sq, [(0, 1, 2), (0, 2, 3), (2, 0, 1)])
    case("duplicate_element_2d.mesh", None, 1, "duplicate_element", 3)
    write_medit("duplicate_element_3d.mesh", tet2, [(0, 1, 2, 3), (0, 2, 1, 4), (1, 2, 3, 0)])
    case("duplicate_element_3d.mesh", None, 1, "duplicate_element", 3)

    # ---- combinatorial ----
    # Three triangles on edge (0,2) of the unit square: the third reaches to (2,0.5).
    write_medit("non_manifold_facet_2d.mesh", sq + [(2, 0.5)], [(0, 1, 2), (0, 2, 3), (2, 0, 4)])
    case("non_manifold_facet_2d.mesh", None, 1, "non_manifold_facet", 3)
    write_medit("non_manifold_facet_3d.mesh", tet2 + [(1, 1, 1)], [(0, 1, 2, 3), (0, 2, 1, 4), (0, 1, 2, 5)])
    case("non_manifold_facet_3d.mesh", None, 1, "non_manifold_facet", 3)
    write_medit("inconsistent_orientation_2d.mesh", sq, [(0, 1, 2), (0, 3, 2)])
    case("inconsistent_orientation_2d.mesh", None, 1, "inconsistent_orientation", 2)
    write_medit("inconsistent_orientation_3d.mesh", tet2, [(0, 1, 2, 3), (0, 1, 2, 4)])
    case("inconsistent_orientation_3d.mesh", None, 1, "inconsistent_orientation", 2)

    # ---- geometric ----
    # Flat: vertex 4 of the 2x2 grid (the centre) moved onto the midpoint of edge (1,1)-(2,1)... of
    # triangle (4, 5, 8): centre (1,1) -> (2, 1.5) lies on edge (2,1)-(2,2).
    fp, ft = kuhn_2d(2, 2)
    fp = list(fp)
    fp[4] = (2.0, 1.5)
    write_medit("flat_element_2d.mesh", fp, ft)
    case("flat_element_2d.mesh", None, 1, "flat_element", 8)
    write_medit("flat_element_3d.mesh", [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)], [(0, 1, 2, 3)])
    case("flat_element_3d.mesh", None, 1, "flat_element", 1)
    write_medit("inverted_element_2d.mesh", sq, [(0, 2, 1), (0, 3, 2)])
    case("inverted_element_2d.mesh", None, 1, "inverted_element", 2)
    write_medit("inverted_element_3d.mesh", tet2, [(0, 2, 1, 3), (0, 1, 2, 4)])
    case("inverted_element_3d.mesh", None, 1, "inverted_element", 2)
    # Two triangles (tetrahedra) sharing only a vertex: a pinch, valid (design decision 8), alone
    # and against the domain of the two triangles (segments sharing the vertex).
    write_medit("pinch_vertex_2d.mesh", [(0, 0), (1, 0), (0, 1), (-1, 0), (0, -1)], [(0, 1, 2), (0, 3, 4)])
    case("pinch_vertex_2d.mesh", None, 0, "none", 2)
    write_poly("pinch_vertex.poly", [(0, 0), (1, 0), (0, 1), (-1, 0), (0, -1)], [(0, 1), (1, 2), (2, 0), (0, 3), (3, 4), (4, 0)])
    case("pinch_vertex_2d.mesh", "pinch_vertex.poly", 0, "none", 2)
    write_medit("pinch_vertex_3d.mesh",
                [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0), (0, -1, 0), (0, 0, -1)],
                [(0, 1, 2, 3), (0, 5, 4, 6)])
    case("pinch_vertex_3d.mesh", None, 0, "none", 2)
    # A triangle inside another sharing a corner (the boundary edges there leave, leave, enter,
    # enter), and a tetrahedron inside another sharing an edge (the four boundary triangles
    # around it do not alternate): the elements cover a region twice.
    write_medit("non_manifold_boundary_2d.mesh", [(0, 0), (4, 0), (0, 4), (2, 1), (1, 2)], [(0, 1, 2), (0, 3, 4)])
    case("non_manifold_boundary_2d.mesh", None, 1, "non_manifold_boundary", 2)
    write_medit("non_manifold_boundary_3d.mesh",
                [(0, 0, 0), (4, 0, 0), (0, 4, 0), (0, 0, 4), (1, 1, 0.5), (1, 0.5, 1)],
                [(0, 1, 2, 3), (0, 1, 4, 5)])
    case("non_manifold_boundary_3d.mesh", None, 1, "non_manifold_boundary", 2)
    # T-junction: in the 4x4 grid, the edge (1,1)-(2,1) is split at (1.5,1) in the triangle above
    # it only; all its vertices are interior, so the boundary stays a manifold.
    tp, tt = kuhn_2d(4, 4)
    tp = list(tp)
    a, b = 1 * 5 + 1, 1 * 5 + 2  # (1,1), (2,1)
    tp.append((1.5, 1.0))
    m = len(tp) - 1
    above = [i for i, t in enumerate(tt) if a in t and b in t and any(tp[v][1] > 1 for v in t)][0]
    t0 = tt[above]
    k = [i for i in range(3) if t0[i] not in (a, b)][0]
    parts = [tuple(m if i == j else t0[i] for i in range(3)) for j in range(3) if j != k]
    tt = tt[:above] + [parts[0]] + tt[above + 1:] + [parts[1]]
    write_medit("t_junction_2d.mesh", tp, tt)
    case("t_junction_2d.mesh", None, 1, "t_junction", 33)
    # 3D: the 4^3 grid's facet between two tetrahedra of cube (1,1,1) split on one side.
    gp, gt = kuhn_3d(4)
    gp = list(gp)
    bnd = boundary_vertices(gt)
    table = facets(gt)
    chosen = next(f for f, o in sorted(table.items()) if len(o) == 2 and not (set(f) & bnd))
    e = table[chosen][0]
    s0 = gt[e]
    pa, pb, pc = (gp[v] for v in chosen)
    gp.append(tuple((pa[c] + pb[c] + 2 * pc[c]) / 4 for c in range(3)))
    m = len(gp) - 1
    parts = [tuple(m if s0[i] == v else s0[i] for i in range(4)) for v in chosen]
    gt = gt[:e] + [parts[0]] + gt[e + 1:] + parts[1:]
    write_medit("t_junction_3d.mesh", gp, gt)
    case("t_junction_3d.mesh", None, 1, "t_junction", 386)
    # The classic T-junction between two squares glued along x = 1, the right one split at
    # (1, 0.5): the junction's facet ends on the outer boundary, so the boundary passes twice
    # through (1,0) and (1,1), with two boundary edges leaving (1,0) upward along x = 1: the
    # vertex (1, 0.5) lies on the boundary edge (1,0)-(1,1) (README).
    write_medit("t_junction_on_boundary_2d.mesh",
                [(0, 0), (1, 0), (1, 1), (0, 1), (2, 0), (2, 1), (1, 0.5)],
                [(0, 1, 2), (0, 2, 3), (1, 4, 6), (6, 4, 5), (6, 5, 2)])
    case("t_junction_on_boundary_2d.mesh", None, 1, "t_junction", 5)
    # Branched double cover: 7 triangles (tetrahedra) around a centre (axis), ring winding twice.
    ring = [(round(1000 * math.cos(4 * math.pi * k / 7)), round(1000 * math.sin(4 * math.pi * k / 7))) for k in range(7)]
    write_medit("boundary_intersection_2d.mesh", ring + [(0, 0)], [(7, k, (k + 1) % 7) for k in range(7)])
    case("boundary_intersection_2d.mesh", None, 1, "boundary_intersection", 7)
    write_medit("boundary_intersection_3d.mesh", [(x, y, 0) for x, y in ring] + [(0, 0, -1000), (0, 0, 1000)],
                [(7, 8, k, (k + 1) % 7) for k in range(7)])
    case("boundary_intersection_3d.mesh", None, 1, "boundary_intersection", 7)
    # Multiple cover: the grid plus a copy scaled by 1/2 about its centre, moved by 2^-12.
    for dim, (p0, e0), n, dom in ((2, kuhn_2d(4, 4), 4, "square4.poly"), (3, kuhn_3d(2), 2, "cube2_surface.mesh")):
        c = n / 2
        copy = [tuple(c + (x - c) / 2 + 2 ** -12 for x in p) for p in p0]
        el = e0 + [tuple(v + len(p0) for v in t) for t in e0]
        write_medit(f"multiple_cover_{dim}d.mesh", p0 + copy, el)
        case(f"multiple_cover_{dim}d.mesh", None, 1, "multiple_cover", len(el))
        case(f"multiple_cover_{dim}d.mesh", dom, 1, "multiple_cover", len(el))

    # ---- against the domain ----
    case("valid_square4_2d.mesh", "bowtie.poly", 1, "invalid_domain", 32)
    case("valid_cube2_3d.mesh", "cube2_surface_open.mesh", 1, "invalid_domain", 48)
    # A corner triangle removed: its diagonal is now a boundary facet inside the square.
    rp, rt = kuhn_2d(4, 4)
    write_medit("facet_off_domain_2d.mesh", rp, rt[1:])
    # Its vertex (1,1) is now a boundary vertex off the domain: vertex_off (defect.h).
    case("facet_off_domain_2d.mesh", "square4.poly", 1, "vertex_off_domain_boundary", 31)
    case("facet_off_domain_2d.mesh", None, 0, "none", 31)
    rp, rt = kuhn_3d(2)
    write_medit("facet_off_domain_3d.mesh", rp, rt[1:])
    case("facet_off_domain_3d.mesh", "cube2_surface.mesh", 1, "vertex_off_domain_boundary", 47)
    # Corner cut: the elements of the corner (4,0) / (2,0,0) and that vertex removed. Every
    # boundary vertex is still on the domain boundary; the new facets cross the corner.
    cp2, ct2 = kuhn_2d(4, 4)
    ct2 = [t for t in ct2 if 4 not in t]
    cp2, ct2 = compact(cp2, ct2)
    write_medit("corner_cut_2d.mesh", cp2, ct2)
    case("corner_cut_2d.mesh", "square4.poly", 1, "facet_off_domain_boundary", 31)
    cp3, ct3 = kuhn_3d(2)
    ct3 = [t for t in ct3 if 2 not in t]
    cp3, ct3 = compact(cp3, ct3)
    write_medit("corner_cut_3d.mesh", cp3, ct3)
    case("corner_cut_3d.mesh", "cube2_surface.mesh", 1, "facet_off_domain_boundary", 46)
    # A boundary vertex (2,0) of the 4x4 grid moved to (2,-1/256): the bottom segment is split
    # at a point off it.
    op, ot = kuhn_2d(4, 4)
    op = list(op)
    op[2] = (2.0, -1 / 256)
    write_medit("vertex_off_domain_2d.mesh", op, ot)
    case("vertex_off_domain_2d.mesh", "square4.poly", 1, "vertex_off_domain_boundary", 32)
    op, ot = kuhn_3d(2)
    op = list(op)
    op[4] = (1.0, 1.0, -1 / 256)  # the centre of the bottom face
    write_medit("vertex_off_domain_3d.mesh", op, ot)
    case("vertex_off_domain_3d.mesh", "cube2_surface.mesh", 1, "vertex_off_domain_boundary", 48)
    case("valid_square4_2d.mesh", "two_squares.poly", 1, "domain_boundary_not_covered", 32)
    case("valid_cube2_3d.mesh", "two_cubes_surface.mesh", 1, "domain_boundary_not_covered", 48)
    case("valid_square4_2d.mesh", "square4_hole.poly", 1, "hole_covered", 32)
    case("valid_square4_hole_2d.mesh", "square4_inner_region.poly", 1, "region_not_meshed", 24)
    hp3, ht3 = kuhn_3d(4, skip=lambda i, j, k: 1 <= i < 3 and 1 <= j < 3 and 1 <= k < 3)
    write_medit("cube4_cavity_3d.mesh", hp3, ht3)
    # decision 8: an inner shell oriented inward bounds a cavity (no hole point needed); one
    # oriented like the outer shell has winding number 2 inside: solid, so left empty it is
    # a region not meshed
    case("cube4_cavity_3d.mesh", "cube4_with_inner_box.mesh", 0, "none", 336)
    case("cube4_cavity_3d.mesh", "cube4_with_inner_box_outward.mesh", 1, "region_not_meshed", 336)
    case("cube4_cavity_3d.mesh", None, 0, "none", 336)

    # ---- unreadable (exit 2) ----
    with open("unreadable_truncated.mesh", "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n")
    case("unreadable_truncated.mesh", None, 2, "-", 0)
    with open("unreadable_nan.mesh", "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\nnan 0 0\n0 1 0\nTriangles\n1\n1 2 3 0\nEnd\n")
    case("unreadable_nan.mesh", None, 2, "-", 0)
    with open("unreadable_index.mesh", "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n1\n1 2 4 0\nEnd\n")
    case("unreadable_index.mesh", None, 2, "-", 0)
    with open("unreadable_huge_count.mesh", "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 3\nVertices\n1000000000\n0 0 0 0\nEnd\n")
    case("unreadable_huge_count.mesh", None, 2, "-", 0)
    with open("unreadable_garbage.mesh", "w") as f:
        f.write("this is not a mesh\n")
    case("unreadable_garbage.mesh", None, 2, "-", 0)
    case("does_not_exist.mesh", None, 2, "-", 0)
    case("valid_square4_2d.mesh", "does_not_exist.poly", 2, "-", 0)

    with open("MANIFEST.tsv", "w") as f:
        f.write("# file\tdomain\texit\tdefect\telements   (written by make_corpus.py; see ../README.md)\n")
        for r in ROWS:
            f.write("\t".join(str(x) for x in r) + "\n")


if __name__ == "__main__":
    main()

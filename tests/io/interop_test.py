#!/usr/bin/python3
"""Interoperability of certimesh's mesh files with Gmsh and meshio (issue 4).

    interop_test.py gmsh_reads_certimesh   CERTIMESH WORKDIR
    interop_test.py certimesh_reads_gmsh   CERTIMESH WORKDIR GEO_DIR
    interop_test.py meshio_reads_certimesh CERTIMESH WORKDIR
    interop_test.py certimesh_reads_meshio CERTIMESH WORKDIR

Each builds its meshes here (independently of certimesh), runs `certimesh convert` and the
other tool, and compares what each side read. The script reads certimesh's ASCII .vtu output
with Python's own XML parser, so the comparison never trusts certimesh's reader to check
itself. Exit 0 pass, 1 fail, 77 skipped (the tool is not installed; CTest SKIP_RETURN_CODE).

Gmsh 4.8.4 writes coordinates with 16 significant digits (%.16g), not always enough for a
double to round-trip: after a Gmsh re-save a coordinate is checked to within
|x' - x| <= 6.2e-16 |x| (half a unit in the 16th digit, 5e-16 |x|, plus the half-ulp rounding
when the decimal is read back), and the script reports how many came back bit for bit.
Every other comparison is exact.
"""
import collections
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

SKIP = 77
VTK_TYPES = {3: "line", 5: "triangle", 10: "tetra"}
ARITY = {"line": 2, "triangle": 3, "tetra": 4}
GMSH_DIGITS_BOUND = 6.2e-16


# ---------------------------------------------------------------------------------------------
# Test meshes: plain Python lists, labels at awkward values (0, negative, int32 extremes).

class Mesh:
    def __init__(self, dimension, points, cells, point_labels=None):
        self.dimension = dimension      # 2 or 3
        self.points = points            # list of (x, y, z) tuples, z == 0 in 2D
        self.cells = cells              # list of (kind, node tuple, label)
        self.point_labels = point_labels  # None or one int per point

    def cell_multiset(self, kinds=("line", "triangle", "tetra")):
        return collections.Counter(c for c in self.cells if c[0] in kinds)


def mesh_2d():
    n = 4  # (n+1) x (n+1) grid over [0, 1]^2, coordinates that need 17 significant digits
    points = [(i / n + (j % 2) / 3e3, j / n + (i % 3) / 7e3, 0.0) for j in range(n + 1) for i in range(n + 1)]
    vid = lambda i, j: j * (n + 1) + i
    cells = []
    labels = [1, 2, 0, -7, 2147483647, -2147483648]
    for j in range(n):
        for i in range(n):
            a, b, c, d = vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)
            cells.append(("triangle", (a, b, c), labels[(i + j) % len(labels)]))
            cells.append(("triangle", (a, c, d), labels[(i + 2 * j) % len(labels)]))
    for i in range(n):
        cells.append(("line", (vid(i, 0), vid(i + 1, 0)), 10))
        cells.append(("line", (vid(i + 1, n), vid(i, n)), 0 if i % 2 else -11))
    point_labels = [1 if i in (0, n) or j in (0, n) else 0 for j in range(n + 1) for i in range(n + 1)]
    return Mesh(2, points, cells, point_labels)


def mesh_3d():
    n = 2  # Kuhn subdivision of an n^3 grid of cubes: 6 tetrahedra per cube
    vid = lambda i, j, k: (k * (n + 1) + j) * (n + 1) + i
    points = [(i / 3 + 0.1 * k, j / 3 - 1e-5 * i, k * 0.7)
              for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
    cells = []
    paths = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    labels = [3, 0, -1, 5, 2147483647, 3]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                for p, path in enumerate(paths):
                    corner = [i, j, k]
                    tet = [vid(*corner)]
                    for axis in path:
                        corner[axis] += 1
                        tet.append(vid(*corner))
                    cells.append(("tetra", tuple(tet), labels[(p + i + j + k) % len(labels)]))
    for j in range(n):
        for i in range(n):
            a, b, c, d = vid(i, j, 0), vid(i + 1, j, 0), vid(i + 1, j + 1, 0), vid(i, j + 1, 0)
            cells.append(("triangle", (a, c, b), 7))
            cells.append(("triangle", (a, d, c), 0 if i else 8))
    cells.append(("line", (vid(0, 0, 0), vid(n, 0, 0)), 4))
    point_labels = [(i + 2 * j + 3 * k) % 4 - 1 for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
    return Mesh(3, points, cells, point_labels)


# ---------------------------------------------------------------------------------------------
# .vtu written and read here, with ElementTree (ASCII only: certimesh writes ASCII).

def write_vtu(mesh, path):
    kinds = {v: k for k, v in VTK_TYPES.items()}
    connectivity, offsets, types, labels = [], [], [], []
    for kind, nodes, label in mesh.cells:
        connectivity.extend(nodes)
        offsets.append(len(connectivity))
        types.append(kinds[kind])
        labels.append(label)
    text = ['<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">\n',
            '<UnstructuredGrid>\n<FieldData><DataArray type="Int32" Name="certimesh_dimension" format="ascii">',
            str(mesh.dimension), '</DataArray></FieldData>\n',
            f'<Piece NumberOfPoints="{len(mesh.points)}" NumberOfCells="{len(mesh.cells)}">\n']
    if mesh.point_labels is not None:
        text += ['<PointData><DataArray type="Int32" Name="label" format="ascii">',
                 " ".join(map(str, mesh.point_labels)), '</DataArray></PointData>\n']
    text += ['<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">\n',
             "\n".join(" ".join(repr(c) for c in p) for p in mesh.points), '\n</DataArray></Points>\n<Cells>\n']
    for name, values in (("connectivity", connectivity), ("offsets", offsets), ("types", types)):
        text += [f'<DataArray type="Int64" Name="{name}" format="ascii">', " ".join(map(str, values)), '</DataArray>\n']
    text += ['</Cells>\n<CellData><DataArray type="Int32" Name="label" format="ascii">', " ".join(map(str, labels)),
             '</DataArray></CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n']
    with open(path, "w") as f:
        f.write("".join(text))


def read_vtu(path):
    """certimesh's .vtu output (ASCII arrays) as a Mesh; labels missing -> 0."""
    root = ET.parse(path).getroot()
    grid = root.find("UnstructuredGrid")
    piece = grid.find("Piece")

    def array(parent, name=None):
        if parent is None:
            return None
        for a in parent.findall("DataArray"):
            if name is None or a.get("Name") == name:
                assert a.get("format", "ascii") == "ascii", "certimesh writes ASCII"
                return (a.text or "").split()
        return None

    dimension = int(array(grid.find("FieldData"), "certimesh_dimension")[0])
    xyz = [float(v) for v in array(piece.find("Points"))]
    points = [tuple(xyz[i:i + 3]) for i in range(0, len(xyz), 3)]
    cells_element = piece.find("Cells")
    connectivity = [int(v) for v in array(cells_element, "connectivity")]
    offsets = [int(v) for v in array(cells_element, "offsets")]
    types = [int(v) for v in array(cells_element, "types")]
    labels = [int(v) for v in array(piece.find("CellData"), "label") or ["0"] * len(types)]
    point_labels = array(piece.find("PointData"), "label")
    cells, begin = [], 0
    for end, vtk_type, label in zip(offsets, types, labels):
        cells.append((VTK_TYPES[vtk_type], tuple(connectivity[begin:end]), label))
        begin = end
    return Mesh(dimension, points, cells, None if point_labels is None else [int(v) for v in point_labels])


# ---------------------------------------------------------------------------------------------
# Running tools and comparing.

class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def run(command):
    result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    if result.returncode != 0 or "Error" in result.stderr:
        raise Failure(f"{' '.join(command)} exited {result.returncode}:\n{result.stdout}\n{result.stderr}")
    return result


def convert(certimesh, source, target):
    run([certimesh, "convert", source, target])


def same_bits(a, b):
    return math.copysign(1.0, a) == math.copysign(1.0, b) and a == b


def compare_points(expected, got, what, bound=0.0):
    """Points equal bit for bit (bound 0) or within bound * |x|; returns how many were exact."""
    check(len(expected) == len(got), f"{what}: {len(got)} points, expected {len(expected)}")
    exact = 0
    for i, (p, q) in enumerate(zip(expected, got)):
        for a, b in zip(p, q):
            if bound == 0.0:
                check(same_bits(a, b), f"{what}: point {i} is {q}, expected {p} (bit for bit)")
            else:
                check(abs(a - b) <= bound * abs(a), f"{what}: point {i} is {q}, expected {p} (to {bound} relative)")
        exact += all(same_bits(a, b) for a, b in zip(p, q))
    return exact


def compare_cells(expected, got, what, kinds=("line", "triangle", "tetra")):
    e, g = expected.cell_multiset(kinds), got.cell_multiset(kinds)
    check(e == g, f"{what}: cells differ; only expected: {list((e - g).items())[:5]}; "
                  f"only read: {list((g - e).items())[:5]}")


def bits(point):
    return tuple(float(c).hex() for c in point)


def geometry(mesh, kinds):
    """Points and cells as multisets of exact coordinates: independent of point numbering."""
    cells = collections.Counter((kind, tuple(bits(mesh.points[v]) for v in nodes), label)
                                for kind, nodes, label in mesh.cells if kind in kinds)
    return collections.Counter(bits(p) for p in mesh.points), cells


def labelled_points(mesh):
    return collections.Counter(zip(map(bits, mesh.points), mesh.point_labels or []))


def padded(points):
    return [tuple(float(c) for c in p) + (0.0,) * (3 - len(p)) for p in points]


# ---------------------------------------------------------------------------------------------
# 1. Gmsh reads what certimesh writes; certimesh reads what Gmsh writes.

def gmsh_reads_certimesh(certimesh, work):
    if shutil.which("gmsh") is None:
        print("SKIP: gmsh is not installed (apt-get install gmsh)")
        return SKIP
    for mesh, name in ((mesh_2d(), "2d"), (mesh_3d(), "3d")):
        source, ours, gmshs, back = (os.path.join(work, f"{name}{s}") for s in
                                     (".vtu", "_certimesh.msh", "_gmsh.msh", "_back.vtu"))
        write_vtu(mesh, source)
        convert(certimesh, source, ours)
        # Gmsh loads the file as a discrete model and saves it again in MSH 4.1 ASCII.
        run(["gmsh", ours, "-save", "-format", "msh41", "-o", gmshs])
        convert(certimesh, gmshs, back)
        got = read_vtu(back)
        check(got.dimension == mesh.dimension, f"{name}: dimension {got.dimension}, expected {mesh.dimension}")
        exact = compare_points(mesh.points, got.points, f"{name} after Gmsh", GMSH_DIGITS_BOUND)
        compare_cells(mesh, got, f"{name} after Gmsh")
        check(got.point_labels is None, f"{name}: Gmsh kept the label view?")  # a view, not mesh data
        print(f"{name}: Gmsh re-saved {len(mesh.cells)} cells with their labels; "
              f"{exact}/{len(mesh.points)} points bit for bit, the rest within {GMSH_DIGITS_BOUND:g} relative")
    return 0


def certimesh_reads_gmsh(certimesh, work, geo_dir):
    if shutil.which("gmsh") is None:
        print("SKIP: gmsh is not installed (apt-get install gmsh)")
        return SKIP
    try:
        import meshio  # the independent reader of Gmsh's file
    except ImportError:
        print("SKIP: meshio is not installed for /usr/bin/python3 (apt-get install python3-meshio)")
        return SKIP
    for geo, flag, dimension in (("square.geo", "-2", 2), ("cube.geo", "-3", 3)):
        msh = os.path.join(work, geo.replace(".geo", "_generated.msh"))
        back = msh.replace(".msh", ".vtu")
        run(["gmsh", flag, os.path.join(geo_dir, geo), "-format", "msh41", "-o", msh])
        convert(certimesh, msh, back)
        got = read_vtu(back)
        oracle = meshio.read(msh)
        kinds = [b.type for b in oracle.cells]
        check(set(kinds) <= set(ARITY), f"{geo}: Gmsh wrote cell types {kinds}")
        expected = Mesh(dimension, padded(oracle.points), [
            (block.type, tuple(int(v) for v in nodes), int(label))
            for block, labels in zip(oracle.cells, oracle.cell_data["gmsh:physical"])
            for nodes, label in zip(block.data, labels)])
        check(got.dimension == dimension, f"{geo}: dimension {got.dimension}, expected {dimension}")
        compare_points(expected.points, got.points, geo)
        compare_cells(expected, got, geo)
        print(f"{geo}: certimesh read Gmsh's {len(expected.points)} points and {len(expected.cells)} cells "
              f"as meshio does (points bit for bit, labels = gmsh:physical)")
    return 0


# ---------------------------------------------------------------------------------------------
# 2. meshio reads what certimesh writes, for every format; certimesh reads what meshio writes.

# Per format: the file name, meshio's cell-label and point-label keys, the cell kinds the
# format holds, and the meshes it applies to.
FORMATS = [
    ("gmsh", "out.msh", "gmsh:physical", "label", ("line", "triangle", "tetra"), (2, 3)),
    ("vtu", "out.vtu", "label", "label", ("line", "triangle", "tetra"), (2, 3)),
    ("medit", "out.mesh", "medit:ref", "medit:ref", ("line", "triangle", "tetra"), (2, 3)),
    ("tetgen", "out.node", "tetgen:ref", "tetgen:ref", ("tetra",), (3,)),
]


def meshio_view(m, cell_key, point_key, kinds, dimension):
    """What meshio read, as a Mesh (labels from cell_key; point labels from point_key)."""
    cells = []
    for i, block in enumerate(m.cells):
        check(block.type in ARITY, f"meshio read a cell block of type {block.type}")
        labels = m.cell_data[cell_key][i] if cell_key in m.cell_data else [0] * len(block.data)
        cells += [(block.type, tuple(int(v) for v in nodes), int(label)) for nodes, label in zip(block.data, labels)]
    point_labels = None
    if point_key in m.point_data:
        values = m.point_data[point_key]
        check(all(float(v) == int(v) for v in values), "point labels are not integers")
        point_labels = [int(v) for v in values]
    return Mesh(dimension, padded(m.points), [c for c in cells if c[0] in kinds], point_labels)


def meshio_reads_certimesh(certimesh, work):
    try:
        import meshio
    except ImportError:
        print("SKIP: meshio is not installed for /usr/bin/python3 (apt-get install python3-meshio)")
        return SKIP
    for mesh, name in ((mesh_2d(), "2d"), (mesh_3d(), "3d")):
        source = os.path.join(work, f"{name}.vtu")
        write_vtu(mesh, source)
        for fmt, file_name, cell_key, point_key, kinds, dimensions in FORMATS:
            if mesh.dimension not in dimensions:
                continue
            what = f"{name} .{file_name.split('.')[1]} ({fmt})"
            target = os.path.join(work, f"{name}_{file_name}")
            convert(certimesh, source, target)
            m = meshio.read(target, file_format=fmt)
            got = meshio_view(m, cell_key, point_key, kinds, mesh.dimension)
            check(m.points.shape[1] in (mesh.dimension, 3), f"{what}: points of {m.points.shape[1]} coordinates")
            compare_points(mesh.points, got.points, what)
            compare_cells(mesh, got, what, kinds)
            check(got.point_labels == mesh.point_labels, f"{what}: point labels {got.point_labels}")
            print(f"{what}: meshio read {len(got.points)} points bit for bit, {len(got.cells)} cells, "
                  f"cell labels as {cell_key}, point labels as {point_key}")
    return 0


def meshio_mesh(meshio, numpy, mesh, fmt, kinds):
    """The test mesh as a meshio.Mesh carrying labels under the keys `fmt` writes."""
    if fmt == "gmsh":
        return meshio_gmsh_mesh(meshio, numpy, mesh)
    blocks, labels = [], []
    for kind in ("line", "triangle", "tetra"):
        cells = [c for c in mesh.cells if c[0] == kind]
        if kind in kinds and cells:
            blocks.append((kind, numpy.array([c[1] for c in cells])))
            labels.append(numpy.array([c[2] for c in cells], dtype=numpy.int32))
    points = numpy.array([p[:mesh.dimension] if fmt == "medit" else p for p in mesh.points])
    key = {"vtu": "label", "medit": "medit:ref", "tetgen": "tetgen:ref"}[fmt]
    return meshio.Mesh(points, blocks, point_data={key: numpy.array(mesh.point_labels, dtype=numpy.int32)},
                       cell_data={key: labels})


def meshio_gmsh_mesh(meshio, numpy, mesh):
    """meshio 5.0's Gmsh writer takes one physical tag per cell block (its first cell's) and
    writes an entity only for the (dim, tag) pairs of its nodes' gmsh:dim_tags: so one block
    per (kind, label), and every block's entity given at least one node of its own."""
    dims = {"line": 1, "triangle": 2, "tetra": 3}
    groups = collections.defaultdict(list)
    for kind, nodes, label in mesh.cells:
        groups[(dims[kind], label)].append((kind, nodes))
    blocks, physical, geometrical, entity_of = [], [], [], []
    for (dim, label), cells in sorted(groups.items()):
        tag = sum(1 for d, _ in entity_of if d == dim) + 1
        entity_of.append((dim, tag))
        blocks.append((cells[0][0], numpy.array([c[1] for c in cells])))
        physical.append(numpy.full(len(cells), label, dtype=numpy.int32))
        geometrical.append(numpy.full(len(cells), tag, dtype=numpy.int32))
    dim_tags = [None] * len(mesh.points)
    for b in sorted(range(len(blocks)), key=lambda b: len(blocks[b][1])):  # smallest first
        free = [v for v in numpy.unique(blocks[b][1]) if dim_tags[v] is None]
        check(free, f"meshio Gmsh mesh: no node left for the entity {entity_of[b]}")
        dim_tags[free[0]] = entity_of[b]
    dim_tags = [t if t is not None else entity_of[-1] for t in dim_tags]
    return meshio.Mesh(numpy.array(mesh.points), blocks,
                       point_data={"label": numpy.array(mesh.point_labels, dtype=numpy.int32),
                                   "gmsh:dim_tags": numpy.array(dim_tags)},
                       cell_data={"gmsh:physical": physical, "gmsh:geometrical": geometrical})


def certimesh_reads_meshio(certimesh, work):
    try:
        import meshio
        import numpy
    except ImportError:
        print("SKIP: meshio is not installed for /usr/bin/python3 (apt-get install python3-meshio)")
        return SKIP
    writes = [  # (format, file name, meshio write options)
        ("gmsh", "m.msh", {"file_format": "gmsh", "binary": False}),
        ("vtu", "m_ascii.vtu", {"binary": False}),
        ("vtu", "m_binary.vtu", {"binary": True, "compression": None}),
        ("vtu", "m_zlib.vtu", {}),  # meshio's default: binary, zlib-compressed
        ("medit", "m.mesh", {}),
        ("tetgen", "m.node", {}),
    ]
    for mesh, name in ((mesh_2d(), "2d"), (mesh_3d(), "3d")):
        for fmt, file_name, options in writes:
            _, _, cell_key, point_key, kinds, dimensions = next(f for f in FORMATS if f[0] == fmt)
            if mesh.dimension not in dimensions:
                continue
            what = f"{name} {file_name} written by meshio {options}"
            written = os.path.join(work, f"{name}_{file_name}")
            meshio.write(written, meshio_mesh(meshio, numpy, mesh, fmt, kinds), **options)
            back = written + ".certimesh.vtu"
            convert(certimesh, written, back)
            got = read_vtu(back)
            check(got.dimension == mesh.dimension, f"{what}: dimension {got.dimension}, expected {mesh.dimension}")
            # The oracle is meshio reading its own file: meshio's ASCII writers round
            # coordinates, and both readers must see the same decimals.
            oracle = meshio_view(meshio.read(written, file_format=fmt), cell_key, point_key, kinds, mesh.dimension)
            # Point numbering may differ (meshio numbers .msh nodes in file order, certimesh by
            # tag), so points and cells are compared as multisets of coordinates, bit for bit.
            check(geometry(oracle, kinds) == geometry(got, kinds), f"{what}: certimesh and meshio read different meshes")
            # And nothing was lost on the way: meshio writes .msh coordinates with 17 digits
            # (exact); the other formats keep the point numbering (ASCII .vtu rounds points).
            if fmt == "gmsh":
                check(geometry(got, kinds) == geometry(mesh, kinds), f"{what}: not the mesh meshio was given")
            else:
                check(got.cell_multiset(kinds) == mesh.cell_multiset(kinds), f"{what}: not the cells meshio was given")
            if fmt == "gmsh":
                # meshio 5.0 reads $NodeData in tag order but its points in file order (the
                # nodes are grouped by entity), so here the original mesh is the oracle.
                check(labelled_points(got) == labelled_points(mesh), f"{what}: point labels {got.point_labels}")
            elif fmt in ("vtu", "medit"):  # certimesh's point labels come from these keys
                check(labelled_points(got) == labelled_points(oracle), f"{what}: point labels {got.point_labels}")
            print(f"{what}: certimesh read {len(got.points)} points (as meshio does) and {len(got.cells)} cells")
    return 0


def main(argv):
    if len(argv) < 4:
        print(__doc__)
        return 2
    command, certimesh, work = argv[1], argv[2], argv[3]
    os.makedirs(work, exist_ok=True)
    commands = {
        "gmsh_reads_certimesh": lambda: gmsh_reads_certimesh(certimesh, work),
        "certimesh_reads_gmsh": lambda: certimesh_reads_gmsh(certimesh, work, argv[4]),
        "meshio_reads_certimesh": lambda: meshio_reads_certimesh(certimesh, work),
        "certimesh_reads_meshio": lambda: certimesh_reads_meshio(certimesh, work),
    }
    try:
        return commands[command]()
    except Failure as failure:
        print(f"FAIL: {failure}")
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))

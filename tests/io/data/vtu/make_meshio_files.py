# Writes the meshio-made .vtu files of this folder (meshio 5.0.0, Debian python3-meshio):
#   /usr/bin/python3 make_meshio_files.py
# The mesh: 4 points, one triangle (label -3) and one tetrahedron (label 7), point labels 1..4,
# one coordinate with a full 17-digit mantissa, so the tests can compare with literal values.
import meshio
import numpy as np

points = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.1, 0.2, 1e-300]])
cells = [("triangle", np.array([[0, 1, 2]])), ("tetra", np.array([[0, 1, 2, 3]]))]
mesh = meshio.Mesh(points, cells,
                   point_data={"label": np.array([1, 2, 3, 4], dtype=np.int32)},
                   cell_data={"label": [np.array([-3], dtype=np.int32), np.array([7], dtype=np.int32)]})
meshio.write("meshio_binary.vtu", mesh, binary=True, compression=None)
meshio.write("meshio_binary_zlib.vtu", mesh)  # meshio's default: binary, zlib-compressed
meshio.write("meshio_ascii.vtu", mesh, binary=False)

# VTK's own layout for inline uncompressed binary: header_type UInt64 and the header in its own
# base64 block before the data's (meshio encodes header and data as one block). Same mesh.
import base64


def vtk_block(array):
    data = array.tobytes()
    return (base64.b64encode(np.array([len(data)], dtype="<u8").tobytes()).decode()
            + base64.b64encode(data).decode())


def data_array(type_name, name, array, components=""):
    return (f'<DataArray type="{type_name}" Name="{name}"{components} format="binary">\n'
            f'{vtk_block(array)}\n</DataArray>\n')


with open("vtk_style_binary_uint64.vtu", "w") as f:
    f.write('<?xml version="1.0"?>\n'
            '<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">\n'
            '<UnstructuredGrid>\n<Piece NumberOfPoints="4" NumberOfCells="2">\n'
            '<PointData>\n' + data_array("Int32", "label", np.array([1, 2, 3, 4], dtype="<i4")) + '</PointData>\n'
            '<CellData>\n' + data_array("Int16", "label", np.array([-3, 7], dtype="<i2")) + '</CellData>\n'
            '<Points>\n' + data_array("Float64", "Points", points.astype("<f8"), ' NumberOfComponents="3"')
            + '</Points>\n<Cells>\n'
            + data_array("Int32", "connectivity", np.array([0, 1, 2, 0, 1, 2, 3], dtype="<i4"))
            + data_array("Int32", "offsets", np.array([3, 7], dtype="<i4"))
            + data_array("UInt8", "types", np.array([5, 10], dtype="u1"))
            + '</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n')

# A compressor certimesh does not read (LZMA), for the refusal test.
meshio.write("meshio_binary_lzma.vtu", mesh, compression="lzma")

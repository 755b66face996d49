"""Readers of deal.II's VTU and PVD files for the tests (no side effects:
the test scripts import them)."""
import base64
import xml.etree.ElementTree as ET
import zlib

import numpy as np


def data_array(element):
    """The values of a DataArray of deal.II's VTU (zlib-compressed base64
    blocks after a base64 header of UInt32 counts, or ascii)."""
    dtype = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "u1"}[element.get("type")]
    text = "".join(element.text.split())
    if element.get("format") == "ascii":
        return np.array(text.split(), dtype=float)
    n_blocks = np.frombuffer(base64.b64decode(text[:8]), "<u4", 1)[0]
    header_bytes = 4 * (3 + n_blocks)
    header_chars = 4 * ((header_bytes + 2) // 3)
    header = np.frombuffer(base64.b64decode(text[:header_chars]), "<u4", 3 + n_blocks)
    blob = base64.b64decode(text[header_chars:])
    raw, start = b"", 0
    for size in header[3:]:
        raw += zlib.decompress(blob[start:start + size])
        start += size
    return np.frombuffer(raw, dtype)


def read_vtu(path):
    """The piece of a VTU: (points, cells, {field: (components, values)}).
    deal.II writes every field as point data, a cell field at the cell's own
    vertices (its cells do not share points)."""
    piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
    fields = {a.get("Name"): (int(a.get("NumberOfComponents", "1")), data_array(a))
              for a in piece.find("PointData").findall("DataArray")}
    return int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells")), fields


def read_pvd(path):
    """(time, file) of every DataSet of a PVD index."""
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_points(path):
    """(points, {field: values}) of a VTU: the points as an (n, 3) array, each
    field as an (n, components) array."""
    piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
    points = data_array(piece.find("Points/DataArray")).reshape(-1, 3).astype(float)
    fields = {}
    for a in piece.find("PointData").findall("DataArray"):
        c = int(a.get("NumberOfComponents", "1"))
        fields[a.get("Name")] = data_array(a).reshape(-1, c).astype(float)
    return points, fields

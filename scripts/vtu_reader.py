"""Read lithostress's ParaView output (deal.II's zlib-compressed XML VTU
files, one per rank, gathered by a .pvtu and a .pvd time series) into
numpy arrays, for scripts that measure results at the output's nodes.

    series = read_pvd(directory)            # [(time_s, pvtu_path), ...]
    nodes = read_pvtu(path)                 # dict of arrays, one row per node
    nodes["x"], nodes["y"], nodes["stress"] (n x 3: xx, yy, xy), ...

Each cell's patch repeats its own nodes, so a node shared by cells appears
once per cell with that cell's values (stresses are discontinuous across
cells); maxima and minima over the rows are the finite-element field's.
"""
import base64
import os
import re
import struct
import zlib

import numpy as np

_TYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "<u1",
          "Int64": "<i8", "UInt32": "<u4", "UInt64": "<u8"}


def _decode(data, dtype):
    """One base64, zlib-compressed block sequence (VTK's header: count,
    block size, last block size, compressed sizes)."""
    head = base64.b64decode(data[:8])
    blocks = struct.unpack("<I", head[:4])[0]
    header_length = 4 * (3 + blocks)
    header_b64 = ((header_length + 2) // 3) * 4
    header = struct.unpack("<%dI" % (3 + blocks),
                           base64.b64decode(data[:header_b64]))
    raw = base64.b64decode(data[header_b64:])
    out, pos = [], 0
    for size in header[3:]:
        out.append(zlib.decompress(raw[pos:pos + size]))
        pos += size
    return np.frombuffer(b"".join(out), dtype=dtype)


def read_vtu(path):
    """The point data of one .vtu piece: x, y and every named array (vector
    arrays as n x components)."""
    text = open(path).read()
    out = {}
    points = re.search(r"<Points>\s*<DataArray([^>]*)>\s*([^<]*)</DataArray>",
                       text)
    typ = re.search(r'type="(\w+)"', points.group(1)).group(1)
    xyz = _decode(points.group(2).strip(), _TYPES[typ]).reshape(-1, 3)
    out["x"], out["y"] = xyz[:, 0].astype(float), xyz[:, 1].astype(float)
    point_data = re.search(r"<PointData[^>]*>(.*?)</PointData>", text, re.S)
    for m in re.finditer(r"<DataArray([^>]*)>\s*([^<]*)</DataArray>",
                         point_data.group(1) if point_data else ""):
        attrs, data = m.group(1), m.group(2).strip()
        name = re.search(r'Name="([^"]*)"', attrs).group(1)
        typ = re.search(r'type="(\w+)"', attrs).group(1)
        components = re.search(r'NumberOfComponents="(\d+)"', attrs)
        values = _decode(data, _TYPES[typ]).astype(float)
        if components and int(components.group(1)) > 1:
            values = values.reshape(-1, int(components.group(1)))
        out[name] = values
    return out


def read_pvtu(path):
    """All pieces of a .pvtu, concatenated."""
    text = open(path).read()
    pieces = re.findall(r'<Piece\s+Source="([^"]+)"', text)
    parts = [read_vtu(os.path.join(os.path.dirname(path), p)) for p in pieces]
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


def read_pvd(directory):
    """The time series of solution.pvd: [(time [s], .pvtu path)]."""
    text = open(os.path.join(directory, "solution.pvd")).read()
    return [(float(t), os.path.join(directory, f)) for t, f in
            re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]

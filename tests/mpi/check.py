"""MPI: the cantilever (global refinement) and the adaptive L-shaped
problem on 2 ranks agree with 1 rank.

Both runs discretise the same problem on the same mesh, so they solve the
same linear system; they differ only in the order of floating-point sums
(ghost exchanges, reductions, the partition of the multigrid's smoothers
and, with AMG, its partition-dependent aggregates), which changes the
solver's iterates in round-off and where it stops. CG is run to a relative
residual of 1e-13 so that this difference is far below everything compared.

1. The meshes are the same cell for cell, in every cycle: each run writes
   its mesh in the ParaView files (higher-order cells, every node through
   the mapping), read here from the compressed .vtu pieces of all ranks;
   the sorted lists of cells, each given by the coordinates of its 9 Q2
   nodes, must be identical. Equal numbers of cells and DoFs would not show
   that the adaptive marking (which only sums over ranks) refines the
   same cells.
2. Every entry of convergence.csv is finite (a NaN or inf fails the test,
   it never compares as "not worse") and an entry empty in one table
   (a rate or change in cycle 0) is empty in the other.
3. Point values (u_*, s_* and their changes between cycles) agree to
   TOL_FIELD relative to the largest value of that field over the points
   and cycles; errors (L2(u), energy, L2(stress), their rel_* forms,
   err_u@P) agree relatively, each to its own value, to TOL_ERROR; rates
   to TOL_RATE, relatively.
4. The displacement at every node of the ParaView output agrees to 2^-23
   (two float32 roundings of 2^-24 each: the .vtu files hold float32) plus
   TOL_FIELD, relative to the largest displacement.

Tolerances, from the differences measured with the solver at 1e-13
(cantilever to 8.5 k DoFs / L-shaped domain, 16 adaptive cycles):
point values 6.1e-12 / 7.3e-13 of the field's largest value; errors
5.3e-9 / 3.1e-10 of themselves (largest for the point error err_u@P1,
1.3e-7 of |u| on the finest cantilever: an error's relative difference is
the solution's difference divided by a small number); rates 2.3e-9 /
1.3e-9; nodal displacements in the .vtu equal to the last float32 bit.
TOL_FIELD = 1e-10, TOL_ERROR = 5e-8 and TOL_RATE = 3e-8 are 9-16x the
largest of these; a partition-dependent mistake (a missing ghost
contribution, a constraint lost at a processor boundary) changes values by
the order of the discretisation error."""
import base64, csv, math, struct, sys, os, zlib
import xml.etree.ElementTree as ET
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

TOL_FIELD = 1e-10
TOL_ERROR = 5e-8
TOL_RATE = 3e-8
FLOAT32 = 2.0 ** -23


def raw_table(output):
    """convergence.csv as (header, rows of strings)."""
    with open(os.path.join(output, "convergence.csv")) as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def decode_array(element):
    """The values of a <DataArray format="binary"> written by deal.II with
    zlib compression: base64 of a 4 x uint32 header (blocks, block size,
    last block size, compressed size), then base64 of the compressed
    block."""
    text = "".join(element.text.split())
    kind = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
            "UInt8": "B", "UInt32": "I", "UInt64": "Q"}[element.get("type")]
    if element.get("format") == "ascii":
        return [float(v) for v in text.split()]
    blocks, size, last, compressed = struct.unpack("<4I", base64.b64decode(text[:24]))
    if blocks != 1:
        fail("unexpected .vtu encoding: %d compressed blocks" % blocks)
    data = zlib.decompress(base64.b64decode(text[24:]))
    if len(data) != size:
        fail("unexpected .vtu encoding: %d bytes instead of %d" % (len(data), size))
    return list(struct.unpack("<%d%s" % (size // struct.calcsize(kind), kind), data))


def read_mesh(pvtu):
    """The cells of all pieces of a .pvtu record: a sorted list of cells,
    each the sorted tuple of its nodes' (x, y), and {node (x, y): (u_x, u_y)}."""
    directory = os.path.dirname(pvtu)
    pieces = [p.get("Source") for p in ET.parse(pvtu).getroot().iter("Piece")]
    cells, displacement = [], {}
    for piece in pieces:
        root = ET.parse(os.path.join(directory, piece)).getroot()
        for grid in root.iter("Piece"):
            points = decode_array(grid.find("Points/DataArray"))
            arrays = {a.get("Name"): a for a in grid.find("Cells").iter("DataArray")}
            connectivity = decode_array(arrays["connectivity"])
            offsets = decode_array(arrays["offsets"])
            xy = [(points[3 * i], points[3 * i + 1]) for i in range(len(points) // 3)]
            start = 0
            for end in offsets:
                cells.append(tuple(sorted(xy[k] for k in connectivity[start:end])))
                start = end
            data = {a.get("Name"): a for a in grid.find("PointData").iter("DataArray")}
            if "displacement" not in data:
                fail("%s: no displacement in the ParaView output" % piece)
            u = decode_array(data["displacement"])
            ncomp = int(data["displacement"].get("NumberOfComponents", "1"))
            for i, p in enumerate(xy):
                displacement[p] = (u[ncomp * i], u[ncomp * i + 1])
    return sorted(cells), displacement


for name, prm, cycles in [("cantilever", "cantilever/cantilever.prm", 5),
                          ("l_shaped", "l_shaped/l_shaped_adaptive.prm", 16)]:
    sets = ["Mesh refinement/Number of cycles=%d" % cycles,
            "Solver/Relative tolerance=1e-13", "Output/Write ParaView files=true",
                   "Output/ParaView cycles=all"]
    outs = []
    for ranks in (1, 2):
        out = os.path.abspath("output_mpi_%s_%d" % (name, ranks))
        run(prm, out, ranks, sets)
        outs.append(out)

    # 2. Finite entries, the same empty ones.
    (head1, raw1), (head2, raw2) = raw_table(outs[0]), raw_table(outs[1])
    # Every cycle asked for, in both tables: the loops below compare row by
    # row and would assert nothing over an empty or truncated table.
    check(head1 == head2 and len(raw1) == len(raw2) == cycles,
          "%s: same columns and number of cycles (%d and %d, %d expected)"
          % (name, len(raw1), len(raw2), cycles))
    bad = []
    finite = True
    for r1, r2 in zip(raw1, raw2):
        for key, v1, v2 in zip(head1, r1, r2):
            if (v1 == "") != (v2 == ""):
                finite = False
                bad.append("%s: '%s' vs '%s'" % (key, v1, v2))
            elif v1 != "" and not (math.isfinite(float(v1)) and math.isfinite(float(v2))):
                finite = False
                bad.append("%s: %s vs %s" % (key, v1, v2))
    check(finite, "%s: every entry finite in both tables, the same ones empty %s"
          % (name, "; ".join(bad[:4])))

    # 3. Values.
    one, two = table(outs[0]), table(outs[1])
    worst = {"field": (0.0, ""), "error": (0.0, ""), "rate": (0.0, "")}
    compared = {"field": 0, "error": 0, "rate": 0}
    for a, b in zip(one, two):
        check(a["dofs"] == b["dofs"] and a["cells"] == b["cells"],
              "%s cycle %d: same numbers of cells and DoFs (%d, %d)" % (name, a["cycle"], a["cells"], a["dofs"]))
        for key in a:
            if not (math.isfinite(a[key]) and math.isfinite(b[key])):
                continue
            field = key.replace("change_", "")
            if field.startswith(("u_", "s_")) and "@" in field:
                prefix = field.split("@")[0][:2]
                scale = max(abs(r[k]) for r in one for k in r
                            if k.startswith(prefix) and "@" in k and math.isfinite(r[k]))
                kind, diff = "field", abs(a[key] - b[key]) / scale
            elif key.startswith("rate"):
                kind, diff = "rate", abs(a[key] - b[key]) / abs(b[key])
            elif key in ("cycle", "dofs", "cells"):
                continue
            else:
                kind, diff = "error", abs(a[key] - b[key]) / abs(b[key])
            compared[kind] += 1
            if diff > worst[kind][0]:
                worst[kind] = (diff, "%s in cycle %d" % (key, a["cycle"]))
    # A kind with no finite entry at all (a column renamed, points not
    # written) would pass with its largest difference 0.
    for kind, tol in (("field", TOL_FIELD), ("error", TOL_ERROR), ("rate", TOL_RATE)):
        check(compared[kind] > 0 and worst[kind][0] <= tol,
              "%s: largest relative difference of the %s columns 1 vs 2 ranks %.1e (%s; %d entries "
              "compared) <= %.0e" % (name, kind, worst[kind][0], worst[kind][1], compared[kind], tol))

    # 1. and 4. The meshes and the nodal displacements of every cycle.
    for row in one:
        c = int(row["cycle"])
        record = [os.path.join(o, "solution_%03d.pvtu" % c) for o in outs]
        if not all(os.path.exists(p) for p in record):
            check(False, "%s cycle %d: ParaView record written by both runs" % (name, c))
            continue
        (cells1, u1), (cells2, u2) = read_mesh(record[0]), read_mesh(record[1])
        check(len(cells1) == row["cells"] and cells1 == cells2,
              "%s cycle %d: the same %d cells (node coordinates) on 1 and 2 ranks" % (name, c, len(cells1)))
        if not u1 or u1.keys() != u2.keys():
            check(False, "%s cycle %d: displacement at the same nodes on 1 and 2 ranks" % (name, c))
            continue
        umax = max(math.hypot(*v) for v in u1.values())
        diff = max(math.hypot(u1[p][0] - u2[p][0], u1[p][1] - u2[p][1]) for p in u1) / umax
        check(diff <= FLOAT32 + TOL_FIELD,
              "%s cycle %d: displacement at all %d nodes, largest difference %.1e of max |u| "
              "(float32 output: allowed %.1e)" % (name, c, len(u1), diff, FLOAT32 + TOL_FIELD))
finish()

"""The meshes of the buried-tip verification cases (issue 27), shared by
their tests and by bench/run --problems buried: Gmsh MSH 2.2 files written
with gmsh_writer.write_msh."""
import math

from gmsh_writer import graded, write_msh


def half_space_msh(path, dip, fine, n_fine, top, bottom):
    """The half-space as a parallelogram whose columns follow the fault's
    plane x = d cot(dip) (dip in radians), n_fine cells of `fine` km from
    it and from the surface, then graded by 1.5 to 50 000 km; the physical
    curve "fault" runs along the plane from the depth `top` to `bottom`
    [km] only (rows of the mesh)."""
    depths = graded(fine, n_fine, 1.5, 50000.0)
    offsets = graded(fine, n_fine, 1.5, 50000.0)
    columns = [-o for o in reversed(offsets[1:])] + offsets
    rows = [(-d, [d / math.tan(dip) + o for o in columns]) for d in reversed(depths)]
    nx, ny = len(columns), len(rows)
    on_fault = columns.index(0.0)
    row_at = {round(-y, 9): j for j, (y, xs) in enumerate(rows)}
    write_msh(path, rows, {
        "left": [(0, j, 0, j + 1) for j in range(ny - 1)],
        "right": [(nx - 1, j, nx - 1, j + 1) for j in range(ny - 1)],
        "base": [(i, 0, i + 1, 0) for i in range(nx - 1)],
        "top": [(i, ny - 1, i + 1, ny - 1) for i in range(nx - 1)],
        "fault": [(on_fault, j, on_fault, j + 1) for j in range(row_at[bottom], row_at[top])]})


def crack_msh(path, far, half_length=5.0):
    """A square of 1 km cells within 8 km of the crack (x = 0, |y| <=
    half_length km, the physical curve "fault"), then graded by doubling
    to `far` km on each side."""
    g = graded(1.0, 8, 2.0, far)
    axis = [-o for o in reversed(g[1:])] + g
    n, mid = len(axis), axis.index(0.0)
    rows = [(y, list(axis)) for y in axis]
    write_msh(path, rows, {
        "left": [(0, j, 0, j + 1) for j in range(n - 1)],
        "right": [(n - 1, j, n - 1, j + 1) for j in range(n - 1)],
        "base": [(i, 0, i + 1, 0) for i in range(n - 1)],
        "top": [(i, n - 1, i + 1, n - 1) for i in range(n - 1)],
        "fault": [(mid, j, mid, j + 1)
                  for j in range(axis.index(-half_length), axis.index(half_length))]})

"""The thesis's 27-node cantilever (§4.3) with its own elements, for the
tolerance of the thesis-mesh check in check.py (not a ctest test; standard
library only, run with python3).

10 x 2.5 beam, E = 0.85e7, nu = 0.35, every node of x = l = 10 fixed, the
end load P = 5e4 as the parabolic shear traction on x = 0 (consistent nodal
forces), nodes on a 9 x 3 grid. Tip deflection v(0, 0) with
  - 4 x 1 Q2 (nine-node) quadrilaterals: lithostress's elements; must
    reproduce the program's thesis-mesh value -1.34115 (plane strain; it
    does, to 12 digits);
  - 8 six-node triangles (P2, the thesis's isoparametric element): each
    2.5 x 2.5 square split along either diagonal, or alternating;
  - the thesis's constant-strain elements (§4.3.2, thesis_cantilever()):
    32 CSTs (each 1.25 x 1.25 square cut along a diagonal) and 16 CSQs
    (four CSTs about a centre node), the end load consistent with linear
    edges: CST 52.5 % of beam theory (plane strain; 56.7 % plane stress),
    CSQ 89.5 % (88.5 %), against the thesis's 58 % and 83 %;
against beam theory -P l^3/(3 E I) (E' = E/(1 - nu^2) in plane strain).
Measured: plane strain beam -1.32141, Q2 -1.34115 (+1.49 %), P2 triangles
-1.30180 / -1.30180 / -1.30144 (-1.5 %); plane stress beam -1.50588, Q2
-1.54861 (+2.84 %), P2 -1.52596 (+1.33 %).

The refined constant-strain meshes of §4.3.2 (grid_cantilever(), same
beam, end and load on an nx x ny node grid; error against beam theory,
plane strain / plane stress): the thesis's 288 nodes and 496 CSTs as a
32 x 9 grid (its figure 4.10 is not in the text), -2.75 % / -1.36 %
(alternating diagonals -0.23 %); its 85 nodes and 64 CSQs as a 17 x 5
grid, -0.33 % / -0.35 %. The
smallest grid within 5 % on the family with square cells and a node on
the neutral axis (nx - 1 = 4 (ny - 1), ny odd; smallest_grid_within()):
CST 33 x 9 (297 nodes, 512 triangles, -2.63 % / -1.25 %; 25 x 7 gives
-7.17 %), CSQ 17 x 5 (the thesis's mesh; 9 x 3 gives -10.5 %). With ny
even allowed as well: CST 29 x 8 (232 nodes, -4.48 %), CSQ 13 x 4
(52 nodes, -3.33 %).

The lithostatic column of §4.4.2 on the thesis's 9 nodes and 8 CSTs
(lithostatic_column_cst(), base on rollers): with the diagonals \\ the
top left node subsides 109.8 % and the top right one 90.9 % of equation
4.4's 12.717 m (thesis: +10 % and -10 %), / mirrors this; the principal
axes turn by up to 11.4 degrees (thesis 13) and the principal stresses
differ from the exact ones at the triangles' centroids by up to 12.7 %
in the lower row of triangles and up to 54.6 % in the upper row (thesis:
up to 10 %). A fixed base changes the subsidences to 109.5 % and 91.0 %.
Alternating diagonals meeting at the centre give a symmetric 102.4 %,
7.5 degrees and 11.0 %."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import solve_dense  # noqa: E402

P, L, C, E, NU = 5e4, 10.0, 1.25, 0.85e7, 0.35
NODES = [(1.25 * i, y) for y in (-C, 0.0, C) for i in range(9)]


def node(i, j):
    return 9 * j + i


def elasticity(strain, young=E, nu=NU):
    if strain:
        f = young / ((1 + nu) * (1 - 2 * nu))
        return [[f * (1 - nu), f * nu, 0], [f * nu, f * (1 - nu), 0], [0, 0, f * (1 - 2 * nu) / 2]]
    f = young / (1 - nu * nu)
    return [[f, f * nu, 0], [f * nu, f, 0], [0, 0, f * (1 - nu) / 2]]


def p2(xi, eta):
    """Six-node triangle: values and reference gradients (vertices, then
    the midpoints of edges 01, 12, 20)."""
    lam = [1 - xi - eta, xi, eta]
    dlam = [(-1, -1), (1, 0), (0, 1)]
    values = [l * (2 * l - 1) for l in lam] + [4 * lam[a] * lam[b] for a, b in ((0, 1), (1, 2), (2, 0))]
    grads = [[(4 * lam[a] - 1) * dlam[a][k] for k in range(2)] for a in range(3)]
    grads += [[4 * (lam[a] * dlam[b][k] + lam[b] * dlam[a][k]) for k in range(2)]
              for a, b in ((0, 1), (1, 2), (2, 0))]
    return values, grads


def q2(xi, eta):
    """Nine-node quadrilateral on [-1, 1]^2, lexicographic nodes."""
    def l(t):
        return [t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2]

    def dl(t):
        return [t - 0.5, -2 * t, t + 0.5]
    values, grads = [], []
    for j in range(3):
        for i in range(3):
            values.append(l(xi)[i] * l(eta)[j])
            grads.append([dl(xi)[i] * l(eta)[j], l(xi)[i] * dl(eta)[j]])
    return values, grads


GAUSS3 = [(-math.sqrt(0.6), 5 / 9), (0.0, 8 / 9), (math.sqrt(0.6), 5 / 9)]
QUAD_RULE = [(a, b, wa * wb) for a, wa in GAUSS3 for b, wb in GAUSS3]
TRIANGLE_RULE = [(1 / 6, 1 / 6, 1 / 6), (2 / 3, 1 / 6, 1 / 6), (1 / 6, 2 / 3, 1 / 6)]  # exact for degree 2


def tip_deflection(elements, shape, rule, strain, nodes=NODES, linear_edge=False):
    """v(0, 0) of the mesh @p elements (node indices into @p nodes) with
    the element @p shape and quadrature @p rule; the end load's nodal
    forces consistent with a quadratic edge, or with two linear edges."""
    n = 2 * len(nodes)
    K = [[0.0] * n for _ in range(n)]
    D = elasticity(strain)
    for element in elements:
        dofs = [2 * a + d for a in element for d in range(2)]
        for xi, eta, weight in rule:
            _, grads = shape(xi, eta)
            J = [[sum(g[r] * nodes[a][c] for g, a in zip(grads, element)) for c in range(2)] for r in range(2)]
            det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
            inv = [[J[1][1] / det, -J[0][1] / det], [-J[1][0] / det, J[0][0] / det]]
            B = [[0.0] * len(dofs) for _ in range(3)]
            for a, g in enumerate(grads):
                gx = inv[0][0] * g[0] + inv[0][1] * g[1]
                gy = inv[1][0] * g[0] + inv[1][1] * g[1]
                B[0][2 * a], B[1][2 * a + 1], B[2][2 * a], B[2][2 * a + 1] = gx, gy, gy, gx
            DB = [[sum(D[r][k] * B[k][c] for k in range(3)) for c in range(len(dofs))] for r in range(3)]
            for i, di in enumerate(dofs):
                for j, dj in enumerate(dofs):
                    K[di][dj] += weight * det * sum(B[k][i] * DB[k][j] for k in range(3))
    f = [0.0] * n
    inertia = 2 * C ** 3 / 3
    for t, weight in GAUSS3:  # t_y = -P (c^2 - y^2) / (2 I) on x = 0
        if linear_edge:
            # Two linear edges, y in [-c, 0] and [0, c], each mapped from t.
            for j0 in (0, 1):
                y = C * (j0 - 1) + C * (t + 1) / 2
                traction = -P * (C * C - y * y) / (2 * inertia)
                for j, value in ((j0, (1 - t) / 2), (j0 + 1, (1 + t) / 2)):
                    f[2 * node(0, j) + 1] += weight * C / 2 * value * traction
        else:
            y = C * t
            for j, value in enumerate([t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2]):
                f[2 * node(0, j) + 1] += weight * C * value * (-P * (C * C - y * y) / (2 * inertia))
    fixed = {2 * node(8, j) + d for j in range(3) for d in range(2)}
    free = [i for i in range(n) if i not in fixed]
    u = solve_dense([[K[i][j] for j in free] for i in free], [f[i] for i in free])
    return u[free.index(2 * node(0, 1) + 1)]


def p1(xi, eta):
    """Three-node (constant strain) triangle."""
    return [1 - xi - eta, xi, eta], [(-1, -1), (1, 0), (0, 1)]


CENTROID_RULE = [(1 / 3, 1 / 3, 1 / 2)]


def split_rectangles(nx, ny, at, diagonal):
    """The (nx - 1) x (ny - 1) rectangles of a node grid numbered by
    @p at(i, j), each cut into two CSTs along a diagonal (0: /, 1: \\,
    2: alternating)."""
    elements = []
    for i in range(nx - 1):
        for j in range(ny - 1):
            a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
            if (diagonal if diagonal < 2 else (i + j) % 2) == 0:
                elements += [[a, b, c], [a, c, d]]
            else:
                elements += [[a, b, d], [b, c, d]]
    return elements


def quadrilaterals_of_four(nodes, nx, ny, at):
    """The rectangles of the grid as constant-strain quadrilaterals: four
    CSTs meeting at a centre node, appended to @p nodes (thesis §3.3.2;
    the centre node's freedoms are condensed in the thesis, kept here:
    the same stiffness)."""
    elements = []
    for i in range(nx - 1):
        for j in range(ny - 1):
            corners = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
            nodes.append(tuple(sum(nodes[k][r] for k in corners) / 4 for r in range(2)))
            elements += [[corners[k], corners[(k + 1) % 4], len(nodes) - 1] for k in range(4)]
    return elements


def cst_triangles(diagonal):
    """The 27 nodes' 16 squares, each cut into two CSTs along a diagonal
    (0: /, 1: \\, 2: alternating)."""
    return split_rectangles(9, 3, node, diagonal)


def csq_mesh():
    """The 16 squares as constant-strain quadrilaterals."""
    nodes = list(NODES)
    return quadrilaterals_of_four(nodes, 9, 3, node), nodes


def thesis_cantilever(strain=True):
    """Tip deflections v(0, 0) on the thesis's 27 nodes (§4.3.2): beam
    theory, the CST mesh (each diagonal pattern), the CSQ mesh, the
    six-node triangles and lithostress's Q2 quadrilaterals."""
    beam = -P * L ** 3 / (3 * (E / (1 - NU * NU) if strain else E) * 2 * C ** 3 / 3)
    quads = [[node(2 * e + i, j) for j in range(3) for i in range(3)] for e in range(4)]
    csq, csq_nodes = csq_mesh()
    return {"beam": beam,
            "CST": tip_deflection(cst_triangles(0), p1, CENTROID_RULE, strain, linear_edge=True),
            "CST \\": tip_deflection(cst_triangles(1), p1, CENTROID_RULE, strain, linear_edge=True),
            "CST alternating": tip_deflection(cst_triangles(2), p1, CENTROID_RULE, strain,
                                              linear_edge=True),
            "CSQ": tip_deflection(csq, p1, CENTROID_RULE, strain, csq_nodes, linear_edge=True),
            "P2": tip_deflection(triangles(0), p2, TRIANGLE_RULE, strain),
            "Q2": tip_deflection(quads, q2, QUAD_RULE, strain)}


def triangles(diagonal):
    elements = []
    for e in range(4):
        def n(i, j):
            return node(2 * e + i, j)
        d = diagonal if diagonal < 2 else e % 2
        if d == 0:
            elements.append([n(0, 0), n(2, 0), n(2, 2), n(1, 0), n(2, 1), n(1, 1)])
            elements.append([n(0, 0), n(2, 2), n(0, 2), n(1, 1), n(1, 2), n(0, 1)])
        else:
            elements.append([n(0, 0), n(2, 0), n(0, 2), n(1, 0), n(1, 1), n(0, 1)])
            elements.append([n(2, 0), n(2, 2), n(0, 2), n(2, 1), n(1, 2), n(1, 1)])
    return elements


def linear_triangle(coords, D):
    """Stiffness (6 x 6, unit thickness), strain matrix B and area of the
    constant-strain triangle with the vertices @p coords (closed form of
    tip_deflection()'s p1 with CENTROID_RULE)."""
    (x1, y1), (x2, y2), (x3, y3) = coords
    twice_area = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1)
    b = [(y2 - y3) / twice_area, (y3 - y1) / twice_area, (y1 - y2) / twice_area]
    c = [(x3 - x2) / twice_area, (x1 - x3) / twice_area, (x2 - x1) / twice_area]
    B = [[0.0] * 6 for _ in range(3)]
    for a in range(3):
        B[0][2 * a], B[1][2 * a + 1], B[2][2 * a], B[2][2 * a + 1] = b[a], c[a], c[a], b[a]
    DB = [[sum(D[r][k] * B[k][col] for k in range(3)) for col in range(6)] for r in range(3)]
    area = twice_area / 2
    K = [[area * sum(B[k][i] * DB[k][j] for k in range(3)) for j in range(6)] for i in range(6)]
    return K, B, area


def solve_banded(entries, rhs):
    """x of K x = rhs for K symmetric positive definite, given as
    {(i, j): K_ij}: Cholesky within the band. The refined meshes of
    §4.3.2 have several hundred freedoms, too many for solve_dense's full
    elimination in pure Python."""
    n = len(rhs)
    w = max(abs(i - j) for i, j in entries)
    L = [[0.0] * (w + 1) for _ in range(n)]  # L[i][i - j] for j in [i - w, i]
    for (i, j), value in entries.items():
        if j <= i:
            L[i][i - j] = value
    for i in range(n):
        row = L[i]
        for j in range(max(0, i - w), i + 1):
            other = L[j]
            s = row[i - j] - sum(row[i - k] * other[j - k] for k in range(max(0, i - w), j))
            row[i - j] = math.sqrt(s) if j == i else s / other[0]
    y = [0.0] * n
    for i in range(n):
        y[i] = (rhs[i] - sum(L[i][i - k] * y[k] for k in range(max(0, i - w), i))) / L[i][0]
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (y[i] - sum(L[k][k - i] * x[k] for k in range(i + 1, min(n, i + w + 1)))) / L[i][0]
    return x


def solve_triangles(nodes, elements, D, forces, fixed):
    """Displacements [u_x, u_y, ...] of the constant-strain triangles
    @p elements on @p nodes under the nodal @p forces, the freedoms in
    @p fixed held at zero. The freedoms are ordered by the nodes' x, then
    y, so that the stiffness is banded for the grids here."""
    order = sorted(range(len(nodes)), key=lambda a: (nodes[a][0], nodes[a][1]))
    rank = {a: r for r, a in enumerate(order)}
    free = sorted((i for i in range(2 * len(nodes)) if i not in fixed),
                  key=lambda i: 2 * rank[i // 2] + i % 2)
    index = {i: r for r, i in enumerate(free)}
    entries = {}
    for element in elements:
        K, _, _ = linear_triangle([nodes[a] for a in element], D)
        dofs = [2 * a + d for a in element for d in range(2)]
        for p, di in enumerate(dofs):
            for q, dj in enumerate(dofs):
                if di in index and dj in index:
                    key = (index[di], index[dj])
                    entries[key] = entries.get(key, 0.0) + K[p][q]
    x = solve_banded(entries, [forces[i] for i in free])
    u = [0.0] * (2 * len(nodes))
    for i, value in zip(free, x):
        u[i] = value
    return u


def grid_cantilever(nx, ny, kind="CST", strain=True, diagonal=0):
    """Tip deflection v(0, 0) and its error against beam theory (per cent,
    negative: too stiff) of the §4.3 cantilever on an @p nx x @p ny node
    grid with the thesis's constant-strain elements: each rectangle cut
    into two CSTs along a diagonal (@p kind "CST", @p diagonal as in
    cst_triangles()) or a CSQ of four CSTs about a centre node (@p kind
    "CSQ"). The beam, the fixed end and the end load are
    thesis_cantilever()'s: the parabolic shear on x = 0 as forces
    consistent with the linear edges between its nodes (3 Gauss points
    per edge, exact for the cubic integrand). With an even @p ny the tip
    value is interpolated along the linear edge on x = 0. The 9 x 3 grid
    reproduces thesis_cantilever()'s CST and CSQ values; the thesis's
    refined meshes (§4.3.2) are 32 x 9 (CST: 288 nodes, 496 triangles)
    and 17 x 5 (CSQ: 85 nodes, 64 quadrilaterals)."""
    def at(i, j):
        return ny * i + j
    nodes = [(L * i / (nx - 1), -C + 2 * C * j / (ny - 1)) for i in range(nx) for j in range(ny)]
    elements = (quadrilaterals_of_four(nodes, nx, ny, at) if kind == "CSQ"
                else split_rectangles(nx, ny, at, diagonal))
    forces = [0.0] * (2 * len(nodes))
    inertia = 2 * C ** 3 / 3
    for j in range(ny - 1):
        y0, y1 = nodes[at(0, j)][1], nodes[at(0, j + 1)][1]
        for t, weight in GAUSS3:
            y = (y0 + y1) / 2 + (y1 - y0) / 2 * t
            traction = -P * (C * C - y * y) / (2 * inertia)
            for k, value in ((j, (1 - t) / 2), (j + 1, (1 + t) / 2)):
                forces[2 * at(0, k) + 1] += weight * (y1 - y0) / 2 * value * traction
    fixed = {2 * at(nx - 1, j) + d for j in range(ny) for d in range(2)}
    u = solve_triangles(nodes, elements, elasticity(strain), forces, fixed)
    below = (ny - 1) // 2
    s = -nodes[at(0, below)][1] / (nodes[at(0, below + 1)][1] - nodes[at(0, below)][1])
    tip = (1 - s) * u[2 * at(0, below) + 1] + s * u[2 * at(0, below + 1) + 1]
    beam = -P * L ** 3 / (3 * (E / (1 - NU * NU) if strain else E) * inertia)
    return tip, 100 * (tip / beam - 1)


def smallest_grid_within(kind, tolerance=5.0, strain=True, diagonal=0):
    """The thesis's redesign "until they gave results which fell within 5%
    of the analytic solution" (§4.3.2) on one family of grids: square
    cells (nx - 1 = 4 (ny - 1), as the thesis's 9 x 3 and 17 x 5 grids and
    near its 32 x 9) with a node on the neutral axis (ny odd), refined
    until |grid_cantilever()'s error| <= @p tolerance. Returns (nx, ny,
    nodes, elements, error): nodes of the grid (a CSQ's centre node is
    internal and not counted, as in the thesis's 85), elements as
    triangles for CST and quadrilaterals for CSQ."""
    ny = 3
    while True:
        nx = 4 * (ny - 1) + 1
        error = grid_cantilever(nx, ny, kind, strain, diagonal)[1]
        if abs(error) <= tolerance:
            cells = (nx - 1) * (ny - 1)
            return nx, ny, nx * ny, 2 * cells if kind == "CST" else cells, error
        ny += 2


def lithostatic_column_cst(diagonal=1, fixed_base=False, n=3):
    """The lithostatic column of §4.4.2 with the thesis's CST mesh: a
    10 km square on an @p n x @p n node grid (the thesis: 3 x 3 nodes,
    8 triangles, figure 4.14), each square cut along a diagonal as in
    cst_triangles() (1, the default: \\, gives the thesis's skew: the
    top left node subsides too far, the top right one too little); the
    column of tests/lithostatic_column/column.prm (E = 9e10 Pa, nu = 0.25,
    rho = 2800 kg/m^3, g = 9.81, plane strain), sides on vertical rollers,
    base on horizontal rollers (the thesis's and column.prm's; with
    @p fixed_base u_x is held there too), gravity as consistent nodal
    forces (a third of each triangle's weight at each vertex; forces
    lumped by tributary area give the exact nodal displacements and no
    skew). Returns the top surface's subsidence at the left and right
    edges in per cent of equation 4.4's 12.717 m, and per triangle
    (centroid x, y; rotation of the principal axes from horizontal and
    vertical, degrees; largest relative error of the two principal
    stresses, per cent), each triangle's constant stress against the
    exact one at its centroid (sigma_yy = rho g y, sigma_xx =
    nu/(1-nu) sigma_yy; the exact stress is linear, so this is also the
    triangle's mean), with the maxima over the triangles; and
    "magnitude_of_column", the largest error of either principal stress
    relative to the column's largest stress (rho g h at the base) instead
    of to its own exact value."""
    young, nu, rho, g, h = 9e10, 0.25, 2800.0, 9.81, 1e4
    D = elasticity(True, young, nu)

    def at(i, j):
        return n * i + j
    nodes = [(h * i / (n - 1), -h + h * j / (n - 1)) for i in range(n) for j in range(n)]
    elements = split_rectangles(n, n, at, diagonal)
    forces = [0.0] * (2 * len(nodes))
    for element in elements:
        area = linear_triangle([nodes[a] for a in element], D)[2]
        for a in element:
            forces[2 * a + 1] -= rho * g * area / 3
    fixed = {2 * at(i, j) for i in (0, n - 1) for j in range(n)}
    fixed |= {2 * at(i, 0) + d for i in range(n) for d in ((0, 1) if fixed_base else (1,))}
    u = solve_triangles(nodes, elements, D, forces, fixed)
    exact = (1 + nu) * (1 - 2 * nu) * rho * g * h * h / (2 * young * (1 - nu))
    per_element = []
    for element in elements:
        B = linear_triangle([nodes[a] for a in element], D)[1]
        ue = [u[2 * a + d] for a in element for d in range(2)]
        strain = [sum(B[r][k] * ue[k] for k in range(6)) for r in range(3)]
        sxx, syy, sxy = (sum(D[r][k] * strain[k] for k in range(3)) for r in range(3))
        x, y = (sum(nodes[a][k] for a in element) / 3 for k in range(2))
        exact_yy = rho * g * y
        exact_xx = nu / (1 - nu) * exact_yy
        angle = abs(math.degrees(0.5 * math.atan2(2 * sxy, sxx - syy))) % 90
        mean, radius = (sxx + syy) / 2, math.hypot((sxx - syy) / 2, sxy)
        error = max(abs((mean + radius) / exact_xx - 1), abs((mean - radius) / exact_yy - 1))
        per_element.append((x, y, min(angle, 90 - angle), 100 * error,
                            100 * max(abs(mean + radius - exact_xx),
                                      abs(mean - radius - exact_yy)) / (rho * g * h)))
    return {"left": -100 * u[2 * at(0, n - 1) + 1] / exact,
            "right": -100 * u[2 * at(n - 1, n - 1) + 1] / exact,
            "rotation": max(e[2] for e in per_element),
            "magnitude": max(e[3] for e in per_element),
            "magnitude_of_column": max(e[4] for e in per_element),
            "elements": per_element}


if __name__ == "__main__":
    for strain in (True, False):
        r = thesis_cantilever(strain)
        print("%s: " % ("plane strain" if strain else "plane stress") +
              "; ".join("%s %.5f (%.1f %% of beam theory)" % (k, v, 100 * v / r["beam"])
                        for k, v in r.items()))
    quads = [[node(2 * e + i, j) for j in range(3) for i in range(3)] for e in range(4)]
    for strain in (True, False):
        beam = -P * L ** 3 / (3 * (E / (1 - NU * NU) if strain else E) * 2 * C ** 3 / 3)
        results = [("Q2 4 x 1", tip_deflection(quads, q2, QUAD_RULE, strain))]
        for name, diagonal in (("P2, / diagonals", 0), ("P2, \\ diagonals", 1), ("P2, alternating", 2)):
            results.append((name, tip_deflection(triangles(diagonal), p2, TRIANGLE_RULE, strain)))
        print("%s: beam theory %.5f; " % ("plane strain" if strain else "plane stress", beam)
              + "; ".join("%s %.5f (%+.2f %%)" % (k, v, 100 * (v / beam - 1)) for k, v in results))

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
against beam theory -P l^3/(3 E I) (E' = E/(1 - nu^2) in plane strain).
Measured: plane strain beam -1.32141, Q2 -1.34115 (+1.49 %), P2 triangles
-1.30180 / -1.30180 / -1.30144 (-1.5 %); plane stress beam -1.50588, Q2
-1.54861 (+2.84 %), P2 -1.52596 (+1.33 %)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import solve_dense  # noqa: E402

P, L, C, E, NU = 5e4, 10.0, 1.25, 0.85e7, 0.35
NODES = [(1.25 * i, y) for y in (-C, 0.0, C) for i in range(9)]


def node(i, j):
    return 9 * j + i


def elasticity(strain):
    if strain:
        f = E / ((1 + NU) * (1 - 2 * NU))
        return [[f * (1 - NU), f * NU, 0], [f * NU, f * (1 - NU), 0], [0, 0, f * (1 - 2 * NU) / 2]]
    f = E / (1 - NU * NU)
    return [[f, f * NU, 0], [f * NU, f, 0], [0, 0, f * (1 - NU) / 2]]


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


def tip_deflection(elements, shape, rule, strain):
    n = 2 * len(NODES)
    K = [[0.0] * n for _ in range(n)]
    D = elasticity(strain)
    for element in elements:
        dofs = [2 * a + d for a in element for d in range(2)]
        for xi, eta, weight in rule:
            _, grads = shape(xi, eta)
            J = [[sum(g[r] * NODES[a][c] for g, a in zip(grads, element)) for c in range(2)] for r in range(2)]
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
    for t, weight in GAUSS3:  # t_y = -P (c^2 - y^2) / (2 I) on x = 0, quadratic edge
        y = C * t
        for j, value in enumerate([t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2]):
            f[2 * node(0, j) + 1] += weight * C * value * (-P * (C * C - y * y) / (2 * inertia))
    fixed = {2 * node(8, j) + d for j in range(3) for d in range(2)}
    free = [i for i in range(n) if i not in fixed]
    u = solve_dense([[K[i][j] for j in free] for i in free], [f[i] for i in free])
    return u[free.index(2 * node(0, 1) + 1)]


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


if __name__ == "__main__":
    quads = [[node(2 * e + i, j) for j in range(3) for i in range(3)] for e in range(4)]
    for strain in (True, False):
        beam = -P * L ** 3 / (3 * (E / (1 - NU * NU) if strain else E) * 2 * C ** 3 / 3)
        results = [("Q2 4 x 1", tip_deflection(quads, q2, QUAD_RULE, strain))]
        for name, diagonal in (("P2, / diagonals", 0), ("P2, \\ diagonals", 1), ("P2, alternating", 2)):
            results.append((name, tip_deflection(triangles(diagonal), p2, TRIANGLE_RULE, strain)))
        print("%s: beam theory %.5f; " % ("plane strain" if strain else "plane stress", beam)
              + "; ".join("%s %.5f (%+.2f %%)" % (k, v, 100 * (v / beam - 1)) for k, v in results))

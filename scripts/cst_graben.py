#!/usr/bin/python3
"""Mithen's (1980) constant-strain-triangle model of the plane normal fault
(thesis §6.1.6-§6.1.7): the graben widths that a CST mesh gives.

The thesis attributes Mithen's "constant graben width of 50-55 km for all
thicknesses of the elastic layer" (§6.1.7) to his CST meshes being too
stiff to model lithospheric flexure. lithostress has no triangles, so this
script solves the thesis's plane normal fault (§6.1.1, prm/normal_fault.prm)
with the dual node method of thesis §5.2 on constant strain triangles
(thesis §3.3.1), as Mithen did, on meshes from coarse to fine:

  - a 1000 km plate h thick (E = 0.85e11 Pa, nu = 0.25, plane strain, no
    body force), the left edge pulled by a horizontal tension, the right
    edge held horizontally, the base on a fluid of 2900 kg/m^3 (Winkler);
  - the fault from x = 500 km at the surface, dipping 63.43 degrees
    towards the right, its nodes doubled (thesis §5.2, figure 5.1) and
    joined by the thesis's element stiffnesses 5e10 and 1e15 N/m per
    element length l = h / (2 sin 63.43 deg) (as graben_widths.py), lumped
    on the nodes;
  - Coulomb friction mu = 0.1 on the effective normal stress, the normal
    spring's compression plus the lithostatic 2911 g d less the pore
    pressure 1000 g d (FSHEAR), solved exactly by an active set: a node
    slides where the spring's shear would exceed mu times that stress, and
    then carries mu times it, and is free where that stress is tensile
    (the friction takes the springs' traction, not Mithen's average of
    the two CSTs beside the fault: the point here is the elements'
    stiffness);
  - the columns nx across and the rows ny through the layer: each
    rectangle cut into two CSTs along its "/" diagonal (or "\\", or
    alternating), the columns sheared near the fault so that its nodes lie
    on it.

The graben width is the distance from the fault's surface trace to the
largest sigma_1 in the top row of triangles on the downthrown side (their
centroids, as the constant strain is the element's; also interpolated by
a parabola through the largest and its two neighbours).

Usage: cst_graben.py OUTDIR
runs the long-wavelength rows of table 6.3 (10 km at 50 MPa, 20 km at 60,
30 km at 80) and the 20 km layer at 50 MPa on 27 CST meshes of the
thesis's size (THESIS_SIZED_MESHES) and on a fine one (FINE_MESH), and
writes OUTDIR/cst_graben.csv:
  thickness_km,tension_MPa,columns,rows,diagonal,width_km,
  width_interpolated_km,throw_m,sliding_depth_km
and OUTDIR/cst_graben.png (the widths against the layer's thickness).
"""
import argparse
import csv
import math
import os

import numpy as np
import scipy.sparse
import scipy.sparse.linalg

# The plate, the fault's dip and the fluid base of graben_widths.py.
from graben_widths import DIP, E, G, NU, flexural_parameter
from graben_widths import RHO_F as RHO_FLUID

WIDTH, TRACE = 1000e3, 500e3
RHO_LITHOSTATIC, RHO_PORE = 2911.0, 1000.0
MU = 0.1
ELEMENT_SHEAR, ELEMENT_NORMAL = 5e10, 1e15
STICK, SLIDE, FREE = 0, 1, 2
SHEAR_ZONE = 60e3  # the columns within this distance of the trace are sheared


class PlateMesh:
    """Node grid of the plate with the fault's nodes doubled: columns
    0..nx, rows 0..ny (0 at the surface); the fault's column is nx / 2.
    Column j lies at x = x_j + w(x_j) * d / tan(dip) at depth d, with w
    falling linearly from 1 at the trace to 0 at SHEAR_ZONE from it."""

    def __init__(self, h, nx, ny, diagonal="/"):
        assert nx % 2 == 0, "the fault's trace must be a node column"
        self.h, self.nx, self.ny = h, nx, ny
        self.fault_column = nx // 2
        xs = np.linspace(0.0, WIDTH, nx + 1)
        depths = np.linspace(0.0, h, ny + 1)
        weight = np.clip(1.0 - np.abs(xs - TRACE) / SHEAR_ZONE, 0.0, 1.0)
        grid = [(x + w * d / math.tan(DIP), -d) for d in depths for x, w in zip(xs, weight)]
        self.nodes = np.array(grid)
        # The hanging wall's copies of the fault's nodes, one per row.
        self.twin = {i: len(grid) + i for i in range(ny + 1)}
        self.nodes = np.vstack([self.nodes, self.nodes[[self.at(self.fault_column, i)
                                                        for i in range(ny + 1)]]])
        self.triangles = self._triangles(diagonal)

    def at(self, j, i, hanging_wall=False):
        """Node of column j, row i (the hanging wall's copy on the fault)."""
        if hanging_wall and j == self.fault_column:
            return self.twin[i]
        return i * (self.nx + 1) + j

    def _triangles(self, diagonal):
        triangles = []
        for i in range(self.ny):
            for j in range(self.nx):
                right = j >= self.fault_column
                a, b = self.at(j, i, right), self.at(j + 1, i, right)
                c, d = self.at(j + 1, i + 1, right), self.at(j, i + 1, right)
                slash = diagonal == "/" or (diagonal == "alternating" and (i + j) % 2 == 0)
                triangles += [[d, b, a], [d, c, b]] if slash else [[a, d, c], [a, c, b]]
        return np.array(triangles)

    def top_row(self, side):
        """Triangles with an edge on the surface on the downthrown
        (@p side > 0: right) side of the fault."""
        centroids = self.nodes[self.triangles].mean(axis=1)
        on_top = [t for t, tri in enumerate(self.triangles)
                  if sum(self.nodes[tri, 1] > -1e-6) == 2 and side * (centroids[t, 0] - TRACE) > 0]
        return sorted(on_top, key=lambda t: centroids[t, 0])


def elasticity():
    """Plane-strain elasticity matrix (thesis eq. 3.9)."""
    f = E / ((1 + NU) * (1 - 2 * NU))
    return f * np.array([[1 - NU, NU, 0.0], [NU, 1 - NU, 0.0], [0.0, 0.0, (1 - 2 * NU) / 2]])


def strain_matrices(mesh):
    """B (t x 3 x 6) and areas of the constant strain triangles (thesis
    §3.3.1)."""
    p = mesh.nodes[mesh.triangles]
    x, y = p[:, :, 0], p[:, :, 1]
    twice = (x[:, 1] - x[:, 0]) * (y[:, 2] - y[:, 0]) - (x[:, 2] - x[:, 0]) * (y[:, 1] - y[:, 0])
    assert np.all(twice > 0), "triangles must be anticlockwise"
    b = np.stack([y[:, 1] - y[:, 2], y[:, 2] - y[:, 0], y[:, 0] - y[:, 1]], axis=1) / twice[:, None]
    c = np.stack([x[:, 2] - x[:, 1], x[:, 0] - x[:, 2], x[:, 1] - x[:, 0]], axis=1) / twice[:, None]
    B = np.zeros((len(p), 3, 6))
    B[:, 0, 0::2], B[:, 1, 1::2], B[:, 2, 0::2], B[:, 2, 1::2] = b, c, c, b
    return B, twice / 2


class CSTFaultModel:
    """The plane normal fault of thesis §6.1.1 on a CST mesh with the dual
    node fault of thesis §5.2 and exact Coulomb friction."""

    def __init__(self, mesh, tension, stiffness_length, mu=MU,
                 element_stiffnesses=(ELEMENT_SHEAR, ELEMENT_NORMAL)):
        self.mesh, self.tension, self.mu = mesh, tension, mu
        self.D = elasticity()
        self.B, self.area = strain_matrices(mesh)
        n = 2 * len(mesh.nodes)
        self.n = n
        self.K, self.f = self._elastic_system()
        self.tangent = np.array([math.cos(DIP), -math.sin(DIP)])  # down the fault
        self.normal = np.array([math.sin(DIP), math.cos(DIP)])  # into the hanging wall
        self.fault_pairs = [(mesh.at(mesh.fault_column, i), mesh.twin[i]) for i in range(mesh.ny + 1)]
        length = mesh.h / math.sin(DIP) / mesh.ny
        self.tributary = np.array([length / (2 if i in (0, mesh.ny) else 1)
                                   for i in range(mesh.ny + 1)])
        self.ks = element_stiffnesses[0] / stiffness_length * self.tributary
        self.kn = element_stiffnesses[1] / stiffness_length * self.tributary
        self.depth = -mesh.nodes[[a for a, _ in self.fault_pairs], 1]
        self.overburden = (RHO_LITHOSTATIC - RHO_PORE) * G * self.depth

    def _elastic_system(self):
        mesh = self.mesh
        dofs = np.repeat(2 * mesh.triangles, 2, axis=1) + np.tile([0, 1], 3)
        local = np.einsum("tki,kl,tlj,t->tij", self.B, self.D, self.B, self.area)
        rows = np.repeat(dofs, 6, axis=1).ravel()
        cols = np.tile(dofs, (1, 6)).ravel()
        K = scipy.sparse.coo_matrix((local.ravel(), (rows, cols)), shape=(self.n, self.n)).tolil()
        f = np.zeros(self.n)
        # The fluid base: a pressure rho_f g (-u_y) on its linear edges.
        for j in range(mesh.nx):
            right = j >= mesh.fault_column
            a, b = mesh.at(j, mesh.ny, right), mesh.at(j + 1, mesh.ny, right)
            edge = abs(mesh.nodes[b, 0] - mesh.nodes[a, 0])
            k = RHO_FLUID * G * edge / 6
            for p, q, w in ((a, a, 2), (b, b, 2), (a, b, 1), (b, a, 1)):
                K[2 * p + 1, 2 * q + 1] += w * k
        # The left edge pulled by the tension (tension positive).
        for i in range(mesh.ny):
            dy = mesh.h / mesh.ny
            for node in (mesh.at(0, i), mesh.at(0, i + 1)):
                f[2 * node] -= self.tension * dy / 2
        return K.tocsr(), f

    def _fault_matrix(self, state, signs):
        """Springs and friction of the fault's node pairs: the normal spring
        always; the shear spring where the pair sticks (STICK); where it
        slides (SLIDE), the traction mu (overburden - kn g) sign along the
        fault, linear in the opening g (its constant part is returned as a
        force); nothing where the effective normal force is tensile (FREE)."""
        rows, cols, vals = [], [], []
        force = np.zeros(self.n)
        for m, (a, b) in enumerate(self.fault_pairs):
            jump = {2 * b: 1.0, 2 * b + 1: 1.0, 2 * a: -1.0, 2 * a + 1: -1.0}
            t = {d: s * self.tangent[d % 2] for d, s in jump.items()}
            nn = {d: s * self.normal[d % 2] for d, s in jump.items()}
            for p in nn:
                for q in nn:
                    rows.append(p), cols.append(q), vals.append(self.kn[m] * nn[p] * nn[q])
                    if state[m] == STICK:
                        rows.append(p), cols.append(q), vals.append(self.ks[m] * t[p] * t[q])
            if state[m] == SLIDE:
                for p in t:
                    force[p] -= t[p] * self.mu * signs[m] * self.overburden[m] * self.tributary[m]
                    for q in nn:
                        rows.append(p), cols.append(q)
                        vals.append(-t[p] * self.mu * signs[m] * self.kn[m] * nn[q])
        return scipy.sparse.coo_matrix((vals, (rows, cols)), shape=(self.n, self.n)), force

    def fault_state(self, u):
        """Slip, opening, spring shear force and effective normal force of
        each fault node pair [m, m, N, N]."""
        slip, opening = [], []
        for a, b in self.fault_pairs:
            jump = u[2 * b:2 * b + 2] - u[2 * a:2 * a + 2]
            slip.append(jump @ self.tangent), opening.append(jump @ self.normal)
        slip, opening = np.array(slip), np.array(opening)
        return slip, opening, self.ks * slip, self.overburden * self.tributary - self.kn * opening

    def solve(self, max_iterations=100):
        """Displacements with exact Coulomb friction on the fault (active
        set: each node pair sticks, slides or is free, until the sets
        repeat)."""
        fixed = [2 * self.mesh.at(self.mesh.nx, i) for i in range(self.mesh.ny + 1)]
        free = np.setdiff1d(np.arange(self.n), fixed)
        state = np.full(len(self.fault_pairs), STICK)
        signs = np.zeros(len(self.fault_pairs))
        for _ in range(max_iterations):
            Kf, ff = self._fault_matrix(state, signs)
            A = (self.K + Kf).tocsr()[free][:, free]
            u = np.zeros(self.n)
            u[free] = scipy.sparse.linalg.spsolve(A.tocsc(), (self.f + ff)[free])
            slip, _, shear, normal = self.fault_state(u)
            new_state, new_signs = state.copy(), signs.copy()
            for m in range(len(state)):
                if normal[m] <= 0:
                    new_state[m] = FREE
                elif state[m] == SLIDE:
                    new_state[m] = SLIDE if signs[m] * slip[m] > 0 else STICK
                elif state[m] == FREE or abs(shear[m]) > self.mu * normal[m]:
                    new_state[m], new_signs[m] = SLIDE, np.sign(slip[m])
            if np.array_equal(new_state, state) and np.array_equal(new_signs, signs):
                self.state = state
                return u
            state, signs = new_state, new_signs
        raise RuntimeError("the fault's stick-slip set did not settle in %d iterations"
                           % max_iterations)

    def stresses(self, u):
        """sigma_xx, sigma_yy, sigma_xy of each triangle (tension positive)."""
        dofs = np.repeat(2 * self.mesh.triangles, 2, axis=1) + np.tile([0, 1], 3)
        strain = np.einsum("tij,tj->ti", self.B, u[dofs])
        return strain @ self.D.T


def largest_principal(sigma):
    """In-plane sigma_1 (tension positive) of each row [sxx, syy, sxy]."""
    centre = (sigma[:, 0] + sigma[:, 1]) / 2
    radius = np.hypot((sigma[:, 0] - sigma[:, 1]) / 2, sigma[:, 2])
    return centre + radius


def graben_width(model, u):
    """Distance from the trace to the largest sigma_1 of the top row of
    triangles on the downthrown side [m]: at that triangle's centroid, and
    interpolated by a parabola through it and its neighbours."""
    top = model.mesh.top_row(+1)
    x = model.mesh.nodes[model.mesh.triangles[top]].mean(axis=1)[:, 0] - TRACE
    s1 = largest_principal(model.stresses(u)[top])
    k = int(np.argmax(s1))
    if 0 < k < len(top) - 1:
        (xa, xb, xc), (fa, fb, fc) = x[k - 1:k + 2], s1[k - 1:k + 2]
        denominator = (xb - xa) * (fb - fc) - (xb - xc) * (fb - fa)
        if denominator != 0:
            shift = ((xb - xa) ** 2 * (fb - fc) - (xb - xc) ** 2 * (fb - fa)) / (2 * denominator)
            return x[k], xb - shift
    return x[k], x[k]


def run_case(h_km, tension_mpa, nx, ny, diagonal="/"):
    """One model: (width, interpolated width [km], throw [m], sliding depth
    [km])."""
    h = h_km * 1e3
    mesh = PlateMesh(h, nx, ny, diagonal)
    model = CSTFaultModel(mesh, tension_mpa * 1e6, h / (2 * math.sin(DIP)))
    u = model.solve()
    width, interpolated = graben_width(model, u)
    a, b = model.fault_pairs[0]
    throw = u[2 * a + 1] - u[2 * b + 1]
    depth = max((d for d, s in zip(model.depth, model.state) if s != STICK), default=0.0)
    return width / 1e3, interpolated / 1e3, throw, depth / 1e3


# The long-wavelength rows of table 6.3 (sliding reaches the base), one
# tension per layer thickness [km: MPa].
LONG_WAVELENGTH = {10: 50, 20: 60, 30: 80}
# CST meshes of the thesis's size: 17-25 km columns (the thesis's nodes lie
# 20 km apart if its 100 six-node triangles form 25 columns of two rows,
# doc/faults.md), one to four rows, each diagonal pattern.
THESIS_SIZED_MESHES = [(nx, ny, d) for nx in (40, 50, 60) for ny in (1, 2, 4)
                       for d in ("/", "\\", "alternating")]
# The thesis's nodes as CSTs: 51 x 5 nodes.
THESIS_NODES_MESH = (50, 4, "/")
# A fine mesh: 312.5 m columns, rows of 1/16 of the layer.
FINE_MESH = (3200, 16, "/")


def mithen_comparison():
    """Graben widths of the long-wavelength rows and the 20 km layer's throw
    at 50 MPa on every thesis-sized mesh and on the fine mesh:
    [(mesh, thickness_km, tension_MPa, width, interpolated width, throw,
    sliding depth)]."""
    rows = []
    for mesh in THESIS_SIZED_MESHES + [FINE_MESH]:
        for h, tension in sorted(LONG_WAVELENGTH.items()) + [(20, 50)]:
            rows.append((mesh, h, tension) + run_case(h, tension, *mesh))
    return rows


def write_comparison(rows, path):
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["thickness_km", "tension_MPa", "columns", "rows", "diagonal", "width_km",
                         "width_interpolated_km", "throw_m", "sliding_depth_km"])
        for (nx, ny, d), h, tension, width, interpolated, throw, depth in rows:
            writer.writerow([h, tension, nx, ny, d, "%.2f" % width, "%.2f" % interpolated,
                             "%.1f" % throw, "%.2f" % depth])


def plot_comparison(rows, path):
    """Widths against layer thickness: every thesis-sized CST mesh, the
    fine CST mesh, the thin plate's pi alpha / 4 + h / 2 and Mithen's
    50-55 km."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.axhspan(50, 55, color="tab:red", alpha=0.15, label="Mithen (1980): 50-55 km")
    thick = sorted(LONG_WAVELENGTH)
    markers = {1: "v", 2: "o", 4: "^"}
    for ny, marker in markers.items():
        points = [(r[1] + (r[0][0] - 50) / 40, r[3]) for r in rows
                  if r[0] != FINE_MESH and r[0][1] == ny and LONG_WAVELENGTH.get(r[1]) == r[2]]
        ax.plot(*zip(*points), marker, color="tab:grey", mfc="none", ms=5,
                label="thesis-sized CST meshes, %d row%s" % (ny, "s" if ny > 1 else ""))
    fine = [r[3] for h in thick for r in rows if r[0] == FINE_MESH and r[1:3] == (h, LONG_WAVELENGTH[h])]
    ax.plot(thick, fine, "s-", color="tab:blue", label="fine CST mesh (converged)")
    h = np.linspace(8, 32, 50)
    plate = [math.pi * flexural_parameter(x * 1e3) / 4e3 + x / 2 for x in h]
    ax.plot(h, plate, "k--", lw=0.8, label="thin plate: pi alpha / 4 + h / 2")
    ax.set_xlabel("elastic layer thickness [km] (meshes of 40, 50, 60 columns left to right)")
    ax.set_ylabel("graben width [km]")
    ax.set_title("Graben widths on constant strain triangles (thesis §6.1.7)", fontsize=10)
    ax.set_xticks(thick)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    rows = mithen_comparison()
    path = os.path.join(args.outdir, "cst_graben.csv")
    write_comparison(rows, path)
    plot_comparison(rows, os.path.join(args.outdir, "cst_graben.png"))
    for h, tension in sorted(LONG_WAVELENGTH.items()):
        coarse = [r[3] for r in rows if r[1] == h and r[2] == tension and r[0] != FINE_MESH]
        fine = [r[3] for r in rows if r[1] == h and r[2] == tension and r[0] == FINE_MESH][0]
        print("%d km, %d MPa: width %.1f-%.1f km on %d thesis-sized CST meshes, %.1f km on the "
              "fine mesh" % (h, tension, min(coarse), max(coarse), len(coarse), fine))
    print("wrote", path)


if __name__ == "__main__":
    main()

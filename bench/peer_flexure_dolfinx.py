#!/usr/bin/python3
"""Peer reference for the lithostress flexure benchmark: FEniCSx dolfinx
0.5.2 (Debian bookworm's python3-dolfinx) with PETSc CG + GAMG.

What it measures
  The same problem that bench/run times as "flexure" (prm/flexure.prm), solved
  by a generic finite-element library with an off-the-shelf algebraic
  multigrid, on the same machine and the same day:
    * a 1000 km x 20 km plate, x in [0, 1e6] m, y in [-2e4, 0] m, plane strain
      linear elasticity, E = 0.85e11 Pa, nu = 0.25, no body force;
    * structured quadrilateral mesh of NX x NY cells, vector Q2 elements
      (2000 x 40 cells = 648,162 DoFs, the size the figures are compared at);
    * left and right edges on vertical rollers (u_x = 0, u_y free);
    * a Winkler foundation on the base, int_base k u_y v_y ds with
      k = 2900 * 9.81 Pa/m;
    * a line load of (0, -2e12) N/m at the top centre (5e5, 0), added to
      the assembled right-hand side at that vertex's y-DoF;
    * PETSc CG with PCGAMG, the three 2-D rigid-body modes as near null
      space, block size 2, stopping at ||r||_2 <= 1e-10 ||b||_2 on the
      unpreconditioned residual (deal.II's SolverControl rule in lithostress).
  Element integrals use 3 x 3 Gauss points (quadrature degree 4), as
  lithostress does (QGauss(degree + 1)); on this rectangular mesh that is
  exact.  FFCx would otherwise pick 4 x 4 (--quadrature-degree auto).

Why
  It is the "peer" of bench/run: it exists only to normalise the benchmark
  figures of lithostress against a generic FE library + PETSc GAMG run on
  the same machine at the same time. It is not part of the test suite and
  nothing in the build depends on it.

Timings (wall clock, time.perf_counter, MPI barriers before each stamp):
  setup_s               mesh + vector Q2 function space + boundary DoFs +
                        matrix/vector creation (sparsity, preallocation)
  assemble_s            matrix and right-hand side assembly, Dirichlet
                        rows, point load
  near_nullspace_s      building the three rigid-body-mode vectors
  preconditioner_setup_s  KSPSetUp (GAMG hierarchy, smoother set-up)
  solve_s               KSPSolve
  total_s               from the start of mesh creation to the solution,
                        minus jit_s
  jit_s                 dolfinx.fem.form on the benchmark mesh (FFCx cache
                        is warm: the same forms are first compiled on a
                        4 x 2 mesh, whose time is jit_warmup_s)
  matvec_ms             one product with the assembled matrix (mean of 20),
                        measured after the solve, outside total_s
Memory: peak_rss_mb = ru_maxrss summed over ranks (as lithostress does);
baseline_rss_mb = the same right after the imports.

Check against thin-plate theory (D = E h^3/(12(1-nu^2)), alpha =
(4D/k)^(1/4), w0 = P alpha^3/(8D)): u_y under the load (a logarithmic
singularity of 2-D elasticity: it grows slowly under refinement and is
~11-13 % larger than w0), u_y 200 km and alpha from the load (theory
-w0 e^{-x/alpha}(cos + sin)), and the forebulge crest (found among the top
surface nodes; theory: x = pi alpha, height w0 e^{-pi}). Thin-plate theory
neglects shear deformation (~3.7 % here, doc/verification.md section 8), so
expect the far field within ~5 %.

Usage (one JSON line on stdout, a readable summary on stderr):
  nice -n 10 /usr/bin/python3 bench/peer_flexure_dolfinx.py [--refine K |
      --cells NX,NY] [--quadrature-degree 4|auto] [--view]
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \\
      mpirun -np 2 /usr/bin/python3 bench/peer_flexure_dolfinx.py
--refine K means NX = 250 * 2^K, NY = 5 * 2^K (K = 3 is the default
2000 x 40). Further PETSc options can be given through PETSC_OPTIONS with
the prefix "peer_" (e.g. PETSC_OPTIONS="-peer_pc_gamg_threshold 0.01");
they take precedence over the ones this script sets.
Needs: apt-get install -y python3-dolfinx (run with /usr/bin/python3).
"""
import argparse
import json
import logging
import math
import os
import resource
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import ufl  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

import dolfinx  # noqa: E402
import dolfinx.fem.petsc  # noqa: E402
from dolfinx import fem, geometry, la, mesh  # noqa: E402

# Problem data (SI units).
LENGTH = 1.0e6
THICKNESS = 2.0e4
E_MODULUS = 0.85e11
POISSON = 0.25
K_WINKLER = 2900.0 * 9.81
LINE_LOAD = 2.0e12            # N/m, downward
LOAD_X = 5.0e5
PROBE_DISTANCE = 2.0e5        # the "200 km" check point, measured from the load
RTOL = 1.0e-10
PREFIX = "peer_"
# Options this script sets: the first four are the choices, the rest are
# PETSc 3.18's defaults, written out so that the run records them.
PETSC_SETTINGS = {
    "ksp_type": "cg",
    "ksp_norm_type": "unpreconditioned",
    "ksp_rtol": RTOL,
    "pc_type": "gamg",
    "ksp_max_it": 10000,
    "pc_gamg_type": "agg",
    "mg_levels_ksp_type": "chebyshev",
    "mg_levels_pc_type": "jacobi",
}


def rss_mb(comm):
    """ru_maxrss of this process in MiB, summed over the ranks."""
    return comm.allreduce(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, op=MPI.SUM)


def thin_plate():
    """Flexural rigidity, flexural parameter, deflection under the load."""
    rigidity = E_MODULUS * THICKNESS ** 3 / (12.0 * (1.0 - POISSON ** 2))
    alpha = (4.0 * rigidity / K_WINKLER) ** 0.25
    w0 = LINE_LOAD * alpha ** 3 / (8.0 * rigidity)
    return rigidity, alpha, w0


def thin_plate_uy(distance, alpha, w0):
    """Vertical displacement (positive up) at @distance from the load."""
    s = abs(distance) / alpha
    return -w0 * math.exp(-s) * (math.cos(s) + math.sin(s))


class Problem:
    """Mesh, space, boundary conditions and forms for an NX x NY mesh."""

    def __init__(self, comm, nx, ny, quadrature_degree, stamp):
        self.comm = comm
        # --- mesh and function space -------------------------------------
        self.mesh = mesh.create_rectangle(
            comm, [np.array([0.0, -THICKNESS]), np.array([LENGTH, 0.0])], [nx, ny],
            cell_type=mesh.CellType.quadrilateral, ghost_mode=mesh.GhostMode.none)
        stamp("mesh")
        self.V = fem.VectorFunctionSpace(self.mesh, ("Lagrange", 2))
        stamp("space")
        msh, V = self.mesh, self.V
        tdim = msh.topology.dim
        fdim = tdim - 1
        msh.topology.create_connectivity(fdim, tdim)
        h_x = LENGTH / nx
        tol_x, tol_y = 1e-6 * h_x, 1e-6 * THICKNESS / ny
        ends = mesh.locate_entities_boundary(
            msh, fdim, lambda x: np.isclose(x[0], 0.0, atol=tol_x) | np.isclose(x[0], LENGTH, atol=tol_x))
        base = mesh.locate_entities_boundary(msh, fdim, lambda x: np.isclose(x[1], -THICKNESS, atol=tol_y))
        base = np.sort(base).astype(np.int32)
        self.base_tags = mesh.meshtags(msh, fdim, base, np.full(base.size, 1, dtype=np.int32))
        # Rollers: u_x = 0 on both ends (only the x-component sub-space).
        roller_dofs = fem.locate_dofs_topological(V.sub(0), fdim, ends)
        self.bc = fem.dirichletbc(PETSc.ScalarType(0.0), roller_dofs, V.sub(0))
        # The y-DoF of the load vertex (local index in the blocked space).
        load_vertex = mesh.locate_entities_boundary(
            msh, 0, lambda x: np.isclose(x[0], LOAD_X, atol=tol_x) & np.isclose(x[1], 0.0, atol=tol_y))
        self.load_dofs = fem.locate_dofs_topological(V.sub(1), 0, load_vertex)
        n_load = comm.allreduce(int(np.count_nonzero(
            self.load_dofs < V.dofmap.index_map.size_local * V.dofmap.index_map_bs)), op=MPI.SUM)
        if n_load != 1:
            raise SystemExit("the load point (%g, 0) is not a mesh vertex for NX=%d" % (LOAD_X, nx))
        stamp("boundary")
        # --- forms ---------------------------------------------------------
        lmbda = fem.Constant(msh, PETSc.ScalarType(
            E_MODULUS * POISSON / ((1.0 + POISSON) * (1.0 - 2.0 * POISSON))))
        mu = fem.Constant(msh, PETSc.ScalarType(E_MODULUS / (2.0 * (1.0 + POISSON))))
        k = fem.Constant(msh, PETSc.ScalarType(K_WINKLER))
        body_force = fem.Constant(msh, PETSc.ScalarType((0.0, 0.0)))
        md = {} if quadrature_degree is None else {"quadrature_degree": quadrature_degree}
        dx = ufl.Measure("dx", domain=msh, metadata=md)
        ds = ufl.Measure("ds", domain=msh, subdomain_data=self.base_tags, metadata=md)
        u, v = ufl.TrialFunction(V), ufl.TestFunction(V)

        def strain(w):
            return ufl.sym(ufl.grad(w))

        def stress(w):
            return 2.0 * mu * strain(w) + lmbda * ufl.tr(strain(w)) * ufl.Identity(2)

        self.a_ufl = ufl.inner(stress(u), strain(v)) * dx + k * u[1] * v[1] * ds(1)
        self.L_ufl = ufl.inner(body_force, v) * dx

    def compile_forms(self):
        self.a = fem.form(self.a_ufl)
        self.L = fem.form(self.L_ufl)

    def create_system(self):
        self.A = fem.petsc.create_matrix(self.a)
        self.b = fem.petsc.create_vector(self.L)

    def assemble(self):
        A, b = self.A, self.b
        A.zeroEntries()
        fem.petsc.assemble_matrix(A, self.a, bcs=[self.bc])
        A.assemble()
        with b.localForm() as b_local:
            b_local.set(0.0)
        fem.petsc.assemble_vector(b, self.L)
        fem.petsc.apply_lifting(b, [self.a], bcs=[[self.bc]])
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        fem.petsc.set_bc(b, [self.bc])
        # Point load, on the owning rank only (b.array is the owned part).
        n_owned = self.V.dofmap.index_map.size_local * self.V.dofmap.index_map_bs
        owned = self.load_dofs[self.load_dofs < n_owned]
        if owned.size:
            b.array_w[owned] += -LINE_LOAD

    def near_nullspace(self):
        """Two translations and the in-plane rotation, orthonormalised."""
        V = self.V
        index_map, bs = V.dofmap.index_map, V.dofmap.index_map_bs
        n = index_map.size_local
        x = V.tabulate_dof_coordinates()[:n]
        # Rotate about the plate centre: keeps the mode well scaled.
        xc, yc = x[:, 0] - 0.5 * LENGTH, x[:, 1] + 0.5 * THICKNESS
        modes = [la.create_petsc_vector(index_map, bs) for _ in range(3)]
        with modes[0].localForm() as m0, modes[1].localForm() as m1, modes[2].localForm() as m2:
            m0.set(0.0)
            m1.set(0.0)
            m2.set(0.0)
            m0.array_w[0:bs * n:bs] = 1.0
            m1.array_w[1:bs * n:bs] = 1.0
            m2.array_w[0:bs * n:bs] = -yc
            m2.array_w[1:bs * n:bs] = xc
        la.orthonormalize(modes)
        assert la.is_orthonormal(modes, eps=1e-8)
        return PETSc.NullSpace().create(vectors=modes, comm=self.comm)


def set_options():
    opts = PETSc.Options()
    for key, value in PETSC_SETTINGS.items():
        if not opts.hasName(PREFIX + key):      # PETSC_OPTIONS wins
            opts[PREFIX + key] = value


def options_in_use():
    """All PETSc options with this script's prefix (set here or by the user)."""
    return {key[len(PREFIX):]: value for key, value in sorted(PETSc.Options().getAll().items())
            if key.startswith(PREFIX)}


def warm_up(comm, quadrature_degree):
    """Compile the element and the forms on a tiny mesh (fills FFCx cache).

    Twice: with a cold cache, compiling the first form of a mesh changes
    that mesh's UFL coordinate element in place (FFCx 0.5 marks it
    variant='equispaced'), so forms compiled after it get other signatures
    than they have on a fresh mesh whose forms are all found in the cache.
    The second round is in exactly the state of the timed run."""
    for _ in range(2):
        problem = Problem(comm, 4, 2, quadrature_degree, lambda name: None)
        problem.compile_forms()


def evaluate_uy(problem, u, xs):
    """u_y at points (x, 0) on the top surface, valid on every rank."""
    msh = problem.mesh
    points = np.array([[x, 0.0, 0.0] for x in xs], dtype=np.float64)
    tree = geometry.BoundingBoxTree(msh, msh.topology.dim)
    candidates = geometry.compute_collisions(tree, points)
    colliding = geometry.compute_colliding_cells(msh, candidates, points)
    local = np.full(len(xs), np.nan)
    for i in range(len(xs)):
        cells = colliding.links(i)
        if len(cells) > 0:
            local[i] = np.reshape(u.eval(points[i:i + 1], cells[:1]), -1)[1]
    result = np.full(len(xs), np.nan)
    for values in problem.comm.allgather(local):
        missing = np.isnan(result)
        result[missing] = values[missing]
    return result


def forebulge_crest(problem, u):
    """Largest upward u_y among the top-surface nodes: (x, u_y)."""
    V = problem.V
    n = V.dofmap.index_map.size_local
    bs = V.dofmap.index_map_bs
    x = V.tabulate_dof_coordinates()[:n]
    top = np.flatnonzero(np.isclose(x[:, 1], 0.0, atol=1e-6 * THICKNESS))
    uy = u.x.array[bs * top + 1]
    best = (-np.inf, np.nan)
    if top.size:
        i = int(np.argmax(uy))
        best = (float(uy[i]), float(x[top[i], 0]))
    gathered = problem.comm.allgather(best)
    uy_max, x_max = max(gathered, key=lambda p: p[0])
    return x_max, uy_max


def main():
    comm = MPI.COMM_WORLD
    baseline_rss = rss_mb(comm)

    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--cells", default=None, help="NX,NY (default 2000,40)")
    group.add_argument("--refine", type=int, default=None, help="NX = 250*2^K, NY = 5*2^K")
    parser.add_argument("--quadrature-degree", default="4",
                        help="quadrature degree of the cell and base integrals: 4 = 3x3 Gauss "
                             "(default, as lithostress), 'auto' = FFCx's estimate (4x4)")
    parser.add_argument("--view", action="store_true", help="print KSPView to stderr after the solve")
    args = parser.parse_args()
    if args.refine is not None:
        nx, ny = 250 * 2 ** args.refine, 5 * 2 ** args.refine
    else:
        nx, ny = (int(s) for s in (args.cells or "2000,40").split(","))
    qdeg = None if args.quadrature_degree == "auto" else int(args.quadrature_degree)
    rank0 = comm.rank == 0

    def log(*items):
        if rank0:
            print(*items, file=sys.stderr, flush=True)

    # JIT warm-up: not part of any timing below (quiet the compiler's log).
    logging.getLogger().setLevel(logging.WARNING)
    t = time.perf_counter()
    warm_up(comm, qdeg)
    comm.Barrier()
    jit_warmup = time.perf_counter() - t

    stamps = {}

    def stamp(name):
        comm.Barrier()
        stamps[name] = time.perf_counter()

    set_options()
    stamp("start")
    problem = Problem(comm, nx, ny, qdeg, stamp)
    stamp("forms_start")
    problem.compile_forms()
    stamp("forms")
    problem.create_system()
    stamp("setup")
    problem.assemble()
    stamp("assemble")
    A = problem.A
    if A.getBlockSize() != 2:       # dolfinx 0.5 takes it from the blocked dofmap
        raise SystemExit("expected a matrix with block size 2, got %d" % A.getBlockSize())
    A.setNearNullSpace(problem.near_nullspace())
    stamp("nullspace")
    ksp = PETSc.KSP().create(comm)
    ksp.setOptionsPrefix(PREFIX)
    ksp.setOperators(A)
    ksp.setFromOptions()
    u = fem.Function(problem.V)
    ksp.setUp()
    stamp("pc_setup")
    ksp.solve(problem.b, u.vector)
    stamp("solve")
    u.x.scatter_forward()

    jit = stamps["forms"] - stamps["forms_start"]
    times = {
        "setup_s": stamps["setup"] - stamps["start"] - jit,
        "assemble_s": stamps["assemble"] - stamps["setup"],
        "near_nullspace_s": stamps["nullspace"] - stamps["assemble"],
        "preconditioner_setup_s": stamps["pc_setup"] - stamps["nullspace"],
        "solve_s": stamps["solve"] - stamps["pc_setup"],
        "total_s": stamps["solve"] - stamps["start"] - jit,
        "jit_s": jit,
        "jit_warmup_s": jit_warmup,
        "setup_phases": {"mesh_s": stamps["mesh"] - stamps["start"],
                         "function_space_s": stamps["space"] - stamps["mesh"],
                         "boundary_s": stamps["boundary"] - stamps["space"],
                         "matrix_vector_creation_s": stamps["setup"] - stamps["forms"]},
    }
    times["pc_setup_plus_solve_s"] = times["preconditioner_setup_s"] + times["solve_s"]
    peak_rss = rss_mb(comm)
    peak_rss_max_rank = comm.allreduce(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
                                       op=MPI.MAX)

    # --- after the clock: residual, one matvec, checks --------------------
    options = options_in_use()
    reason = ksp.getConvergedReason()
    iterations = ksp.getIterationNumber()
    b = problem.b
    r = b.duplicate()
    A.mult(u.vector, r)
    r.aypx(-1.0, b)                      # r = b - A u
    b_norm = b.norm()
    rel_residual = r.norm() / b_norm
    y = b.duplicate()
    A.mult(u.vector, y)
    comm.Barrier()
    t = time.perf_counter()
    n_mult = 20
    for _ in range(n_mult):
        A.mult(u.vector, y)
    comm.Barrier()
    matvec_ms = 1e3 * (time.perf_counter() - t) / n_mult
    if args.view:
        viewer = PETSc.Viewer.STDERR(comm)
        ksp.view(viewer)

    rigidity, alpha, w0 = thin_plate()
    xs = [LOAD_X, LOAD_X + PROBE_DISTANCE, LOAD_X - PROBE_DISTANCE, LOAD_X + math.pi * alpha,
          LOAD_X + alpha]
    uy_load, uy_200, uy_200_left, uy_pi_alpha, uy_alpha = evaluate_uy(problem, u, xs)
    crest_x, crest_uy = forebulge_crest(problem, u)
    tp_load = thin_plate_uy(0.0, alpha, w0)
    tp_200 = thin_plate_uy(PROBE_DISTANCE, alpha, w0)
    tp_alpha = thin_plate_uy(alpha, alpha, w0)
    tp_crest = w0 * math.exp(-math.pi)

    def rel(fe, theory):
        """FE / theory - 1: > 0 where the FE displacement is larger."""
        return fe / theory - 1.0

    index_map = problem.V.dofmap.index_map
    result = {
        "problem": "flexure",
        "library": "dolfinx-%s petsc gamg" % dolfinx.__version__,
        "petsc": "%d.%d.%d" % PETSc.Sys.getVersion(),
        "dofs": index_map.size_global * problem.V.dofmap.index_map_bs,
        "cells": nx * ny,
        "mesh": [nx, ny],
        "ranks": comm.size,
        "iterations": iterations,
        "converged_reason": int(reason),
        "relative_residual": rel_residual,
        "matrix_block_size": A.getBlockSize(),
        "quadrature_degree": "auto" if qdeg is None else qdeg,
    }
    phases = times.pop("setup_phases")
    result.update(times)
    result.update({
        "matvec_ms": matvec_ms,
        "peak_rss_mb": peak_rss,
        "peak_rss_max_rank_mb": peak_rss_max_rank,
        "baseline_rss_mb": baseline_rss,
        "setup_phases": phases,
        "uy_load": uy_load,
        "uy_200km": uy_200,
        "uy_200km_left": uy_200_left,
        "uy_alpha": uy_alpha,
        "uy_pi_alpha": uy_pi_alpha,
        "forebulge_x_km": abs(crest_x - LOAD_X) / 1e3,
        "uy_forebulge": crest_uy,
        "thin_plate": {"D": rigidity, "alpha_m": alpha, "w0": w0,
                       "uy_load": tp_load, "uy_200km": tp_200, "uy_alpha": tp_alpha,
                       "forebulge_x_km": math.pi * alpha / 1e3, "uy_forebulge": tp_crest},
        "rel_diff": {"uy_load": rel(uy_load, tp_load), "uy_200km": rel(uy_200, tp_200),
                     "uy_alpha": rel(uy_alpha, tp_alpha),
                     "uy_forebulge": rel(crest_uy, tp_crest)},
        "petsc_options": options,
    })

    def rounded(value):
        if isinstance(value, float):
            return float("%.6g" % value)
        if isinstance(value, dict):
            return {k: rounded(v) for k, v in value.items()}
        return value
    result = rounded(result)
    log("peer flexure (dolfinx %s, PETSc %s): %d x %d cells, %d DoFs, %d rank(s)"
        % (dolfinx.__version__, result["petsc"], nx, ny, result["dofs"], comm.size))
    log("  CG+GAMG: %d iterations, reason %d, |b-Au|/|b| = %.3e" % (iterations, reason, rel_residual))
    log("  setup %.3f s, assemble %.3f s, near null space %.3f s, PC setup %.3f s, solve %.3f s,"
        " total %.3f s (JIT %.3f s excluded; warm-up %.3f s); matvec %.3f ms"
        % (times["setup_s"], times["assemble_s"], times["near_nullspace_s"],
           times["preconditioner_setup_s"], times["solve_s"], times["total_s"], jit, jit_warmup, matvec_ms))
    log("  peak RSS %.1f MiB (baseline after imports %.1f MiB)" % (peak_rss, baseline_rss))
    log("  u_y at the load    %12.4f m   thin plate %12.4f m   (%+.2f %%)"
        % (uy_load, tp_load, 100 * rel(uy_load, tp_load)))
    log("  u_y at +200 km     %12.4f m   thin plate %12.4f m   (%+.2f %%); at -200 km %.4f m"
        % (uy_200, tp_200, 100 * rel(uy_200, tp_200), uy_200_left))
    log("  u_y at alpha       %12.4f m   thin plate %12.4f m   (%+.2f %%)"
        % (uy_alpha, tp_alpha, 100 * rel(uy_alpha, tp_alpha)))
    log("  forebulge crest    %12.4f m at %.1f km; thin plate %.4f m at %.1f km (%+.2f %%)"
        % (crest_uy, abs(crest_x - LOAD_X) / 1e3, tp_crest, math.pi * alpha / 1e3, 100 * rel(crest_uy, tp_crest)))
    if reason <= 0:
        log("  WARNING: KSP did not converge (reason %d)" % reason)
    if rank0:
        print(json.dumps(result), flush=True)
    if reason <= 0:
        sys.exit(1)


if __name__ == "__main__":
    main()

"""Thesis §4.4: lithostatic column. Q2 represents the exact solution (u_y
quadratic in y, stress linear), so the FE solution must equal it to
round-off on every mesh: uniform, adaptively refined with hanging nodes, a
Gmsh mesh, and 2 MPI ranks. Top subsidence
(1+nu)(1-2nu)/(E(1-nu)) rho g H^2/2 = 12.716 m; the thesis prints 12.71."""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

E, nu, rho, g, H = 9e10, 0.25, 2800.0, 9.81, 1e4
exact_top = -(1 + nu) * (1 - 2 * nu) / (E * (1 - nu)) * rho * g * H * H / 2
check(abs(abs(exact_top) - 12.7167) < 1e-4, "analytic top subsidence %.4f m" % exact_top)
check(abs(abs(exact_top) - 12.71) < 0.01, "agrees with the thesis's 12.71 m (truncated)")

# Round-off tolerance: errors relative to the solution's norm, a few hundred
# ulps of the condition-number-weighted solve (CG to 1e-12).
TOL = 1e-9
cases = [("uniform", 1, []),
         ("adaptive-hanging-nodes", 1, ["Mesh refinement/Strategy=adaptive",
                                        "Mesh refinement/Marking=fraction of cells",
                                        "Mesh refinement/Refine fraction=0.3",
                                        "Mesh refinement/Number of cycles=4"]),
         ("two-ranks", 2, ["Mesh refinement/Initial global refinement=2"]),
         ("gmsh", 1, ["Geometry/Model=gmsh",
                      "Geometry/Gmsh/Mesh file=" + os.path.join(SOURCE, "lithostatic_column", "column.msh"),
                      "Materials/rock/Material id=",
                      "Mesh refinement/Number of cycles=2"])]
for name, ranks, sets in cases:
    out = os.path.abspath("output_column_" + name)
    run("lithostatic_column/column.prm", out, ranks, sets + ["Solver/Relative tolerance=1e-12"])
    # Every cycle the run was given has its row (an empty table would
    # pass the per-row checks below).
    cycles = int(read_prm(os.path.join(out, "parameters.prm"))["Mesh refinement/Number of cycles"])
    check(len(table(out)) == cycles, "%s: convergence.csv has a row for each of the %d cycles"
          % (name, cycles))
    for row in table(out):
        tag = "%s cycle %d (%d DoFs)" % (name, row["cycle"], row["dofs"])
        check(row["rel_L2(u)"] < TOL, "%s: relative L2 error of u %.1e < %.0e" % (tag, row["rel_L2(u)"], TOL))
        check(row["rel_L2(stress)"] < TOL, "%s: relative L2 error of stress %.1e" % (tag, row["rel_L2(stress)"]))
        for p in (1, 2, 3):
            u = row["u_y@P%d" % p]
            check(abs(u - exact_top) < TOL * 13, "%s: top point %d subsides %.6f m" % (tag, p, u))
        # sigma_yy = rho g y and sigma_xx = nu/(1-nu) sigma_yy at (5, -5) km
        syy = row["s_yy@P4"]; sxx = row["s_xx@P4"]
        check(abs(syy - rho * g * -5e3) < 1e-9 * rho * g * 5e3, "%s: sigma_yy(-5 km) = %.6e Pa" % (tag, syy))
        check(abs(sxx - nu / (1 - nu) * syy) < 1e-9 * abs(syy), "%s: sigma_xx = nu/(1-nu) sigma_yy" % tag)

# ParaView output of the uniform run: a .pvd record of every cycle and the
# fields the user needs.
out = os.path.abspath("output_column_uniform")
pvd = open(os.path.join(out, "solution.pvd")).read()
check(all(("solution_%03d.pvtu" % c) in pvd for c in range(3)), "solution.pvd lists the .pvtu of every cycle")
pvtu = open(os.path.join(out, "solution_002.pvtu")).read()
for field in ("displacement", "stress", "sigma_zz", "sigma_1", "sigma_2", "sigma_1_direction",
              "deviatoric_xx", "griffith_degree_of_failure", "griffith_regime", "griffith_fracture_angle",
              "material_id", "mpi_rank"):
    check('Name="%s"' % field in pvtu, "output has the field %s" % field)
finish()

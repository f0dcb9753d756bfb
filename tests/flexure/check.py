"""Plate flexure (thesis §6.1.2, SPEC §4): the default experiment against
thin-plate theory. A thin plate neglects shear deformation; for a plate of
thickness h bending with characteristic length alpha the relative size of
the shear correction is (Timoshenko beam on a Winkler foundation, first
order) delta = D / (kappa G h alpha^2) = h^2 / (6 kappa (1 - nu) alpha^2)
with kappa = 5/6: delta = 3.7 % for h = 20 km, alpha = 54 km, nu = 0.25.
The forebulge height must agree within 2 delta and its position within
delta (position is also limited by the profile's point spacing, h/4 on the
coarsest mesh here = 0.7 % of pi alpha); the profile away from the load
must converge under refinement."""
import sys, os, csv, math
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

ROOT = os.path.dirname(SOURCE)
E, nu, h, rho_f, g, V = 0.85e11, 0.25, 20e3, 2900.0, 9.81, 2e12
D = E * h ** 3 / (12 * (1 - nu * nu))
alpha = (4 * D / (rho_f * g)) ** 0.25
delta = h * h / (6 * (5.0 / 6.0) * (1 - nu) * alpha * alpha)
check(abs(alpha / 1e3 - 54.0) < 0.05, "flexural parameter alpha = %.2f km" % (alpha / 1e3))

out = os.path.abspath("output_flexure")
run(os.path.join(ROOT, "prm", "flexure.prm"), out, 1,
    ["Mesh refinement/Initial global refinement=1", "Mesh refinement/Number of cycles=2",
     "Output/Write ParaView files=false"])
values = {r["quantity"]: (float(r["finite_element"]), float(r["thin_plate"]))
          for r in csv.DictReader(open(os.path.join(out, "thin_plate_comparison.csv")))}
for side in ("left", "right"):
    fe, tp = values["forebulge_height_%s_m" % side]
    check(abs(fe / tp - 1) <= 2 * delta, "%s forebulge height %.2f m vs thin plate %.2f m (%.1f %%, allowed %.1f %%)"
          % (side, fe, tp, 100 * (fe / tp - 1), 200 * delta))
    fe, tp = values["forebulge_distance_%s_m" % side]
    check(abs(fe / tp - 1) <= delta, "%s forebulge %.1f km from the load vs thin plate %.1f km (allowed %.1f %%)"
          % (side, fe / 1e3, tp / 1e3, 100 * delta))
fe, tp = values["deflection_at_1_alpha_m"]
check(abs(fe / tp - 1) <= 2 * delta, "deflection one alpha from the load %.1f m vs %.1f m" % (fe, tp))
rows = table(out)
# Points 2-4 are 100, 150 and 250 km from the load: the change of u_y
# between the two meshes must be far below the thin-plate difference.
for p in (2, 3, 4):
    change = rows[-1]["change_u_y@P%d" % p]
    check(change < 1e-3 * abs(rows[-1]["u_y@P%d" % p]) + 1e-3,
          "u_y at P%d converged: change %.1e m between meshes" % (p, change))
finish()

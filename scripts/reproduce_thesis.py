#!/usr/bin/python3
"""Every quantitative statement of thesis chapters 4, 6 and 7 against
lithostress, in one table.

The statements are the catalogue scripts/thesis_statements.csv (chapter,
section, experiment, quantity, the thesis's number, the range or upper
bound it states (low, high; empty if none), its unit and the thesis's
words). This script runs the models that answer them:

  chapter 4  the thesis's 27-node cantilever with its own elements (CST,
             CSQ, six-node triangles: tests/cantilever/thesis_elements.py),
             the lithostatic column (tests/lithostatic_column/column.prm)
             and the thick cylinder's relaxation functions (the closed form
             of doc/viscoelastic_cylinder_derivation.md);
  chapter 6  the plane and listric normal and thrust faults at 30 and
             50 MPa, the plane normal fault's elastic stage (the fault
             elastic, before it slides) and the thesis iteration (§5.5)
             with convergence factors 1, 2, 3 and 15, and the graben widths
             of tables 6.3 and 6.4 (scripts/graben_widths.py);
  chapter 7  the eleven subduction configurations
             (scripts/reproduce_subduction.py);

and writes OUTDIR/thesis_comparison.csv with the columns

  chapter,section,experiment,quantity,ours,thesis,unit,explained_by

one row per statement. `ours` is empty where no run of ours answers the
statement. `explained_by` is empty where |ours - thesis| <= 10 % of
|thesis| (for a thesis zero: |ours| <= 0.1), or where ours lies in the
range or under the bound the thesis states; elsewhere it names the run, option or calculation that
accounts for the difference (doc/thesis_comparison.md gives the evidence),
or stays empty: the row is then unexplained. The script prints the median
relative difference and the number of unexplained rows.

Usage: reproduce_thesis.py OUTDIR [--binary PATH] [--skip-subduction]
       [--skip-thesis-iteration]
"""
import argparse
import csv
import json
import math
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "tests", "cantilever"))
sys.path.insert(0, os.path.join(ROOT, "tests", "viscoelastic"))
import cylinder_reference  # noqa: E402
import graben_widths  # noqa: E402
import thesis_mesh_elements  # noqa: E402

QUIET = ["Output/Write ParaView files=false", "Output/Figures/Enabled=false"]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
# Where the fault profiles look for the flexural stresses (km): either
# side of the trace at x = 500 km.
PROFILE_X = (460, 470, 480, 490, 495, 505, 510, 520, 530, 540)


def run(binary, prm, outdir, sets, may_fail=False):
    """Run lithostress on prm/<prm> (or a path) into outdir with --set
    options; returns whether it succeeded (or exits, unless may_fail)."""
    path = prm if os.path.isabs(prm) else os.path.join(ROOT, "prm", prm)
    cmd = [binary, path, "--set", "Output directory=" + outdir]
    for s in QUIET + list(sets):
        cmd += ["--set", s]
    result = subprocess.run(cmd, capture_output=True, text=True, env=ENV)
    if result.returncode != 0 and not may_fail:
        sys.stderr.write(result.stdout[-3000:] + result.stderr[-3000:])
        sys.exit("reproduce_thesis.py: %s failed (output in %s)" % (prm, outdir))
    return result.returncode == 0


def read_csv(path):
    with open(path) as f:
        return [{k: float(v) if v not in ("", None) and k != "state" else v
                 for k, v in r.items()} for r in csv.DictReader(f)]


class FaultRun:
    """The outputs of one fault run: its summary, the surface profile, the
    fault's trace and the stress-depth profiles at PROFILE_X."""

    def __init__(self, outdir):
        with open(os.path.join(outdir, "fault_summary.json")) as f:
            self.summary = json.load(f)
        self.profile = read_csv(os.path.join(outdir, "surface_profile.csv"))
        fault = read_csv(os.path.join(outdir, "fault.csv"))
        self.trace_x = min(fault, key=lambda r: abs(r["y"]))["x"]
        self.stress = {}
        for x in PROFILE_X:
            path = os.path.join(outdir, "stress_depth_x%d.csv" % x)
            if os.path.exists(path):
                self.stress[x] = read_csv(path)

    def throw(self):
        return self.summary["throw_m"]

    def sliding_depth_km(self):
        return self.summary["sliding_depth_m"] / 1e3

    def u_y(self, x_m):
        return min(self.profile, key=lambda r: abs(r["x"] - x_m))["u_y"]

    def extremum_km(self, direction, sign):
        """Distance from the trace to the first local maximum (sign +1) or
        minimum (-1) of u_y on the side direction (+1: x > trace)."""
        flipped = [dict(r, u_y=sign * r["u_y"]) for r in self.profile]
        return graben_widths.crest_distance(flipped, self.trace_x, direction) / 1e3

    def sigma_xx(self, x_km, where):
        """sigma_xx [MPa] at the top (depth 0) or base of the profile."""
        rows = self.stress[x_km]
        row = min(rows, key=lambda r: r["depth"]) if where == "top" else \
            max(rows, key=lambda r: r["depth"])
        return row["sigma_xx"] / 1e6


def run_faults(binary, outdir, with_thesis_iteration):
    """The chapter-6 runs; returns {name: FaultRun or None (diverged)}."""
    profiles = "Output/Stress-depth profiles=" + ", ".join(str(x) for x in PROFILE_X)
    cases = {
        "normal_50": ("normal_fault.prm", [profiles]),
        "normal_50_elastic": ("normal_fault.prm", [profiles, "Faults/fault/Interface law=elastic"]),
        "normal_30": ("normal_fault.prm", ["Loads/Tractions/left/Normal traction=3e7"]),
        "listric_normal_50": ("listric_normal_fault.prm", []),
        "listric_normal_30": ("listric_normal_fault.prm", ["Loads/Tractions/left/Normal traction=3e7"]),
        "thrust_50": ("thrust_fault.prm", []),
        "thrust_30": ("thrust_fault.prm", ["Loads/Tractions/left/Normal traction=-3e7"]),
        "listric_thrust_50": ("listric_thrust_fault.prm", []),
        "listric_thrust_30": ("listric_thrust_fault.prm", ["Loads/Tractions/left/Normal traction=-3e7"]),
    }
    # The thesis iteration (§5.5) on the 800-cell mesh (the thesis's fault
    # elements are coarser than our points: doc/faults.md).
    if with_thesis_iteration:
        for factor in (1, 2, 3, 15):
            cases["normal_50_thesis_factor%d" % factor] = (
                "normal_fault.prm",
                ["Faults/Sliding solver/Method=thesis",
                 "Faults/Sliding solver/Excess shear tolerance=1e5",
                 "Faults/Sliding solver/Convergence factor=%d" % factor,
                 "Faults/Sliding solver/Maximum iterations=3000",
                 "Mesh refinement/Initial global refinement=2"])
    runs = {}
    for name, (prm, sets) in cases.items():
        out = os.path.join(outdir, "faults", name)
        print("chapter 6: %s ..." % name, flush=True)
        ok = run(binary, prm, out, sets, may_fail=name.startswith("normal_50_thesis"))
        runs[name] = FaultRun(out) if ok else None
        if ok and name.startswith("normal_50_thesis"):
            with open(os.path.join(out, "statistics.json")) as f:
                runs[name].statistics = json.load(f)
    return runs


def flexural_change(runs, side, where):
    """The largest change of sigma_xx [MPa] at the top or base of the
    downthrown (side +1, x > 500 km) or upthrown (-1) side between the
    elastic stage and the sliding fault (thesis §6.1.4), signed."""
    changes = [runs["normal_50"].sigma_xx(x, where) - runs["normal_50_elastic"].sigma_xx(x, where)
               for x in PROFILE_X if side * (x - 500) > 0]
    return max(changes, key=abs)


def chapter6(runs, graben):
    """{(experiment, quantity): ours} for chapter 6."""
    n50, n30 = runs["normal_50"], runs["normal_30"]
    ours = {
        ("plane_normal_fault_50MPa", "edge_subsidence_elastic_stage"):
            -runs["normal_50_elastic"].u_y(0.0),
        ("plane_normal_fault_50MPa", "throw_increase_due_to_sliding"):
            n50.throw() - runs["normal_50_elastic"].throw(),
        ("plane_normal_fault_50MPa", "horizontal_tension_increase_top_downthrown_side"):
            flexural_change(runs, 1, "top"),
        ("plane_normal_fault_50MPa", "horizontal_tension_decrease_base_downthrown_side"):
            -flexural_change(runs, 1, "base"),
        ("plane_normal_fault_50MPa", "horizontal_tension_decrease_top_upthrown_side"):
            -flexural_change(runs, -1, "top"),
        ("plane_normal_fault_50MPa", "horizontal_tension_increase_base_upthrown_side"):
            flexural_change(runs, -1, "base"),
        ("plane_normal_fault_50MPa", "sliding_depth"): n50.sliding_depth_km(),
        ("plane_normal_fault_30MPa", "sliding_depth"): n30.sliding_depth_km(),
        ("plane_normal_fault_50MPa", "throw_at_fault"): n50.throw(),
        ("plane_normal_fault_30MPa", "throw_at_fault"): n30.throw(),
        ("plane_normal_fault_30MPa", "short_wavelength_upflexure_axis_distance_from_fault_downthrown"):
            n30.extremum_km(1, 1),
        ("listric_normal_fault_30MPa", "short_wavelength_upflexure_axis_distance_from_fault_downthrown"):
            runs["listric_normal_30"].extremum_km(1, 1),
        ("listric_normal_fault_30MPa", "sliding_depth"): runs["listric_normal_30"].sliding_depth_km(),
        ("listric_normal_fault_50MPa", "sliding_depth_whole_layer"):
            runs["listric_normal_50"].sliding_depth_km(),
        ("plane_thrust_30MPa", "short_wavelength_downflexure_axis_distance_from_fault"):
            min(runs["thrust_30"].extremum_km(d, -1) for d in (-1, 1)),
        ("plane_thrust_50MPa", "sliding_depth_whole_layer"): runs["thrust_50"].sliding_depth_km(),
        ("listric_thrust_30_50MPa", "throw_at_surface_tip_upper_bound_several_metres"):
            max(abs(runs["listric_thrust_30"].throw()), abs(runs["listric_thrust_50"].throw())),
    }
    for factor, key in ((1, "friction_iterations_without_convergence_factor"),
                        (15, "friction_iterations_with_convergence_factor_15")):
        r = runs.get("normal_50_thesis_factor%d" % factor)
        if r is not None:
            ours[("plane_normal_fault_50MPa", key)] = r.statistics.get("nonlinear_iterations")
    stable = [f for f in (1, 2, 3, 15) if runs.get("normal_50_thesis_factor%d" % f) is not None]
    if "normal_50_thesis_factor1" in runs:
        ours[("plane_normal_fault_50MPa", "optimum_convergence_factor_ks_5e10")] = max(stable)
    # Tables 6.3 and 6.4.
    names = {10: "plane_normal_fault_h10km_%dMPa", 20: "plane_normal_fault_%dMPa",
             30: "plane_normal_fault_h30km_%dMPa"}
    for r in graben:
        h, t = int(r["thickness_km"]), int(r["tension_MPa"])
        ours[(names[h] % t, "graben_width_fault_to_most_likely_tensile_failure")] = r["distance_km"]
        ours[("thin_beam_analytic_h%dkm" % h, "graben_width_lower_bound")] = r["thin_beam_min_km"]
        ours[("thin_beam_analytic_h%dkm" % h, "graben_width_upper_bound")] = r["thin_beam_max_km"]
    return ours


def run_graben(binary, outdir):
    out = os.path.join(outdir, "graben_widths")
    print("chapter 6: graben widths (tables 6.3, 6.4) ...", flush=True)
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "graben_widths.py"), out,
                    "--binary", binary, "--global-refinement", "4"],
                   check=True, env=ENV, stdout=subprocess.DEVNULL)
    return read_csv(os.path.join(out, "graben_widths_comparison.csv"))


# Chapter 7: (catalogue experiment, quantity) -> (experiment, the start of
# the quantity in reproduce_subduction.py's table, factor).
SUBDUCTION = {
    ("lateral_density_variations", "max_horizontal_deviatoric_tension_continental_crust_elastic"):
        ("density (elastic)", "largest horizontal deviatoric tension in the continental crust", 1),
    ("lateral_density_variations", "depth_of_max_horizontal_deviatoric_tension_elastic_range_5_10"):
        ("density (elastic)", "its depth below the surface", 1),
    ("lateral_density_variations", "max_vertical_tension_beneath_trench_elastic"):
        ("density (elastic)", "largest vertical tension in the subducting plate near the trench", 1),
    ("lateral_density_variations", "vertical_compression_beneath_outer_rise_elastic"):
        ("density (elastic)", "largest vertical compression beneath the outer rise", 1),
    ("lateral_density_variations", "max_horizontal_deviatoric_tension_right_edge_after_5Myr"):
        ("density (5Myr)", "largest horizontal deviatoric tension in the continental crust", 1),
    ("lateral_density_variations", "depth_of_max_horizontal_deviatoric_tension_after_5Myr_range_5_10"):
        ("density (5Myr)", "its depth below the surface", 1),
    ("slab_pull_load_balance", "unbalanced_upward_vertical_force_trench_outer_rise"):
        ("slab_pull_90 (elastic)", "net upthrust of the trench and outer-rise pressures", 1),
    ("slab_pull_load_balance", "vertical_slab_pull_force_to_balance_downwards"):
        ("slab_pull_90 (elastic)", "vertical slab pull balancing the model's loads", 1),
    ("slab_pull_load_balance", "vertical_stress_applied_over_A_A"):
        ("slab_pull_90 (elastic)", "vertical slab-pull stress over A-A", 1),
    ("subduction_slab_pull_dip_90", "max_horizontal_bending_stress_elastic"):
        ("slab_pull_90 (elastic)", "largest bending stress", 1),
    ("subduction_slab_pull_dip_90", "upflexure_distance_seaward_of_trench_axis_elastic"):
        ("slab_pull_90 (elastic)", "distance of the up-flexure's crest", 1),
    ("subduction_slab_pull_dip_90", "max_horizontal_deviatoric_tension_right_edge_elastic"):
        ("slab_pull_90 (elastic)", "largest horizontal deviatoric tension in the continental crust", 1),
    ("subduction_slab_pull_dip_90", "depth_of_max_horizontal_deviatoric_tension_right_edge_range_5_10"):
        ("slab_pull_90 (elastic)", "its depth below the surface", 1),
    ("subduction_slab_pull_dip_63_vs_26", "increase_regional_horizontal_tension_subducting_plate"):
        ("slab_pull 63.43 -> 26.57 (elastic)", "growth of the regional horizontal tension", 1),
    ("subduction_slab_pull_dip_63_vs_26", "increase_regional_horizontal_compression_overlying_plate"):
        ("slab_pull 63.43 -> 26.57 (elastic)", "growth of the regional horizontal compression", 1),
    ("plate_coupling_locked_vs_ks_1e9", "reduction_regional_horizontal_compression_overlying_mantle"):
        ("coupling (elastic)", "fall of the overlying plate's regional compression in the mantle", 1),
    ("plate_coupling_locked_vs_ks_1e9", "reduction_regional_horizontal_compression_overlying_crust"):
        ("coupling (elastic)", "fall of the overlying plate's regional compression in the crust", 1),
    ("plate_coupling_ks_1e9", "regional_horizontal_compression_overlying_plate_upper_bound"):
        ("coupling (elastic)", "regional compression left in the overlying plate's crust", 1),
    ("plate_coupling_ks_1e9", "near_surface_horizontal_compression_trench_to_arc"):
        ("coupling (elastic)", "near-surface compression between the trench and 700 km", 1),
    ("basal_shear_3p5MPa", "regional_horizontal_compression_subducting_plate_elastic"):
        ("basal_shear (elastic)", "mean horizontal stress in the subducting plate at the left edge", -1),
    ("basal_shear_3p5MPa", "regional_horizontal_stress_overlying_plate_elastic_similar_magnitude"):
        ("basal_shear (elastic)", "mean horizontal stress in the overlying plate at the right edge", 1),
    ("basal_shear_3p5MPa", "near_surface_horizontal_tension_above_fault_base_elastic"):
        ("basal_shear (elastic)", "horizontal stress at the surface above the plate boundary's base", 1),
    ("basal_shear_3p5MPa", "underlying_horizontal_compression_above_fault_base_elastic"):
        ("basal_shear (elastic)", "largest horizontal compression beneath it", -1),
    ("basal_shear_3p5MPa", "near_surface_horizontal_stress_right_edge_elastic"):
        ("basal_shear (elastic)", "horizontal stress at the surface at the right edge", 1),
    ("basal_shear_3p5MPa", "underlying_horizontal_tension_right_edge_elastic"):
        ("basal_shear (elastic)", "largest horizontal tension beneath it", 1),
    ("basal_shear_3p5MPa", "failed_elements_elastic"):
        ("basal_shear (elastic)", "output nodes failed by the Griffith criterion", 1),
    ("thermal_anomaly", "horizontal_tension_top_of_crust_above_anomaly"):
        ("thermal (elastic)", "horizontal stress at the top of the crust above the anomaly", 1),
    ("thermal_anomaly", "horizontal_compression_base_of_lithosphere_above_anomaly"):
        ("thermal (elastic)", "largest horizontal compression above the anomaly", 1),
    ("thermal_anomaly", "failure_depth_above_anomaly_centre"):
        ("thermal (elastic)", "depth of Griffith failure above the anomaly", 1),
    ("thermal_anomaly", "failed_elements_elsewhere"):
        ("thermal (elastic)", "output nodes failed by the Griffith criterion more than", 1),
    ("thermal_anomaly", "regional_horizontal_compression_subducting_plate_and_overlying_above_fault"):
        ("thermal (elastic)", "mean horizontal stress in the subducting plate at the left edge", -1),
}


def chapter7(binary, outdir):
    out = os.path.join(outdir, "subduction")
    print("chapter 7: the eleven subduction configurations ...", flush=True)
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "reproduce_subduction.py"),
                    out, "--binary", binary], check=True, env=ENV, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "subduction_comparison.csv")) as f:
        table = list(csv.DictReader(f))
    ours = {}
    for key, (experiment, start, factor) in SUBDUCTION.items():
        for r in table:
            if r["experiment"] == experiment and r["quantity"].startswith(start) and r["ours"]:
                ours[key] = factor * float(r["ours"])
                break
    return ours


def chapter4(binary, outdir):
    """{(experiment, quantity): ours} for chapter 4."""
    ours = {}
    # The cantilever on the thesis's 27 nodes with its own elements (§4.3.2;
    # plane strain, the program's default).
    tip = thesis_mesh_elements.thesis_cantilever(strain=True)
    for element in ("CST", "CSQ"):
        ours[("cantilever_%s_27node" % element.lower(),
              "max_neutral_fibre_deflection_fraction_of_analytic")] = 100 * tip[element] / tip["beam"]
    # The lithostatic column (§4.4): the top surface's subsidence, and
    # equation 4.4 with the column's E, nu, rho and h = 10 km.
    out = os.path.join(outdir, "lithostatic_column")
    print("chapter 4: the lithostatic column ...", flush=True)
    run(binary, os.path.join(ROOT, "tests", "lithostatic_column", "column.prm"), out, [])
    top = [r for r in read_csv(os.path.join(out, "point_values.csv")) if r["y"] == 0]
    subsidence = -statistics.mean(r["u_y"] for r in top)
    for key in (("lithostatic_column_isoparametric", "top_surface_subsidence_all_nodes"),
                ("lithostatic_column_csq_9node", "top_surface_subsidence_exact"),
                ("lithostatic_column_cst_13node", "top_surface_subsidence_correct")):
        ours[key] = subsidence
    # The stresses against the exact ones: the relative L2 error of the
    # last cycle, and the principal directions' rotation from x and y at
    # the column's centre (5 km, -5 km).
    last = read_csv(os.path.join(out, "convergence.csv"))[-1]
    ours[("lithostatic_column_isoparametric", "principal_stress_magnitude_error")] = \
        100 * last["rel_L2(stress)"]
    centre = [r for r in read_csv(os.path.join(out, "point_values.csv")) if r["y"] == -5000][-1]
    angle = abs(centre["angle_1"]) % 90
    ours[("lithostatic_column_isoparametric", "principal_stress_rotation_from_analytic")] = \
        min(angle, 90 - angle)
    E, nu, rho, g, h = 9e10, 0.25, 2800.0, 9.81, 1e4
    ours[("lithostatic_column_analytic", "top_surface_subsidence_eq_4_4_h_10km")] = \
        (1 + nu) * (1 - 2 * nu) / (E * (1 - nu)) * rho * g * h * h / 2
    # The thick cylinder (§4.5.2): the closed-form relaxation functions
    # f(t) = -C(t)/p and g(t) = D(t)/(p b^2) of the ring model with
    # nu = 1/3 (doc/viscoelastic_cylinder_derivation.md), and u_r(2, 0+).
    ring = cylinder_reference.Solution("ring", nu=1.0 / 3.0)
    p, b = ring.p, ring.b
    ours.update({
        ("thick_cylinder_analytic", "f_t_constant_term"): -ring.C.inf / p,
        ("thick_cylinder_analytic", "f_t_coeff_fast_mode_negated"): ring.C.coeffs[0] / p,
        ("thick_cylinder_analytic", "f_t_coeff_slow_mode_negated"): ring.C.coeffs[1] / p,
        ("thick_cylinder_analytic", "decay_rate_fast_mode_per_maxwell_time"): ring.rates_tau[0],
        ("thick_cylinder_analytic", "decay_rate_slow_mode_per_maxwell_time"): ring.rates_tau[1],
        ("thick_cylinder_analytic", "g_t_coeff_fast_mode"): ring.D.coeffs[0] / (p * b * b),
        ("thick_cylinder_analytic", "g_t_coeff_slow_mode_sign_should_be_plus"):
            ring.D.coeffs[1] / (p * b * b),
    })
    u0 = cylinder_reference.Solution("ring").stresses(2.0, 0.0)[3]
    ours[("thick_cylinder_cst", "radial_displacement_r2in_t0_nodes_i")] = u0
    ours[("thick_cylinder_cst", "radial_displacement_r2in_t0_nodes_j")] = u0
    return ours


def load_explanations():
    """{(experiment, quantity): text} from scripts/thesis_explanations.csv."""
    path = os.path.join(ROOT, "scripts", "thesis_explanations.csv")
    with open(path) as f:
        return {(r["experiment"], r["quantity"]): r["explained_by"] for r in csv.DictReader(f)}


def relative_difference(ours, thesis):
    if ours is None or ours == "":
        return None
    if thesis == 0:
        return abs(ours)
    return abs(ours - thesis) / abs(thesis)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "lithostress"))
    parser.add_argument("--skip-subduction", action="store_true",
                        help="leave chapter 7 out (its rows stay empty)")
    parser.add_argument("--skip-thesis-iteration", action="store_true",
                        help="leave the thesis iteration's runs out (2 minutes)")
    args = parser.parse_args()
    outdir = os.path.abspath(args.outdir)
    os.makedirs(outdir, exist_ok=True)
    if not os.path.exists(args.binary):
        subprocess.run(["bash", os.path.join(ROOT, "scripts", "build.sh"), "build", "Release"],
                       check=True)
    ours = chapter4(args.binary, outdir)
    runs = run_faults(args.binary, outdir, not args.skip_thesis_iteration)
    ours.update(chapter6(runs, run_graben(args.binary, outdir)))
    if not args.skip_subduction:
        ours.update(chapter7(args.binary, outdir))
    explanations = load_explanations()

    with open(os.path.join(ROOT, "scripts", "thesis_statements.csv")) as f:
        statements = list(csv.DictReader(f))
    differences, unexplained = [], []
    path = os.path.join(outdir, "thesis_comparison.csv")
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["chapter", "section", "experiment", "quantity", "ours", "thesis", "unit",
                         "explained_by"])
        for s in statements:
            key = (s["experiment"], s["quantity"])
            value = ours.get(key)
            thesis = float(s["thesis"])
            d = relative_difference(value, thesis)
            agrees = d is not None and d <= 0.1
            # A range or an upper bound the thesis states: inside it.
            if value is not None and (s["low"] or s["high"]):
                low = float(s["low"]) if s["low"] else -math.inf
                agrees = low <= value <= float(s["high"])
            explained = "" if agrees else explanations.get(key, "")
            if d is not None and thesis != 0:
                differences.append(d)
            if not agrees and not explained:
                unexplained.append(key)
            writer.writerow([s["chapter"], s["section"], s["experiment"], s["quantity"],
                             "" if value is None else "%.4g" % value, s["thesis"], s["unit"],
                             explained])
    print("wrote %s: %d rows, %d with a number of ours" % (path, len(statements), len(differences)))
    print("median relative difference (rows with a non-zero thesis value): %.1f %%"
          % (100 * statistics.median(differences)))
    print("unexplained rows (difference > 10 %% or no number of ours, no cause): %d" %
          len(unexplained))
    for key in unexplained:
        print("  %s / %s" % key)


if __name__ == "__main__":
    main()

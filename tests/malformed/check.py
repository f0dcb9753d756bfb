"""Malformed input: each .prm here has one defect. The program must exit
with status 1 and one clear line on stderr that names the entry or file,
without a crash or stack trace, and must not touch an earlier run's
results in the output directory."""
import sys, os, subprocess, shutil
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import lithotest
from lithotest import check, finish, env, BINARY

HERE = os.path.dirname(os.path.abspath(__file__))
expected = {
    "unknown_entry": "Youngs modulus",
    "misspelt_subsection": "Geometri",
    "poisson_ratio_half": "Poisson's ratio",
    "negative_youngs_modulus": "Young's modulus",
    "missing_mesh_file": "no-such-mesh.msh",
    "unknown_boundary_name": "bottom",
    "material_without_id": "material id 0",
    "unparsable_function": "Normal traction",
    "negative_refine_fraction": "Refine fraction",
    "unwritable_output_directory": "Output directory",
    "not_a_number": "Number of cycles",
    "reference_without_solution": "reference",
    "point_outside_body": "Points",
    "unknown_geometry": "sphere",
    "unbalanced_end": "subsection",
    "reference_column_gap": "Reference column",
    "reference_column_too_short": "Reference column",
    "stripping_with_gravity": "Gravity",
    "temperature_change_unparsable": "Temperature change",
    "thermal_coefficient_type_missing": "Coefficient type",
    "negative_fluid_density": "Fluid densities",
    "line_force_outside_body": "Line forces",
    "resultant_and_traction": "Resultant force",
    "resultant_one_component": "Resultant force",
    "profile_line_outside_body": "Stress-depth profiles",
    "multigrid_for_degree_four": "Solver/Type",
}
files = sorted(f[:-4] for f in os.listdir(HERE) if f.endswith(".prm"))
check(len(files) >= 10 and set(files) == set(expected), "%d malformed inputs, each with an expected message" % len(files))

earlier = os.path.abspath("earlier_results")
for name in files:
    shutil.rmtree(earlier, ignore_errors=True)
    os.makedirs(earlier)
    with open(os.path.join(earlier, "solution.pvd"), "w") as f:
        f.write("results of an earlier run\n")
    cmd = [BINARY, os.path.join(HERE, name + ".prm")]
    if name != "unwritable_output_directory":
        cmd += ["--set", "Output directory=" + earlier]
    r = subprocess.run(cmd, capture_output=True, text=True, env=env())
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    check(r.returncode == 1, "%s: exit status %d (expected 1)" % (name, r.returncode))
    check(len(lines) == 1, "%s: one line of error: %s" % (name, lines[0] if lines else "(none)"))
    check(any(expected.get(name, "\0") in l for l in lines), "%s: message names <%s>" % (name, expected.get(name)))
    check("Stacktrace" not in r.stderr and "An error occurred" not in r.stderr, "%s: no stack trace" % name)
    check(sorted(os.listdir(earlier)) == ["solution.pvd"] and
          open(os.path.join(earlier, "solution.pvd")).read() == "results of an earlier run\n",
          "%s: earlier results untouched" % name)
finish()

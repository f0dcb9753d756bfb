"""Malformed and ill-posed input: each .prm here has one defect (a wrong
entry, a model free to move as a rigid body, a user function that is NaN or
infinite somewhere, a mesh too large for memory, a broken Gmsh file, a bad
override given in <name>.args, where {here} stands for this directory). On 1 and on 2 MPI ranks the program must end
within seconds with exit status 1 and one line on stderr that names the
entry or file, the same line on both, without a signal, a crash or a stack
trace, and must leave an earlier run's output directory byte-identical."""
import sys, os, subprocess, shutil, time, concurrent.futures
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import lithotest
from lithotest import check, finish, env, BINARY

HERE = os.path.dirname(os.path.abspath(__file__))
expected = {
    "unknown_entry": "Youngs modulus",
    "misspelt_subsection": "Geometri",
    "poisson_ratio_half": "Poisson's ratio",
    "negative_youngs_modulus": "Young's modulus",
    "youngs_modulus_huge": "Materials/rock/Young's modulus>: must be at most 1e20 Pa (rocks: 1e9 to 2e11 Pa), got 1e+300",
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
    "conduction_unknown_material": "Thermal conductivity",
    "entry_of_another_law": "Materials/rock/Cohesion",
    "conduction_unknown_boundary": "Top boundary",
    "conduction_part_top_and_base": "Temperature/Steady conduction/Base boundary>: names `left`, which is a Top boundary too",
    "conduction_negative_heat_production": "Radiogenic heat production",
    "thermal_coefficient_type_missing": "Coefficient type",
    "negative_fluid_density": "Fluid densities",
    "line_force_outside_body": "Line forces",
    "resultant_and_traction": "Resultant force",
    "resultant_one_component": "Resultant force",
    "profile_line_outside_body": "Stress-depth profiles",
    "multigrid_for_degree_four": "Solver/Type",
    # Ill-posed: a rigid-body motion nothing holds (found on the coarse
    # mesh, before anything is solved or written).
    "free_in_all": "free to move as a rigid body",
    "free_in_y": "free to translate in y",
    "free_in_x": "free to translate in x",
    "free_in_x_spring_only": "free to translate in x",
    "free_rotation": "free to rotate about (0, 0)",
    "free_in_x_and_rotation": "free to translate in x and to rotate about (0, 2) m",
    "spring_too_weak": "free to translate in y: no part prescribes a y-displacement and no spring (isostatic restoring force) holds it vertically (the springs are too weak to hold anything: k L / E = 1.",
    # Non-finite values from each kind of user function, named with the
    # entry and where they occur.
    "displacement_infinite": "Boundary conditions/base/y>: the expression <1/0> is infinite at",
    "displacement_not_a_number": "Boundary conditions/base/y>: the expression <1e-3*sqrt(x - 5000)> is not a number at",
    "traction_infinite_somewhere": "Loads/Tractions/top/Normal traction>: the expression <x > 5000 ? 1/0 : -1e6> is infinite at",
    "shear_traction_not_a_number": "Shear traction>: the expression <1e5*log(x - 2000)> is not a number at",
    "resultant_profile_not_a_number": "Resultant profile>: the expression <sqrt(x - 5000)> is not a number at",
    "temperature_change_infinite": "Temperature change>: the expression <y < -5000 ? 1/0 : 100> is infinite at",
    "density_infinite": "Density",
    "time_factor_infinite": "Loads/Line forces/Time factor>: the expression <1/t> is infinite at",
    "reference_column_infinite": "Reference column",
    "fluid_density_infinite": "Fluid densities",
    # Resources.
    "mesh_too_large": "Resources/Memory limit>: the first mesh (cycle 0) would have about 1.07e+09 cells",
    "memory_limit_too_small": "the limit set by Resources/Memory limit",
    "memory_limit_unparsable": "Resources/Memory limit",
    # The visco-elastic time loop.
    "negative_viscosity": "Viscosity",
    "maxwell_without_viscosity": "Materials/rock/Viscosity>: must be positive for Rheology = maxwell",
    "elastic_with_viscosity": "Materials/rock/Viscosity>: is given, but Rheology = elastic does not creep",
    "renamed_scheme_value": "renamed_scheme_value.prm:55: Time stepping/Scheme = <implicit> is now called <generalized midpoint> (since 2026-11-25, dc58760); set that",
    "renamed_entry_after_error": "The entry value abc for the entry named Poisson's ratio does not match the given pattern",
    "renamed_gravity_entry": "renamed_gravity_entry.prm:70: the entry <Loads/Gravity/Acceleration> has moved to <Gravity field/Acceleration> (since 2026-11-26, 2c42bf2)",
    "end_time_zero": "Time stepping/End time",
    "plate_age_negative": "Temperature/Plate cooling/Plate age",
    "temperature_below_zero": "Temperature/Function/Expression",
    "creep_without_temperature": "Temperature/Model",
    "dilation_above_friction": "Materials/rock/Dilation angle",
    "softening_interval_reversed": "Materials/rock/Softening plastic strain",
    "visco_elasto_plastic_plane_stress": "Materials/rock/Rheology",
    "visco_elasto_plastic_without_law": "Materials/rock/Rheology",
    "thesis_scheme_nonlinear": "Time stepping/Scheme",
    "maximum_viscosity_below_minimum": "Materials/rock/Maximum viscosity",
    "output_time_after_end": "Time stepping/Output times>: the time 4000 years is outside [0, End time]",
    "resume_without_checkpoint": "Time stepping/Resume>: there is no checkpoint",
    "resume_other_model": "checkpoint-000007 belongs to another model",
    "resume_old_checkpoint": "checkpoint-000007 was written by another version of lithostress (format <lithostress-checkpoint 4>",
    "fault_not_named": "Faults/Names>: the geometry has the fault <fault>: name it here",
    "fault_outside_box": "Geometry/Layered box/Fault surface x>: the fault must cross the box from the top to the base",
    "friction_negative": "Faults/fault/Friction coefficient>: must be at least 0, got -0.1",
    "sliding_tolerance_zero": "Faults/Sliding solver/Linear solver tolerance>: must be positive",
    "thesis_reading_with_newton": "Faults/Sliding solver/Thesis stress reading>: applies to Method = thesis only",
    "sliding_solver_unknown": "The entry value magic for the entry named Linear solver does not match the given pattern",
    "fault_stiffness_zero": "Faults/fault/Shear stiffness>: must be greater than 0, got 0",
    "fault_stiffness_overflows": "Faults/fault/Thesis element length>: gives a stiffness per unit area of 5e+307 Pa/m, beyond 1e+30 Pa/m",
    "fault_stiffness_missing": "Faults/fault/Shear stiffness>: is needed by the elastic law",
    "normal_stiffness_word": "Faults/fault/Normal stiffness>: must be `exact` or a stiffness per unit area [Pa/m], got <rigid>",
    "fault_arc_misses_box": "Geometry/Layered box/Fault arc centre>: the arc misses the box",
    "faults_cross": "Geometry/Layered box/Fault surface x>: the faults <b> and <a> meet or cross in the box (at y = -1.99",
    "gmsh_fault_extension_blocked": "Geometry/Gmsh/Fault curves>: the physical curve <fault>'s lower end at (1 -1) lies inside the mesh, and the mesh has no edges that continue the fault to the boundary",
    "fault_cell_size_too_small": "Geometry/Layered box/Fault cell size>: is less than 1e-6 of the Width",
    "fault_cell_size_too_many_cells": "Geometry/Layered box/Fault cell size>: the graded coarse mesh would have 50000 rows of 38 cells",
    "cell_size_growth_one": "Geometry/Layered box/Cell size growth>: must lie in (1, 4], got 1",
    "displacement_goal_stress_component": "Mesh refinement/Goals/Displacement averages>: goal `crust`: unknown component `sigma_xx` (u_x, u_y)",
    "fault_tip_off_row": "Geometry/Layered box/Fault top depth>: the end of the fault <fault> at the depth 3.300000 must be a row of the coarse mesh",
    "fault_tip_below_base": "Geometry/Layered box/Fault bottom depth>: the lower end of the fault <fault> must lie in the box, below the top and at most at the base, got 12.000000",
    "fault_tips_reversed": "Geometry/Layered box/Fault bottom depth>: the lower end of the fault <fault> must lie below its upper end (Fault top depth)",
    "gmsh_fault_format4": "Geometry/Gmsh/Fault curves>: fault curves need a mesh file in MSH format 2",
    "subduction_circle_off_sea_floor": "Geometry/Subduction zone/Plate boundary centre>: the circle must touch the sea floor at its top",
    "subduction_coast_before_trench": "Geometry/Subduction zone/Coast position>: must lie between the trench and the right edge",
    "slab_pull_zero_dip": "Loads/Slab pull/Dip>: must lie in (0, 90] degrees",
    "slab_pull_upward": "Loads/Slab pull/Vertical force>: must be `balance` or a positive downward pull",
    "slab_pull_nothing_to_balance": "Loads/Slab pull/Vertical force>: is `balance`, but the other loads' net vertical force is",
    "write_coarse_mesh_unwritable": "Geometry/Write coarse mesh>: cannot write </nonexistent-directory/section.msh>",
    "gmsh_concentric_no_line": "Geometry/Gmsh/Concentric arcs>: no line of the mesh lies on these circles",
    "gmsh_fault_unknown_curve": "Geometry/Gmsh/Fault curves>: the mesh has no physical curve <scarp>",
    "rigid_edge_pinned_corner": "Boundary conditions/right/x>: is `rigid`, but another part already prescribes",
    # Goals of the refinement.
    "goal_oriented_without_goals": "Mesh refinement/Indicator>: `goal oriented` needs the goals",
    "goal_unknown_component": "Mesh refinement/Goals/Stress averages>: goal `crust`: unknown component `sigma_rr`",
    "goal_box_outside_body": "Mesh refinement/Goals/Stress averages>: the box of goal `crust` does not meet the body",
    # Broken mesh files and command lines.
    "gmsh_truncated": "gmsh_truncated.msh> is truncated: its $Elements section has no $EndElements",
    "gmsh_missing_node": "gmsh_missing_node.msh>: While creating cell 11 (which is numbered as 12 in the input file), you are referencing a vertex with index 19",
    "gmsh_inverted_cell": "gmsh_inverted_cell.msh>: element 10 is inverted or degenerate (Jacobian <= 0 at a point of the closed cell); vertices (6, -10), (4, -10), (4, 0), (6, 0) km",
    "gmsh_coincident_corners": "gmsh_coincident_corners.msh>: element 8 is inverted or degenerate (Jacobian <= 0 at a point of the closed cell); vertices (5, -10), (10, -10), (5, 0), (5, 0) km",
    "number_underflows": "Materials/rock/Young's modulus>: <1e-308> does not fit a double",
    "gmsh_degenerate_cell": "gmsh_degenerate_cell.msh>: element 10 is inverted or degenerate (Jacobian <= 0 at a point of the closed cell); vertices (4, -10), (4, -10), (4, 0), (4, 0) km",
    "override_without_value": "Mesh refinement/Number of cycles",
    "override_empty_value": "Number of cycles",
}
files = sorted(f[:-4] for f in os.listdir(HERE) if f.endswith(".prm"))
check(len(files) >= 40 and set(files) == set(expected),
      "%d malformed inputs, each with an expected message" % len(files))


def tree(directory):
    """Every file under @directory with its bytes."""
    result = {}
    for root, _, names in os.walk(directory):
        for n in names:
            path = os.path.join(root, n)
            with open(path, "rb") as f:
                result[os.path.relpath(path, directory)] = f.read()
    return result


def run_case(name, ranks):
    """Run the malformed input @name on @ranks ranks against an earlier
    run's output directory of its own; return what the checks need."""
    earlier = os.path.abspath("earlier_results_%s_%d" % (name, ranks))
    shutil.rmtree(earlier, ignore_errors=True)
    os.makedirs(os.path.join(earlier, "figures"))
    with open(os.path.join(earlier, "solution.pvd"), "w") as f:
        f.write("results of an earlier run\n")
    with open(os.path.join(earlier, "figures", "surface_profile.csv"), "w") as f:
        f.write("x,u_x,u_y,y\n0,1,2,3\n")
    if name == "resume_old_checkpoint":
        # A checkpoint of the same model in the format before the rock laws
        # became Rheology plug-ins (2026-12-01).
        os.makedirs(os.path.join(earlier, "checkpoint-000007"))
        with open(os.path.join(earlier, "checkpoint.current"), "w") as f:
            f.write("checkpoint-000007\n")
        with open(os.path.join(earlier, "checkpoint-000007", "state.txt"), "w") as f:
            f.write("lithostress-checkpoint 4\n22 serialization::archive 19 0 0\n")
        with open(os.path.join(earlier, "checkpoint-000007", "model.prm"), "w") as f:
            f.write(open(os.path.join(os.path.dirname(HERE), "viscoelastic", "maxwell_block.prm")).read())
    if name == "resume_other_model":
        # The checkpoint of a stiffer block.
        os.makedirs(os.path.join(earlier, "checkpoint-000007"))
        with open(os.path.join(earlier, "checkpoint.current"), "w") as f:
            f.write("checkpoint-000007\n")
        model = open(os.path.join(os.path.dirname(HERE), "viscoelastic", "maxwell_block.prm")).read()
        with open(os.path.join(earlier, "checkpoint-000007", "model.prm"), "w") as f:
            f.write(model.replace("1e11", "2e11"))
    before = tree(earlier)
    cmd = [BINARY, os.path.join(HERE, name + ".prm")]
    if name == "unwritable_output_directory":
        # A directory below an earlier result file cannot be made.
        cmd += ["--set", "Output directory=" + os.path.join(earlier, "solution.pvd", "new")]
    else:
        cmd += ["--set", "Output directory=" + earlier]
    args = os.path.join(HERE, name + ".args")
    if os.path.exists(args):
        cmd += [a.replace("{here}", HERE) for a in open(args).read().splitlines() if a]
    environment = env()
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
        # Open MPI's own banner about a rank's non-zero exit (mpirun -q).
        environment["OMPI_MCA_orte_execute_quiet"] = "1"
    start = time.time()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, env=environment, timeout=120)
    except subprocess.TimeoutExpired:
        return None
    seconds = time.time() - start
    unchanged = tree(earlier) == before
    shutil.rmtree(earlier, ignore_errors=True)
    return r, seconds, unchanged, earlier


# Three runs at a time, checked in order: the test holds two processors,
# and a run is mostly the start-up of MPI and the libraries, which waits
# more than it computes (a 2-rank case: 2.5 s of wall time, 0.9 s of CPU).
with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
    runs = {(name, ranks): pool.submit(run_case, name, ranks)
            for name in files for ranks in (1, 2)}
slowest = 0.0
for name in files:
    messages = []
    for ranks in (1, 2):
        label = "%s (%d rank%s)" % (name, ranks, "s" if ranks > 1 else "")
        result = runs[(name, ranks)].result()
        if result is None:
            check(False, "%s: ends (killed after 120 s: a hang)" % label)
            continue
        r, seconds, unchanged, earlier = result
        slowest = max(slowest, seconds)
        lines = [l for l in r.stderr.splitlines() if l.strip()]
        check(r.returncode == 1, "%s: exit status %d (expected 1; negative = signal)" % (label, r.returncode))
        check(len(lines) == 1, "%s: one line of error: %s" % (label, " | ".join(lines) if lines else "(none)"))
        check(any(expected.get(name, "\0") in l for l in lines), "%s: message names <%s>" % (label, expected.get(name)))
        check("Stacktrace" not in r.stderr and "An error occurred" not in r.stderr and
              "MPI_ABORT" not in r.stderr and "Signal" not in r.stderr, "%s: no stack trace, abort or signal" % label)
        check(seconds < 30, "%s: ends within seconds (%.1f s)" % (label, seconds))
        check(unchanged, "%s: earlier results byte-identical" % label)
        # Each run has an output directory of its own: compared without it.
        messages.append(lines[0].replace(earlier, "<output directory>") if lines else "")
    # A memory estimate includes each rank's size, so it differs.
    if "would have about" not in expected[name] and "Memory limit" not in expected[name]:
        check(len(messages) == 2 and messages[0] == messages[1], "%s: the same message on 1 and 2 ranks" % name)
print("slowest run: %.1f s" % slowest)
finish()

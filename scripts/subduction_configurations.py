"""The eleven chapter-7 configurations of issue 17 (scripts/
reproduce_subduction.py, scripts/subduction_convergence.py, bench/run
--problems subduction): (name, .prm file under prm/, --set options)."""

DIPS = {"90": 90, "63": 63.43494882, "45": 45, "27": 26.56505118}
CONFIGS = (
    [("density", "subduction_density.prm", [])] +
    [("slab_pull_" + k, "subduction_slab_pull.prm",
      ["Loads/Slab pull/Dip=%.8g" % v]) for k, v in DIPS.items()] +
    [("coupling_" + k, "subduction_coupling.prm",
      ["Faults/plate_boundary/Shear stiffness=" + k])
     for k in ("1e10", "5e9", "1e9")] +
    [("basal_shear", "subduction_basal_shear.prm", []),
     ("thermal", "subduction_thermal.prm", []),
     ("thermal_volumetric", "subduction_thermal.prm",
      ["Loads/Thermal strain/Coefficient type=volumetric"])])

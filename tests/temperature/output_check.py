"""The temperature in the results (doc/equations.md §11): the block of
loads/thermal.prm (10 x 10 km, y from -10 km to 0) under a half-space
cooling plate whose age grows with x (1 Myr per km). Every stress-depth
profile's `temperature` column must be the half-space's
T_s + (T_m - T_s) erf(d / (2 sqrt(kappa t(x)))) at its points (d = -y, the
depth below the Depth origin 0) to 1e-9 relative (the CSV's 10 digits); the
ParaView record must list a `temperature` array; without a Temperature
section neither appears; 2 ranks write the same profile.
The thermal strain may take its Delta T from the temperature model
(Loads/Thermal strain/Temperature change = temperature model,
Delta T = T - Reference temperature): with Temperature/Model = function,
T = 273 + 0.025 (-y), the stresses equal those of the same Delta T given
as the expression 0.025 (-y) to 1e-9 of the largest stress; and with
Temperature/Model = none the entry is refused naming it."""
import sys, os, math, re
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

Ts, Tm, kappa = 280.0, 1600.0, 1e-6
seconds_per_myr = 1e6 * 365.25 * 24 * 3600
common = ["Output/Stress-depth profiles=2.5, 7.5", "Output/Points per profile=11"]
with_temperature = common + ["Temperature/Model=plate cooling",
                             "Temperature/Plate cooling/Plate age=x*1e-3",
                             "Temperature/Plate cooling/Surface temperature=%g" % Ts,
                             "Temperature/Plate cooling/Mantle temperature=%g" % Tm]


def pvtu_arrays(out):
    """The point-data array names of the last ParaView record."""
    names = sorted(f for f in os.listdir(out) if f.endswith(".pvtu"))
    check(len(names) > 0, "%s: a ParaView record is written" % out)
    text = open(os.path.join(out, names[-1])).read() if names else ""
    return re.findall(r'<PDataArray[^>]*Name="([^"]+)"', text)


profiles = {}
for ranks in (1, 2):
    out = os.path.abspath("output_temperature_%d" % ranks)
    run("loads/thermal.prm", out, ranks, with_temperature)
    for label, x in (("x2.5", 2.5e3), ("x7.5", 7.5e3)):
        rows = read_csv(os.path.join(out, "stress_depth_%s.csv" % label))
        check(len(rows) == 11 and all("temperature" in r for r in rows),
              "%d rank(s), %s: 11 rows with a temperature column" % (ranks, label))
        age = x * 1e-3 * seconds_per_myr
        worst = 0.0
        for r in rows:
            d = -r["y"]
            exact = Ts + (Tm - Ts) * math.erf(d / (2 * math.sqrt(kappa * age))) if d > 0 else Ts
            worst = max(worst, abs(r["temperature"] - exact) / exact)
        check(worst < 1e-9, "%d rank(s), %s: the half-space temperature to 1e-9 (%.2e)"
              % (ranks, label, worst))
        profiles[(ranks, label)] = [r["temperature"] for r in rows]
    check("temperature" in pvtu_arrays(out), "%d rank(s): ParaView has a temperature array" % ranks)
for label in ("x2.5", "x7.5"):
    check(profiles[(1, label)] == profiles[(2, label)], "%s: 2 ranks write the 1-rank profile" % label)

out = os.path.abspath("output_temperature_none")
run("loads/thermal.prm", out, 1, common)
rows = read_csv(os.path.join(out, "stress_depth_x2.5.csv"))
check(len(rows) == 11 and "temperature" not in rows[0], "without Temperature: no temperature column")
check("temperature" not in pvtu_arrays(out), "without Temperature: no temperature array")

gradient = ["Temperature/Model=function", "Temperature/Function/Expression=273 + 0.025 * (-y)"]
out_model = os.path.abspath("output_thermal_from_temperature")
run("loads/thermal.prm", out_model, 1, common + gradient +
    ["Loads/Thermal strain/Temperature change=temperature model",
     "Loads/Thermal strain/Reference temperature=273"])
out_expression = os.path.abspath("output_thermal_from_expression")
run("loads/thermal.prm", out_expression, 1, common + gradient +
    ["Loads/Thermal strain/Temperature change=0.025 * (-y)"])
keys = ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz")
for label in ("x2.5", "x7.5"):
    a = read_csv(os.path.join(out_model, "stress_depth_%s.csv" % label))
    b = read_csv(os.path.join(out_expression, "stress_depth_%s.csv" % label))
    scale = max(abs(r[k]) for r in b for k in keys)
    worst = max(abs(x[k] - y[k]) for x, y in zip(a, b) for k in keys)
    check(len(a) == len(b) == 11 and scale > 0 and worst <= 1e-9 * scale,
          "%s: the thermal strain of T - 273 K from the temperature model equals the expression's "
          "(largest difference %.1e of %.3g Pa)" % (label, worst / scale, scale))
refused = run("loads/thermal.prm", os.path.abspath("output_thermal_without_temperature"), 1,
              common + ["Loads/Thermal strain/Temperature change=temperature model"],
              expect_success=False)
lines = [l for l in refused.stderr.splitlines() if l.strip()]
check(refused.returncode == 1 and len(lines) == 1 and "Loads/Thermal strain/Temperature change" in lines[0],
      "Temperature change = temperature model without a temperature: refused in one line naming the entry")
finish()

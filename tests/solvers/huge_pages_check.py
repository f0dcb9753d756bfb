"""The `lithostress` launcher (app/launcher.cc) starts the program with
transparent huge pages for large arrays (GLIBC_TUNABLES=
glibc.malloc.hugetlb=1); LITHOSTRESS_HUGE_PAGES=off starts it without. Where
the pages come from must not change a single digit of the results: the
same arithmetic runs on the same values. Checked on the flexure plate
(multigrid) and the cantilever (AMG): statistics.json says which page size
was used, and the convergence tables and surface profiles of the two runs
are identical to the last printed digit. Also: the launcher passes the
command line through (an unreadable .prm is still a clear error) and a
GLIBC_TUNABLES of the user's own is kept."""
import json
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

with open("/sys/kernel/mm/transparent_hugepage/enabled") as f:
    thp_mode = f.read()
kernel_allows = "[never]" not in thp_mode   # the launcher's request can take effect
kernel_always = "[always]" in thp_mode      # every run has huge pages

for name, prm, sets in [
        ("flexure", os.path.join(SOURCE, "..", "prm", "flexure.prm"),
         ["Mesh refinement/Number of cycles=2", "Output/Figures/Enabled=false",
          "Output/Stress-depth profiles="]),
        ("cantilever", "cantilever/cantilever.prm",
         ["Mesh refinement/Number of cycles=3", "Solver/Type=AMG"])]:
    outputs = {}
    for mode in ("on", "off"):
        out = os.path.abspath("output_huge_pages_%s_%s" % (name, mode))
        extra = {} if mode == "on" else {"LITHOSTRESS_HUGE_PAGES": "off"}
        run(prm, out, 1, sets, extra_env=extra)
        with open(os.path.join(out, "statistics.json")) as f:
            stats = json.load(f)
        expected = kernel_always or ((mode == "on") and kernel_allows)
        check(stats["huge_pages"] == expected,
              "%s: huge_pages = %s with the launcher %s (kernel allows: %s)"
              % (name, stats["huge_pages"], mode, kernel_allows))
        outputs[mode] = out
    for result in ("convergence.csv", "surface_profile.csv"):
        paths = [os.path.join(outputs[m], result) for m in ("on", "off")]
        if not os.path.exists(paths[0]):
            continue
        texts = [open(p).read() for p in paths]
        check(texts[0] == texts[1] and len(texts[0]) > 0,
              "%s: %s identical with and without huge pages (%d bytes)"
              % (name, result, len(texts[0])))

# The user's own tunables are kept, and huge pages added to them.
out = os.path.abspath("output_huge_pages_tunables")
run("cantilever/cantilever.prm", out, 1, ["Mesh refinement/Number of cycles=1"],
    extra_env={"GLIBC_TUNABLES": "glibc.malloc.arena_max=2"})
with open(os.path.join(out, "statistics.json")) as f:
    check(json.load(f)["huge_pages"] == (kernel_always or kernel_allows),
          "a GLIBC_TUNABLES of the user's own: huge pages added to it")
if kernel_allows and not kernel_always:
    with open(os.path.join(out, "log.txt")) as f:
        log = f.read()
    check("glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1" in log,
          "the user's own tunable is kept in front of the launcher's")

# The launcher passes the command line through unchanged.
result = run("no_such_file.prm", os.path.abspath("output_huge_pages_missing"),
             expect_success=False)
check(result.returncode != 0 and "no_such_file.prm" in result.stdout + result.stderr,
      "a missing .prm through the launcher: exit %d, the file named"
      % result.returncode)
finish()

#!/usr/bin/env python3
"""Check that includes between the folders of include/lithostress and
source/ point one way: a folder may include only itself and the folders
listed before it (doc/architecture.md, "Layers"). Prints every upward
include and exits 1 if there is one."""
import os
import re
import sys

LAYERS = ["base", "geometry", "temperature", "materials", "reference_solutions",
          "discretization", "loads", "boundary_conditions", "assembly",
          "solvers", "faults", "analysis", "refinement",
          "time_integration", "postprocessors", "simulator"]

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
include = re.compile(r'#include <lithostress/([a-z_]+)/')
bad = 0
for top in ("include/lithostress", "source"):
    for folder, _, files in os.walk(os.path.join(root, top)):
        rel = os.path.relpath(folder, os.path.join(root, top))
        layer = rel.split(os.sep)[0]
        if rel == "." and not [f for f in files if not f.startswith(".")]:
            continue
        if layer not in LAYERS:
            print("folder %s/%s is in no layer" % (top, rel))
            bad += 1
            continue
        for name in files:
            path = os.path.join(folder, name)
            for number, line in enumerate(open(path), 1):
                m = include.match(line)
                if m and LAYERS.index(m.group(1)) > LAYERS.index(layer):
                    rel_path = os.path.relpath(path, root)
                    print("%s:%d: %s includes the higher layer %s"
                          % (rel_path, number, layer, m.group(1)))
                    bad += 1
print("%d upward include(s)" % bad)
sys.exit(1 if bad else 0)

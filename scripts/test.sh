#!/bin/bash
# The test suite: install dependencies, build in Debug (build-debug/, with
# deal.II's assertions) and run every ctest test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-dependencies.sh"
bash "$root/scripts/build.sh" build-debug Debug
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$root/build-debug"
ctest --output-on-failure -j1 "$@"

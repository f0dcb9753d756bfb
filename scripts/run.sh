#!/bin/bash
# The main job: install dependencies, build (Release, build/lithostress) and
# run the default experiment, or the .prm given as argument.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-dependencies.sh"
bash "$root/scripts/build.sh" build Release
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$root"
exec "$root/build/lithostress" "${1:-prm/flexure.prm}" "${@:2}"

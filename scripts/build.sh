#!/bin/bash
# Configure (once) and build lithostress: scripts/build.sh <dir> <Debug|Release>
set -euo pipefail
dir=${1:-build}
type=${2:-Release}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$root/$dir"
cd "$root/$dir"
if [ ! -f CMakeCache.txt ] || ! grep -q "CMAKE_BUILD_TYPE:STRING=$type" CMakeCache.txt; then
  cmake -DCMAKE_BUILD_TYPE="$type" "$root" >/dev/null
fi
make -j"$(nproc)" --no-print-directory lithostress 2>&1 | grep -v "^\[" || true
test -x "$root/$dir/lithostress"

#!/bin/bash
# Configure (once) and build lithostress: scripts/build.sh <dir> <Debug|Release>
# (LITHOSTRESS_SANITIZE=ON in the environment: with ASan + UBSan;
# LITHOSTRESS_SIMD=AUTO (default: AVX2 where the CPU has it), OFF, AVX2 or
# AVX512: the vectorised matrix-free operator)
set -euo pipefail
dir=${1:-build}
type=${2:-Release}
root=$(cd "$(dirname "$0")/.." && pwd)
# A relative <dir> is inside the source tree, an absolute one is taken as is.
case "$dir" in
  /*) path=$dir ;;
  *) path=$root/$dir ;;
esac
mkdir -p "$path"
cd "$path"
sanitize=${LITHOSTRESS_SANITIZE:-OFF}
simd=${LITHOSTRESS_SIMD:-AUTO}
if [ ! -f CMakeCache.txt ] || ! grep -q "CMAKE_BUILD_TYPE:STRING=$type" CMakeCache.txt ||
   ! grep -q "LITHOSTRESS_SANITIZE:BOOL=$sanitize" CMakeCache.txt ||
   ! grep -q "LITHOSTRESS_SIMD:STRING=$simd" CMakeCache.txt; then
  cmake -DCMAKE_BUILD_TYPE="$type" -DLITHOSTRESS_SANITIZE="$sanitize" \
        -DLITHOSTRESS_SIMD="$simd" "$root" >/dev/null
fi
# Build every target (the program and the unit-test programs); progress
# lines are filtered, a failing build still fails this script (pipefail).
make -j"$(nproc)" --no-print-directory 2>&1 | { grep -v "^\[" || true; }
test -x "$path/lithostress"

#!/bin/bash
# The test suite: install dependencies, build in Debug (build-debug/, with
# deal.II's assertions) and run every ctest test.
#   bash scripts/test.sh [ctest arguments]
#   bash scripts/test.sh --sanitize [ctest arguments]
#       the same with AddressSanitizer + UndefinedBehaviorSanitizer
#       (build-sanitize/; about three times slower)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=build-debug
sanitize=OFF
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-sanitize
  sanitize=ON
  shift
fi
bash "$root/scripts/install-dependencies.sh"
LITHOSTRESS_SANITIZE=$sanitize bash "$root/scripts/build.sh" "$dir" Debug
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if [ "$sanitize" = ON ]; then
  # Open MPI and Trilinos keep allocations until exit by design: leak
  # reports would be theirs. Every other error stops the program.
  export ASAN_OPTIONS=detect_leaks=0:abort_on_error=0:halt_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fi
cd "$root/$dir"
ctest --output-on-failure -j"$(nproc)" "$@"

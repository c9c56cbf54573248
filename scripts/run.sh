#!/usr/bin/env bash
# The main job: sets up what is missing, builds, and runs the example with the
# arguments given (defaults: the demonstration on the default specimen).
#   BUILD_DIR   build folder (default: build)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
kokkos=$("$here/scripts/setup.sh" | tail -n 1)
build=${BUILD_DIR:-$here/build}
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$kokkos" >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target vrut-demo
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-$(nproc)}
exec "$build/examples/vrut-demo" "$@"

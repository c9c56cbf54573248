#!/usr/bin/env bash
# The main job: sets up what is missing, builds, and runs the virtual rutting
# test (vrut-rutting) with the arguments given; without any, mix 2# on the
# default specimen, results in out/rutting.
#   BUILD_DIR   build folder (default: build)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
kokkos=$("$here/scripts/setup.sh" | tail -n 1)
build=${BUILD_DIR:-$here/build}
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$kokkos" >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target vrut-rutting
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-$(nproc)}
exec "$build/examples/vrut-rutting" "$@"

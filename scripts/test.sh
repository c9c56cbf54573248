#!/usr/bin/env bash
# Builds vrut and runs the whole test suite (sets up what is missing first).
#   BUILD_DIR   build folder (default: build)
#   CTEST_ARGS  extra arguments for ctest, e.g. "-L physics" or "-LE cuda|fuzz|sanitize"
# Every test has one label: physics, unit, protocol (the Catch2 tests, by
# their tags), examples (the command-line programs), build (headers, law
# concept, package, C++20), cuda, fuzz, sanitize. "ctest --print-labels" lists them.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
kokkos=$("$here/scripts/setup.sh" | tail -n 1)
build=${BUILD_DIR:-$here/build}
jobs=$(nproc)
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$kokkos"
cmake --build "$build" --parallel "$jobs"
cd "$build"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} OMP_PROC_BIND=${OMP_PROC_BIND:-false}
# Side by side as each test's PROCESSORS allow (tests/CMakeLists.txt): on 2
# cores, the single-threaded tests two at a time, the others alone.
# shellcheck disable=SC2086
ctest --output-on-failure --timeout 600 --parallel "$jobs" ${CTEST_ARGS:-}

#!/usr/bin/env bash
# Builds vrut and runs the whole test suite (sets up what is missing first).
#   BUILD_DIR   build folder (default: build)
#   CTEST_ARGS  extra arguments for ctest, e.g. "-L physics" or "-LE cuda|fuzz|sanitize"
# Every test has one label: physics, unit, protocol (the Catch2 tests, by
# their tags), examples (the command-line programs), build (headers, law
# concept, package, C++20), cuda, fuzz, sanitize, python (the Python module).
# "ctest --print-labels" lists them.
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
# ctest's own exit code is the script's; the skipped tests' reasons follow
# its summary.
code=0
# shellcheck disable=SC2086
ctest --output-on-failure --timeout 600 --parallel "$jobs" ${CTEST_ARGS:-} | tee ctest.out || code=$?
# ctest names the tests it skipped (SKIP_RETURN_CODE 77) but not why:
# --output-on-failure shows no skip's output, and LastTest.log records a skip
# as passed. Each skipping script says why on a line of its own, "SKIPPED:
# ..." (tests/*.sh): that line, under each skipped test's name.
skipped=$(sed -n 's/^[[:space:]]*[0-9][0-9]* - \(.*\) (Skipped)$/\1/p' ctest.out)
if [[ -n $skipped ]]; then
  echo "Why they were skipped:"
  while read -r name; do
    reason=$(awk -v name="$name" '/^[0-9]+\/[0-9]+ Testing: / { current = substr($0, index($0, ": ") + 2) }
                                  current == name && /^[[:space:]]*SKIPPED: / { sub(/^[[:space:]]*/, ""); print; exit }' Testing/Temporary/LastTest.log)
    echo "  $name: ${reason:-(no SKIPPED: line in its output; see Testing/Temporary/LastTest.log)}"
  done <<<"$skipped"
fi
exit "$code"

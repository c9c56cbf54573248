#!/usr/bin/env bash
# The unit, physics and pinned tests and the bad-input tests once more, built with
# AddressSanitizer and UndefinedBehaviorSanitizer: any report fails the test.
# clang at -O0 compiles three times faster than at -O1, which keeps this
# within the suite's time; the tests it runs are small. MPI is left out:
# OpenMPI's own start-up allocations would read as leaks (said in the output;
# this script runs no MPI test, and the MPI test of this build folder, were
# one to run it, skips as "left out on purpose" rather than fail).
# Skipped (77) without clang.
#   Usage: sanitize.sh SOURCE_DIR BUILD_DIR KOKKOS_ROOT
set -uo pipefail
src=$1 build=$2 kokkos=$3
command -v clang++ >/dev/null || { echo "SKIPPED: no clang++ (apt-get install clang)"; exit 77; }
flags="-O0 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=None -DKokkos_ROOT="$kokkos" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DVRUT_BUILD_BENCHMARKS=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON -DVRUT_PYTHON=OFF >"$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; echo "FAIL: configuring the sanitizer build"; exit 1; }
echo "note: MPI left out of this build on purpose (CMAKE_DISABLE_FIND_PACKAGE_MPI=ON): vrut-rutting runs here as one"
echo "      process; the two-rank test is examples.rutting_mpi_two_ranks, in the main build"
exes=(vrut-tests-sanitize vrut-demo vrut-creep vrut-specimen vrut-rutting)
cmake --build "$build" --target "${exes[@]}" 2>&1 | grep -E "error|\[[0-9]+/[0-9]+\]"
[[ ${PIPESTATUS[0]} -eq 0 ]] || { echo "FAIL: the sanitizer build"; exit 1; }
# A report exits with its own code (86), never 1 or 2 (which the bad-input
# tests expect), and halts at the first one; cli_errors.sh fails on that code
# and on any report in the output (VRUT_SANITIZED).
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:exitcode=86
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:exitcode=86
# Other libraries' allocations kept until exit by design (lsan.supp says which).
export LSAN_OPTIONS=suppressions=$src/tests/lsan.supp:print_suppressions=0
export VRUT_SANITIZED=1 OMP_NUM_THREADS=2 OMP_PROC_BIND=false
failures=0
log=$build/sanitize.log
: >"$log"
# One tag a run, each with --warn NoTests: a tag that matches nothing (a
# renamed or misspelt one) fails instead of running nothing.
# The pinned runs that are small enough here ([pinned][small]: the 2D
# defaults' section, about a minute at -O0, and a short 3D run): the others
# take 30 times their -O2 time under the sanitizers, many minutes each.
# The physics tests on the OpenMP backend only (a template test's
# "ExecutionSpaces - 0" is its Serial instance): the same kernels, and the
# two bonded blocks' Serial instances alone took 74 of the 127 s here.
for tag in "[unit]" "[input]" "[checkpoint]" "[instability]" "[physics]~*ExecutionSpaces - 0" "[pinned][small]"; do
  "$build/tests/vrut-tests-sanitize" --warn NoTests "$tag" >>"$log" 2>&1 ||
    { echo "FAIL: the $tag tests under the sanitizers (exit $?)"; failures=$((failures + 1)); }
done
# The bad-input tests, two programs at a time on one thread each: most of
# their time is single-threaded work at -O0 (specimens, images), so two lanes
# fill the two cores. Each program's output is kept apart, then appended.
bad_input() {  # bad_input EXAMPLE: its checks into its own log; the exit code is theirs
  OMP_NUM_THREADS=1 VRUT_ERRORS_ONLY=1 "$src/tests/cli_errors.sh" "$1" "$build/examples/vrut-$1" >"$build/bad_input_$1.log" 2>&1
}
lane() { local code=0; for example in "$@"; do bad_input "$example" || { echo "$example"; code=1; }; done; return $code; }
lane specimen demo >"$build/lane_a.failed" & lane_a=$!
lane rutting creep >"$build/lane_b.failed"; code_b=$?
wait "$lane_a"; code_a=$?
for example in demo creep specimen rutting; do cat "$build/bad_input_$example.log" >>"$log"; done
for example in $(cat "$build/lane_a.failed" "$build/lane_b.failed"); do
  echo "FAIL: $example's bad-input tests under the sanitizers"; failures=$((failures + 1))
done
[[ $code_a -eq 0 && $code_b -eq 0 ]] || [[ $failures -gt 0 ]] || { echo "FAIL: a bad-input lane"; failures=$((failures + 1)); }
if grep -qE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$log"; then
  echo "FAIL: sanitizer reports:"; grep -E -A 12 "ERROR: (Address|Leak)Sanitizer|runtime error:" "$log" | head -n 60
  failures=$((failures + 1))
fi
[[ $failures -eq 0 ]] || { grep -E "FAIL|FAILED" "$log" | head -n 20; exit 1; }
grep -E "^(test cases|All tests passed)" "$log"
echo "PASS: unit tests and bad-input tests with ASan and UBSan, no report"

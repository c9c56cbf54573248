#!/usr/bin/env bash
# Built with AddressSanitizer and UndefinedBehaviorSanitizer, any report
# failing the test: the bad-input tests of every program, and the tagged
# cases (`tags` below) of the sixteen test files that vrut-tests-sanitize
# compiles (tests/CMakeLists.txt names them: the engine's, the protocol's
# runs, checkpoints and skeleton). Not here, for the compile time they would
# add at -O0: the files of the Choice slot, the filler, the binder film, the
# cell list, compaction, ensembles, images and the FCC packing; the
# summary and CSV writers (the bad-input tests leave out the runs that
# succeed, VRUT_ERRORS_ONLY), the MPI gather and vrut-pool.
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
export VRUT_SANITIZED=1 OMP_PROC_BIND=false
failures=0
log=$build/sanitize.log
: >"$log"
# The checks, each a job with its own log, run two at a time on one thread
# each (xargs -P 2 hands the next job to the first lane free, the longest
# first): most of them are single-threaded work at -O0, and on two threads
# the OpenMP ones spent a third of their time in spin barriers, so two lanes
# of one thread fill the two cores: 104 s here on 2026-12-06, against 174 s
# one job at a time on two threads (the pinned runs 53 s of that, most of it
# the 2D defaults' whole section, now a short run of them). The threads'
# interplay is checked by the main build's Serial-against-OpenMP tests, bit
# for bit.
#  - One Catch2 tag a job, each with --warn NoTests: a tag that matches
#    nothing (a renamed or misspelt one) fails instead of running nothing.
#    The pinned runs short enough here ([pinned][small]: short runs of the
#    2D defaults and of a 3D box, about 30 s together): the others take 30
#    times their -O2 time under the sanitizers, a minute to many each. The
#    physics tests on the OpenMP backend only (a template test's
#    "ExecutionSpaces - 0" is its Serial instance): the same kernels, and the
#    two bonded blocks' Serial instances alone took 74 of the 127 s here.
#  - The bad-input tests of each program (cli_errors.sh).
tags=("[physics]~*ExecutionSpaces - 0" "[pinned][small]" "[checkpoint]" "[instability]" "[unit]" "[input]")
programs=(specimen rutting creep demo)
run_job() {  # run_job tag N | run_job program NAME: the job's output into its own log, its exit code
  if [[ $1 == tag ]]; then
    "$build/tests/vrut-tests-sanitize" --warn NoTests "${tags[$2]}" >"$build/job_tag_$2.log" 2>&1 ||
      { local code=$?; echo "FAIL: the ${tags[$2]} tests under the sanitizers (exit $code)"; return 1; }
  else
    VRUT_ERRORS_ONLY=1 "$src/tests/cli_errors.sh" "$2" "$build/examples/vrut-$2" >"$build/job_program_$2.log" 2>&1 ||
      { echo "FAIL: $2's bad-input tests under the sanitizers"; return 1; }
  fi
}
export -f run_job
export src build
rm -f "$build"/job_*.log  # a job that does not run leaves no log of an earlier run behind
# Every tag and every program is a job, made from the two lists above (so
# none can be left out of the run), longest first by the seconds each took
# at -O0 on one thread; one not timed here yet goes first.
declare -A seconds=(["tag 0"]=55 ["tag 1"]=30 ["program specimen"]=30 ["tag 2"]=25 ["tag 3"]=15
                    ["program rutting"]=15 ["tag 4"]=10 ["program creep"]=8 ["program demo"]=5 ["tag 5"]=3)
mapfile -t jobs < <({ for i in "${!tags[@]}"; do echo "${seconds["tag $i"]:-1000} tag $i"; done
                      for p in "${programs[@]}"; do echo "${seconds["program $p"]:-1000} program $p"; done; } |
                    sort -k1,1nr | cut -d' ' -f2-)
# Each job's FAIL line on stdout; xargs exits 123 when any job failed.
failed=$(printf '%s\n' "${jobs[@]}" |
  OMP_NUM_THREADS=1 xargs -P 2 -I JOB bash -c "$(declare -p tags); run_job JOB")
code=$?
# A job that did not run left no log: that fails the test too.
for i in "${!tags[@]}"; do
  cat "$build/job_tag_$i.log" >>"$log" 2>/dev/null || failed+=$'\n'"FAIL: the ${tags[$i]} tests did not run"
done
for p in "${programs[@]}"; do
  cat "$build/job_program_$p.log" >>"$log" 2>/dev/null || failed+=$'\n'"FAIL: $p's bad-input tests did not run"
done
failed=$(sed '/^$/d' <<<"$failed")
if [[ -n $failed ]]; then echo "$failed"; failures=$((failures + $(grep -c . <<<"$failed"))); fi
[[ $code -eq 0 ]] || [[ $failures -gt 0 ]] || { echo "FAIL: the jobs' runner (xargs exit $code)"; failures=$((failures + 1)); }
if grep -qE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$log"; then
  echo "FAIL: sanitizer reports:"; grep -E -A 12 "ERROR: (Address|Leak)Sanitizer|runtime error:" "$log" | head -n 60
  failures=$((failures + 1))
fi
[[ $failures -eq 0 ]] || { grep -E "FAIL|FAILED" "$log" | head -n 20; exit 1; }
grep -E "^(test cases|All tests passed)" "$log"
echo "PASS: unit tests and bad-input tests with ASan and UBSan, no report"

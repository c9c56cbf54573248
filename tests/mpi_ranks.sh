#!/usr/bin/env bash
# mpirun -np 2 vrut-rutting --seeds 1-3 shares the seeds between two ranks
# (two on rank 0, one on rank 1) and gathers one summary: the same curves,
# per-seed table and statistics as one process running all three. The same
# in 3D (--dim 3 --seeds 1-2, a small box of 2 mm spheres: one seed a rank).
# Interrupted (Ctrl-C to the ranks in 2D and 3D, SIGTERM to mpirun in 2D),
# every rank's checkpoint is kept and the resume on two ranks ends as the
# run never stopped; a resume on one rank, and more ranks than seeds, are
# refused; one rank failing alone (its checkpoint damaged) ends the job.
# Skipped (77) only where MPI is not here: this build left it out on purpose
# (mpi-left-out: CMAKE_DISABLE_FIND_PACKAGE_MPI, as sanitize.sh does), or
# CMake found none and none is installed (no mpirun, mpiexec or mpicxx on
# PATH). MPI that is installed but broken fails, never skips: CMake did not
# find it though an mpirun or mpicxx is on PATH, or vrut-rutting was built
# with MPI and there is no mpirun, or mpirun itself fails. Anything else
# that goes wrong fails too.
# Usage: mpi_ranks.sh VRUT_RUTTING with-mpi|without-mpi|mpi-left-out
set -u
exe=$1 built=$2
case $built in
  with-mpi) ;;
  mpi-left-out)
    echo "SKIPPED: this build leaves MPI out on purpose (CMAKE_DISABLE_FIND_PACKAGE_MPI=ON)"; exit 77 ;;
  without-mpi)
    installed=$(command -v mpirun mpiexec mpicxx | paste -sd ' ')
    [[ -z $installed ]] || {
      echo "FAIL: MPI is installed ($installed) but CMake did not find it, so vrut-rutting was built without"
      echo "      MPI: a broken install (see the configure log; apt-get install libopenmpi-dev), or"
      echo "      configure with -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON to leave MPI out on purpose"
      exit 1
    }
    echo "SKIPPED: no MPI (vrut-rutting built without it, no mpirun or mpicxx on PATH; apt-get install libopenmpi-dev)"
    exit 77 ;;
  *) echo "FAIL: usage: mpi_ranks.sh VRUT_RUTTING with-mpi|without-mpi|mpi-left-out (got '$built')"; exit 1 ;;
esac
command -v mpirun >/dev/null ||
  { echo "FAIL: vrut-rutting was built with MPI but there is no mpirun on PATH (apt-get install openmpi-bin)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
# OpenMPI refuses root unless told; CI machines run as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
small=(--width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e5 --settle-steps 300 --seeds 1-3)
# The two ranks first: an mpirun that cannot start fails at once.
mpirun -np 2 -x OMP_NUM_THREADS=1 -x OMP_PROC_BIND "$exe" "${small[@]}" --out two >two.out 2>&1 ||
  { echo "FAIL: two ranks: $(tail -n 5 two.out)"; exit 1; }
OMP_NUM_THREADS=2 "$exe" "${small[@]}" --out one >one.out 2>&1 || { echo "FAIL: one process: $(tail -n 3 one.out)"; exit 1; }
failures=0
grep -q '"mpi_ranks": 2' two/summary.json || { echo "FAIL: a build with MPI ran as one rank: $(grep mpi_ranks two/summary.json)"; exit 1; }
# The seeds were really shared: each per-seed entry names the rank that ran it.
ranks=$(grep -o '"rank": [0-9]*' two/summary.json | tr -dc '0-9\n' | paste -sd,)
if [[ $ranks == "0,0,1" ]]; then echo "ok:   seeds 1 and 2 ran on rank 0, seed 3 on rank 1"; else
  echo "FAIL: the seeds ran on ranks $ranks, not 0,0,1"; failures=$((failures + 1)); fi
strip() { grep -vE '"(wall_seconds|particle_steps_per_second|threads|mpi_ranks|rank)"' "$1"; }
same_results() {  # folder of one process, of two ranks, what
  for f in deformation.csv seeds.csv; do
    if cmp -s "$1/$f" "$2/$f"; then echo "ok:   $3$f the same"; else echo "FAIL: $3$f differs"; failures=$((failures + 1)); fi
  done
  if diff <(strip "$1/summary.json") <(strip "$2/summary.json"); then echo "ok:   $3summary.json the same"; else
    echo "FAIL: $3summary.json differs"; failures=$((failures + 1)); fi
}
same_results one two ""

# alpha_T 2e5: about 400 loading steps, long enough for the interrupt below to
# come while it loads; 1#, whose stones place in a fraction of a second here.
small3=(--dim 3 --gradation 1 --width-mm 40 --sphere-radius-mm 2 --shift 2e5 --settle-steps 300 --seeds 1-2)
mpirun -np 2 -x OMP_NUM_THREADS=1 -x OMP_PROC_BIND "$exe" "${small3[@]}" --out two3 >two3.out 2>&1 ||
  { echo "FAIL: 3D, two ranks: $(tail -n 5 two3.out)"; exit 1; }
OMP_NUM_THREADS=2 "$exe" "${small3[@]}" --out one3 >one3.out 2>&1 || { echo "FAIL: 3D, one process: $(tail -n 3 one3.out)"; exit 1; }
grep -q '"mpi_ranks": 2' two3/summary.json || { echo "FAIL: 3D ran as one rank: $(grep mpi_ranks two3/summary.json)"; exit 1; }
ranks=$(grep -o '"rank": [0-9]*' two3/summary.json | tr -dc '0-9\n' | paste -sd,)
if [[ $ranks == "0,1" ]]; then echo "ok:   3D: seed 1 ran on rank 0, seed 2 on rank 1"; else
  echo "FAIL: 3D: the seeds ran on ranks $ranks, not 0,1"; failures=$((failures + 1)); fi
same_results one3 two3 "3D: "

# Interrupted: every rank's checkpoint kept in the output folder beside the
# partial results, the way to go on named with its launcher, and that
# resume (on as many ranks) ending as the run never stopped. The signal as a
# terminal's Ctrl-C gives it (SIGINT to the ranks themselves) in 2D and 3D,
# and as a scheduler gives it (SIGTERM to mpirun) in 2D.
wait_for_files() {  # wait_for_files FILE... : at most 60 s
  local f ready
  for _ in $(seq 1200); do
    ready=1
    for f in "$@"; do [[ -s $f ]] || ready=0; done
    ((ready)) && return 0
    sleep 0.05
  done
  return 1
}
interrupted_and_resumed() {  # DIR WHOLE_DIR SIGNAL ranks|mpirun WHAT ARGS...
  local dir=$1 whole_dir=$2 signal=$3 target=$4 what=$5 pid code; shift 5
  local files=("$dir/checkpoint-rank-0-of-2.vrut" "$dir/checkpoint-rank-1-of-2.vrut")
  mpirun -np 2 -x OMP_NUM_THREADS=1 -x OMP_PROC_BIND "$exe" "$@" --checkpoint-every 0.1 --out "$dir" >"$dir.out" 2>&1 &
  pid=$!
  wait_for_files "${files[@]}" || { echo "FAIL: $what: not both ranks' checkpoints within 60 s: $(tail -n 3 "$dir.out")"; failures=$((failures + 1)); }
  if [[ $target == ranks ]]; then pkill "-$signal" -P "$pid"; else kill "-$signal" "$pid"; fi
  wait "$pid"; code=$?
  if [[ $code -ne 0 ]]; then echo "ok:   $what: exit $code"; else echo "FAIL: $what: exit 0 after SIG$signal"; failures=$((failures + 1)); fi
  grep -q '"interrupted": true' "$dir/summary.json" 2>/dev/null ||
    { echo "FAIL: $what: no partial summary.json: $(tail -n 5 "$dir.out")"; failures=$((failures + 1)); }
  for f in "${files[@]}"; do
    [[ -s $f ]] || { echo "FAIL: $what: $f lost ($(ls "$dir" | paste -sd ' '))"; failures=$((failures + 1)); }
  done
  grep -q "go on with: mpirun -np 2 vrut-rutting --resume $dir" "$dir.out" ||
    { echo "FAIL: $what: the way to go on lacks its launcher: $(grep 'go on' "$dir.out")"; failures=$((failures + 1)); }
  # One rank is not two: refused, saying how many the run had.
  "$exe" --resume "$dir" >"$dir.one.out" 2>&1; code=$?
  if [[ $code -eq 2 ]] && grep -q "run on 2 rank(s).*mpirun -np 2 vrut-rutting --resume $dir" "$dir.one.out"; then
    echo "ok:   $what: a resume on one rank refused"
  else echo "FAIL: $what: a resume on one rank -> exit $code: $(cat "$dir.one.out")"; failures=$((failures + 1)); fi
  # One rank failing alone (its checkpoint damaged) ends the whole job with
  # its message and a non-zero exit, within a minute: the other rank does
  # not wait for it for ever, and the folder keeps its files.
  cp -r "$dir" "$dir.damaged"
  head -c 1000 "$dir/checkpoint-rank-1-of-2.vrut" >"$dir.damaged/checkpoint-rank-1-of-2.vrut"
  timeout -k 10 60 mpirun -np 2 -x OMP_NUM_THREADS=1 -x OMP_PROC_BIND "$exe" --resume "$dir.damaged" >"$dir.damaged.out" 2>&1; code=$?
  if [[ $code -ne 0 && $code -ne 124 ]] && grep -q "checkpoint-rank-1-of-2.vrut is damaged" "$dir.damaged.out" &&
     [[ -s $dir.damaged/checkpoint-rank-0-of-2.vrut ]]; then
    echo "ok:   $what: one rank failing alone ends the job (exit $code)"
  else echo "FAIL: $what: one rank's damaged checkpoint -> exit $code: $(grep -v '^\s*$' "$dir.damaged.out" | head -n 3)"; failures=$((failures + 1)); fi
  mpirun -np 2 -x OMP_NUM_THREADS=1 -x OMP_PROC_BIND "$exe" --resume "$dir" >"$dir.resumed.out" 2>&1 ||
    { echo "FAIL: $what: the resume failed: $(tail -n 5 "$dir.resumed.out")"; failures=$((failures + 1)); }
  grep -q "^resumed: minute" "$dir.resumed.out" ||
    { echo "FAIL: $what: the resume does not say where it took the test up"; failures=$((failures + 1)); }
  same_results "$whole_dir" "$dir" "$what, resumed: "
}
# 2D at alpha_T 4e3 (about 3 s of loading, a seed a rank), so that the
# signal comes while it loads; the run never stopped on the two ranks first.
long=(--width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 4e3 --settle-steps 300 --seeds 1-2)
mpirun -np 2 -x OMP_NUM_THREADS=1 -x OMP_PROC_BIND "$exe" "${long[@]}" --out long >long.out 2>&1 ||
  { echo "FAIL: 2D, the long run: $(tail -n 5 long.out)"; exit 1; }
interrupted_and_resumed cut long INT ranks "2D, Ctrl-C" "${long[@]}"
interrupted_and_resumed cut_term long TERM mpirun "2D, SIGTERM to mpirun" "${long[@]}"
interrupted_and_resumed cut3 two3 INT ranks "3D, Ctrl-C" "${small3[@]}"

# More ranks than seeds: refused, saying why, with a non-zero exit (each
# rank refuses, so none waits for another).
mpirun -np 4 -x OMP_NUM_THREADS=1 "$exe" "${small[@]}" --out four >four.out 2>&1; code=$?
if [[ $code -ne 0 ]] && grep -q "4 MPI ranks for 3 seed(s)" four.out; then echo "ok:   4 ranks for 3 seeds refused (exit $code)"
else echo "FAIL: 4 ranks for 3 seeds -> exit $code: $(tail -n 3 four.out)"; failures=$((failures + 1)); fi
[[ -e four ]] && { echo "FAIL: 4 ranks for 3 seeds left a folder"; failures=$((failures + 1)); }
exit $((failures > 0))
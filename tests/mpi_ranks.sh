#!/usr/bin/env bash
# mpirun -np 2 vrut-rutting --seeds 1-3 shares the seeds between two ranks
# (two on rank 0, one on rank 1) and gathers one summary: the same curves,
# per-seed table and statistics as one process running all three. The same
# in 3D (--dim 3 --seeds 1-2, a small box of 2 mm spheres: one seed a rank).
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

small3=(--dim 3 --width-mm 40 --sphere-radius-mm 2 --shift 1e6 --settle-steps 300 --seeds 1-2)
mpirun -np 2 -x OMP_NUM_THREADS=1 -x OMP_PROC_BIND "$exe" "${small3[@]}" --out two3 >two3.out 2>&1 ||
  { echo "FAIL: 3D, two ranks: $(tail -n 5 two3.out)"; exit 1; }
OMP_NUM_THREADS=2 "$exe" "${small3[@]}" --out one3 >one3.out 2>&1 || { echo "FAIL: 3D, one process: $(tail -n 3 one3.out)"; exit 1; }
grep -q '"mpi_ranks": 2' two3/summary.json || { echo "FAIL: 3D ran as one rank: $(grep mpi_ranks two3/summary.json)"; exit 1; }
ranks=$(grep -o '"rank": [0-9]*' two3/summary.json | tr -dc '0-9\n' | paste -sd,)
if [[ $ranks == "0,1" ]]; then echo "ok:   3D: seed 1 ran on rank 0, seed 2 on rank 1"; else
  echo "FAIL: 3D: the seeds ran on ranks $ranks, not 0,1"; failures=$((failures + 1)); fi
same_results one3 two3 "3D: "
exit $((failures > 0))

#!/usr/bin/env bash
# vrut beside LAMMPS on the same job and the same cores: a hex-packed block of
# disks settling under gravity in a box of three walls; 2D, linear (Hooke)
# normal and tangential springs with Coulomb friction and no damping
# (LAMMPS: pair gran/hooke/history, fix wall/gran hooke/history), the same
# stiffness, friction, mass, time step, disk positions and walls. Runs each
# size in vrut (OpenMP, all cores) and then in LAMMPS (MPI, one rank a core),
# one after the other, and prints both throughputs and their ratio.
#   BUILD_DIR   vrut's build folder (default: build; built if needed)
#   SIZES       "columns:rows:steps ..." (default: about 16k and 64k disks)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
cores=$(nproc)
sizes=${SIZES:-"180:90:2000 360:180:500"}

if ! command -v lmp >/dev/null || ! command -v mpirun >/dev/null; then
  [[ $(id -u) -eq 0 ]] || { echo "install Debian's lammps and openmpi-bin (sudo apt-get install lammps openmpi-bin)" >&2; exit 1; }
  echo "installing Debian's lammps and openmpi-bin" >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends lammps openmpi-bin >&2
fi
if [[ ! -x "$build/benchmarks/vrut-bench-block" ]]; then
  kokkos=$("$here/scripts/setup.sh" | tail -n 1)
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$kokkos" >/dev/null
  cmake --build "$build" --target vrut-bench-block >&2
fi
work=$(mktemp -d)
trap '[[ -n "${KEEP_WORK:-}" ]] || rm -rf "$work"' EXIT
value() { sed -n "s/^$1 //p" "$2"; }

for size in $sizes; do
  IFS=: read -r columns rows steps <<<"$size"
  block=("$build/benchmarks/vrut-bench-block" --columns "$columns" --rows "$rows" --steps "$steps")
  "${block[@]}" --write-lammps "$work/block.data" >"$work/setup.txt"
  OMP_NUM_THREADS=$cores OMP_PROC_BIND=false "${block[@]}" --threads "$cores" >"$work/vrut.txt"
  n=$(value particles "$work/setup.txt")
  cat >"$work/in.block" <<LMP
units si
dimension 2
boundary f f p
atom_style sphere
comm_modify vel yes
read_data $work/block.data
set type 1 mass $(value mass "$work/setup.txt")
neighbor $(awk "BEGIN { print 0.2 * 0.5e-3 }") bin
neigh_modify delay 0 every 1 check yes
pair_style gran/hooke/history $(value kn "$work/setup.txt") $(value ks "$work/setup.txt") 0.0 0.0 $(value friction "$work/setup.txt") 0
pair_coeff * *
fix integrate all nve/sphere
fix gravity all gravity 9.81 vector 0 -1 0
fix floor all wall/gran hooke/history $(value kn "$work/setup.txt") $(value ks "$work/setup.txt") 0.0 0.0 $(value friction "$work/setup.txt") 0 yplane 0.0 NULL
fix sides all wall/gran hooke/history $(value kn "$work/setup.txt") $(value ks "$work/setup.txt") 0.0 0.0 $(value friction "$work/setup.txt") 0 xplane 0.0 $(value width "$work/setup.txt")
fix flat all enforce2d
timestep $(value dt "$work/setup.txt")
thermo 0
run 1
run $steps
LMP
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 \
    mpirun --oversubscribe -np "$cores" lmp -in "$work/in.block" -log "$work/log.lammps" -screen none
  seconds=$(sed -n 's/^Loop time of \([0-9.e+-]*\) on .* for '"$steps"' steps.*/\1/p' "$work/log.lammps" | tail -n 1)
  [[ -n "$seconds" ]] || { echo "LAMMPS gave no loop time; its log:" >&2; tail -n 30 "$work/log.lammps" >&2; exit 1; }
  lammps=$(awk "BEGIN { printf \"%.4g\", $n * $steps / $seconds }")
  vrut=$(value particle_steps_per_second "$work/vrut.txt")
  echo "disks $n, $steps steps, $cores cores: vrut $vrut particle-steps/s (OpenMP), LAMMPS $lammps atom-steps/s ($cores MPI ranks)"
  echo "ratio vrut/LAMMPS = $(awk "BEGIN { printf \"%.2f\", $vrut / $lammps }")"
done

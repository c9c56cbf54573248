#!/usr/bin/env bash
# vrut beside LAMMPS on the same job and the same cores: a block settling
# under gravity in a box, linear (Hooke) normal and tangential springs with
# Coulomb friction and no damping (LAMMPS: pair gran/hooke/history, fix
# wall/gran hooke/history), the same stiffness, friction, mass, time step,
# positions and walls. In 2D (the default) a hex-packed block of disks in a
# box of three walls; with --dim 3 a simple cubic block of touching spheres
# in a box of a floor and four sides. Runs each size in vrut (OpenMP, all
# cores) and then in LAMMPS (MPI, one rank a core), one after the other, and
# prints both throughputs and their ratio.
#   Usage: lammps_side_by_side.sh [--dim 2|3]
#   BUILD_DIR   vrut's build folder (default: build; built if needed)
#   SIZES       2D: "columns:rows:steps ..." (default: about 16k and 64k disks)
#               3D: "columns:rows:layers:steps ..." (default: about 51k spheres)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
cores=$(nproc)
dim=2
if [[ $# -gt 0 ]]; then
  [[ $# -eq 2 && $1 == --dim && ( $2 == 2 || $2 == 3 ) ]] || { echo "usage: $0 [--dim 2|3]" >&2; exit 2; }
  dim=$2
fi
if [[ $dim -eq 2 ]]; then sizes=${SIZES:-"180:90:2000 360:180:500"}; else sizes=${SIZES:-"40:40:32:500"}; fi

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
  if [[ $dim -eq 2 ]]; then
    IFS=: read -r columns rows steps <<<"$size"
    block=("$build/benchmarks/vrut-bench-block" --columns "$columns" --rows "$rows" --steps "$steps")
  else
    IFS=: read -r columns rows layers steps <<<"$size"
    block=("$build/benchmarks/vrut-bench-block" --dim 3 --columns "$columns" --rows "$rows" --layers "$layers"
           --steps "$steps")
  fi
  "${block[@]}" --write-lammps "$work/block.data" >"$work/setup.txt"
  OMP_NUM_THREADS=$cores OMP_PROC_BIND=false "${block[@]}" --threads "$cores" >"$work/vrut.txt"
  n=$(value particles "$work/setup.txt")
  # The walls' law: kn, kt, no damping, friction, and no damping of the tangential spring.
  walls="$(value kn "$work/setup.txt") $(value ks "$work/setup.txt") 0.0 0.0 $(value friction "$work/setup.txt") 0"
  if [[ $dim -eq 2 ]]; then
    geometry="dimension 2
boundary f f p"
    box="fix gravity all gravity 9.81 vector 0 -1 0
fix floor all wall/gran hooke/history $walls yplane 0.0 NULL
fix sides all wall/gran hooke/history $walls xplane 0.0 $(value width "$work/setup.txt")
fix flat all enforce2d"
  else
    geometry="dimension 3
boundary f f f"
    box="fix gravity all gravity 9.81 vector 0 0 -1
fix floor all wall/gran hooke/history $walls zplane 0.0 NULL
fix sides_x all wall/gran hooke/history $walls xplane 0.0 $(value width "$work/setup.txt")
fix sides_y all wall/gran hooke/history $walls yplane 0.0 $(value depth "$work/setup.txt")"
  fi
  cat >"$work/in.block" <<LMP
units si
$geometry
atom_style sphere
comm_modify vel yes
read_data $work/block.data
set type 1 mass $(value mass "$work/setup.txt")
neighbor $(awk "BEGIN { print 0.2 * 0.5e-3 }") bin
neigh_modify delay 0 every 1 check yes
pair_style gran/hooke/history $(value kn "$work/setup.txt") $(value ks "$work/setup.txt") 0.0 0.0 $(value friction "$work/setup.txt") 0
pair_coeff * *
fix integrate all nve/sphere
$box
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
  [[ $dim -eq 2 ]] && what=disks || what=spheres
  echo "$what $n, $steps steps, $cores cores: vrut $vrut particle-steps/s (OpenMP), LAMMPS $lammps atom-steps/s ($cores MPI ranks)"
  echo "ratio vrut/LAMMPS = $(awk "BEGIN { printf \"%.2f\", $vrut / $lammps }")"
done

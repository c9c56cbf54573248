#!/usr/bin/env bash
# The 3D model's convergence in sphere size: the same specimens (mix, seed,
# box) at several sphere radii, each run to the end of the test, one at a
# time, and carried across sessions: a finished run (summary.json) is kept,
# an interrupted one (checkpoint.vrut) is resumed, any other started again.
#
# The depth, 42.4264 mm, is whole FCC cells (2 sqrt(2) r) at 1.5, 1 and
# 0.75 mm (10, 15 and 20 cells; 30 at 0.5 mm), so a seed places the same
# stones in the same box at every radius: a row differs from the next only
# in its spheres.
#
#   benchmarks/sphere_size_study.sh OUTDIR "MIXES" "SEEDS" "RADII" [vrut-rutting options...]
#   e.g. taskset -c 0 benchmarks/sphere_size_study.sh out/size "1 2 3" "1 2 3" "1.5 1 0.75" --width-mm 100 --threads 1
# Then benchmarks/sphere_size_table.py OUTDIR prints the table.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${VRUT_RUTTING:-$here/build/examples/vrut-rutting}
[[ $# -ge 4 ]] || { echo "usage: $0 OUTDIR \"MIXES\" \"SEEDS\" \"RADII\" [vrut-rutting options...]" >&2; exit 2; }
out=$1 mixes=$2 seeds=$3 radii=$4
shift 4
mkdir -p "$out"
for seed in $seeds; do
  for mix in $mixes; do
    for r in $radii; do
      dir="$out/m$mix-s$seed-r$r"
      log="$dir.log"
      # An interrupted run leaves partial results (summary.json) beside its
      # checkpoint: the checkpoint says it is not done.
      if [[ -e "$dir/summary.json" && ! -e "$dir/checkpoint.vrut" ]]; then continue; fi
      start=$(date +%s)
      if [[ -e "$dir/checkpoint.vrut" ]]; then
        echo "resuming $dir" >>"$log"
        "$exe" --resume "$dir" >>"$log" 2>&1
      else
        "$exe" --dim 3 --gradation "$mix" --seed "$seed" --sphere-radius-mm "$r" --depth-mm 42.4264 \
          --checkpoint-every 300 --out "$dir" --force "$@" >"$log" 2>&1
      fi
      echo "$dir: $(( $(date +%s) - start )) s" >>"$out/wall.txt"
    done
  done
done

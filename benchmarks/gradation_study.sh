#!/usr/bin/env bash
# One row of the gradation-sensitivity study (docs/validation.md): mixes 1#,
# 2# and 3#, each as one ensemble of the given seeds, with the candidate's
# options; prints a markdown row: per mix the rut depth's mean and 95 %
# interval (Student t) and the DS median, then 1# over 3# (the spread).
#   benchmarks/gradation_study.sh OUTDIR SEEDS LABEL [vrut-rutting options...]
#   e.g. benchmarks/gradation_study.sh out/film 1-10 "mean film between stones" --width-mm 100 --stone-film mean
# A mix whose OUTDIR/mixM/seeds.csv exists is not run again.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${VRUT_RUTTING:-$here/build/examples/vrut-rutting}
pool=${VRUT_POOL:-$(dirname "$exe")/vrut-pool}
[ $# -ge 3 ] || { echo "usage: $0 OUTDIR SEEDS LABEL [vrut-rutting options...]" >&2; exit 2; }
out=$1 seeds=$2 label=$3
shift 3
mkdir -p "$out"
cells="" mean1="" mean3=""
for mix in 1 2 3; do
  dir="$out/mix$mix"
  if [ ! -f "$dir/seeds.csv" ]; then
    "$exe" --gradation "$mix" --seeds "$seeds" --out "$dir" --force "$@" >"$out/mix$mix.log" 2>&1 ||
      { echo "mix $mix failed, see $out/mix$mix.log" >&2; exit 1; }
  fi
  row=$("$pool" --cells "$dir/seeds.csv")
  cells+="${row% | *} | "
  [ "$mix" = 1 ] && mean1=${row##* | }
  [ "$mix" = 3 ] && mean3=${row##* | }
done
ratio=$(awk -v a="$mean1" -v b="$mean3" 'BEGIN { printf "%.2f", a / b }')
echo "| $label | ${cells}$ratio |"

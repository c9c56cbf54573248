#!/usr/bin/env bash
# Runs vrut-rutting over mixes and seeds and prints a markdown table of rut
# depth and dynamic stability (mean and standard deviation over the seeds).
#   benchmarks/rutting_study.sh OUTDIR "MIXES" "SEEDS" [extra vrut-rutting options...]
#   e.g. benchmarks/rutting_study.sh out/study "1 2 3" "1 2 3 4 5" --shift 1e4
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${VRUT_RUTTING:-$here/build/examples/vrut-rutting}
out=$1 mixes=$2 seeds=$3
shift 3
mkdir -p "$out"
value() { grep -o "\"$2\": *[-0-9.eE+]*" "$1" | head -n1 | sed 's/.*: *//'; }
echo "| mix | runs | rut depth mm (mean +- sd) | DS passes/mm (mean +- sd) | per run (rut / DS) |"
echo "| --- | --- | --- | --- | --- |"
for mix in $mixes; do
  ruts=() dss=() cells="" infinite=0
  for seed in $seeds; do
    dir="$out/mix$mix-seed$seed"
    "$exe" --gradation "$mix" --seed "$seed" --out "$dir" --force "$@" >"$out/mix$mix-seed$seed.log" 2>&1
    r=$(value "$dir/summary.json" rut_depth_mm)
    d=$(value "$dir/summary.json" dynamic_stability_passes_per_mm)
    # No descent between minutes 45 and 60 gives an infinite DS (null in the JSON).
    if [ -z "$d" ]; then infinite=$((infinite + 1)); cells+=$(printf '%.2f / inf; ' "$r"); else dss+=("$d"); cells+=$(printf '%.2f / %.0f; ' "$r" "$d"); fi
    ruts+=("$r")
  done
  stats() { printf '%s\n' "$@" | awk '{s+=$1; q+=$1*$1; n++} END {m=s/n; v=(n>1)?(q-n*m*m)/(n-1):0; if (v<0) v=0; printf "%.2f +- %.2f", m, sqrt(v)}'; }
  ds_cell="n/a"; [ ${#dss[@]} -gt 0 ] && ds_cell=$(stats "${dss[@]}")
  [ $infinite -gt 0 ] && ds_cell+=" ($infinite infinite, left out)"
  echo "| $mix | ${#ruts[@]} | $(stats "${ruts[@]}") | $ds_cell | $cells |"
done

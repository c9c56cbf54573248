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
[ $# -ge 3 ] || { echo "usage: $0 OUTDIR SEEDS LABEL [vrut-rutting options...]" >&2; exit 2; }
out=$1 seeds=$2 label=$3
shift 3
mkdir -p "$out"
# seeds.csv columns: seed,...,rut_depth_mm (5),...,dynamic_stability_passes_per_mm (8)
summary() {
  awk -F, 'NR > 1 { r[++n] = $5; d[n] = $8 }
    END {
      split("12.706 4.303 3.182 2.776 2.571 2.447 2.365 2.306 2.262 2.228 2.201 2.179 2.160 2.145 2.131 2.120 2.110 2.101 2.093 2.086 2.080 2.074 2.069 2.064 2.060 2.056 2.052 2.048 2.045", t, " ")
      for (i = 1; i <= n; ++i) { s += r[i]; q += r[i] * r[i] }
      m = s / n; sd = sqrt((q - n * m * m) / (n - 1)); h = t[n - 1] * sd / sqrt(n)
      # median of the DS: sort a copy
      for (i = 1; i <= n; ++i) e[i] = d[i]
      for (i = 2; i <= n; ++i) { v = e[i]; for (j = i - 1; j >= 1 && e[j] > v; --j) e[j + 1] = e[j]; e[j + 1] = v }
      med = (n % 2) ? e[(n + 1) / 2] : 0.5 * (e[n / 2] + e[n / 2 + 1])
      printf "%.2f (%.2f to %.2f) | %.0f | %.4f\n", m, m - h, m + h, med, m
    }' "$1"
}
cells="" mean1="" mean3=""
for mix in 1 2 3; do
  dir="$out/mix$mix"
  if [ ! -f "$dir/seeds.csv" ]; then
    "$exe" --gradation "$mix" --seeds "$seeds" --out "$dir" --force "$@" >"$out/mix$mix.log" 2>&1 ||
      { echo "mix $mix failed, see $out/mix$mix.log" >&2; exit 1; }
  fi
  row=$(summary "$dir/seeds.csv")
  cells+="${row% | *} | "
  [ "$mix" = 1 ] && mean1=${row##* | }
  [ "$mix" = 3 ] && mean3=${row##* | }
done
ratio=$(awk -v a="$mean1" -v b="$mean3" 'BEGIN { printf "%.2f", a / b }')
echo "| $label | ${cells}$ratio |"

#!/usr/bin/env bash
# The table of stone_study.sh: per mix and row, the mean rut depth and its
# change paired with the row `exact` on the same seeds (mean, 95 % Student t
# interval), the same for the deformation at 45 min, the DS median, the
# touching stone pairs per stone at the end, the steps and the wall time.
#   Usage: stone_study_table.sh OUT_DIR "MIXES" "ROWS"
set -euo pipefail
out=$1 mixes=$2 rows=$3
echo "| mix | row | rut mm | rut change (95 % CI) | 45 min change (95 % CI) | DS median | DS median change | stone neighbours per stone | steps | wall s |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for mix in $mixes; do
  base=$out/$mix-exact/seeds.csv
  for row in $rows; do
    dir=$out/$mix-$row
    [[ -f $dir/seeds.csv ]] || continue
    wall=$(grep -o '"wall_seconds": [0-9.e+]*' "$dir/summary.json" | awk '{ printf "%.0f", $2 }')
    awk -F, -v mix="$mix" -v row="$row" -v wall="$wall" '
      function tq(dof) {  # two-sided 95 % Student t quantile
        split("12.706 4.303 3.182 2.776 2.571 2.447 2.365 2.306 2.262 2.228 2.201 2.179 2.160 2.145 2.131", t, " ")
        return dof <= 15 ? t[dof] : 1.96 + 2.5 / dof
      }
      function median(a, n,   i, j, v) {
        for (i = 2; i <= n; ++i) { v = a[i]; for (j = i - 1; j >= 1 && a[j] > v; --j) a[j + 1] = a[j]; a[j + 1] = v }
        return n % 2 ? a[(n + 1) / 2] : 0.5 * (a[n / 2] + a[n / 2 + 1])
      }
      function ci(sum, sq, n,   m, sd) {
        m = sum / n; sd = n > 1 ? sqrt((sq - n * m * m) / (n - 1)) : 0
        return sprintf("%+.2f (%+.2f to %+.2f)", m, m - tq(n - 1) * sd / sqrt(n), m + tq(n - 1) * sd / sqrt(n))
      }
      FNR == 1 { next }
      FILENAME == ARGV[1] { rut0[$1] = $5; d450[$1] = $6; ds0[++n0] = $8; next }
      { n++; rut += $5; dr = $5 - rut0[$1]; sr += dr; qr += dr * dr
        d45 = $6 - d450[$1]; s45 += d45; q45 += d45 * d45; ds[n] = $8; nb += 2 * $12 / $11; steps = $13 }
      END {
        m0 = median(ds0, n0); m = median(ds, n)
        printf "| %s# | %s | %.2f | %s | %s | %.0f | %+.0f | %.2f | %d | %s |\n", mix, row, rut / n, ci(sr, qr, n),
               ci(s45, q45, n), m, m - m0, nb / n, steps, wall
      }' "$base" - <"$dir/seeds.csv"  # the row from standard input: it may be the base itself
  done
done

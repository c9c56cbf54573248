#!/usr/bin/env bash
# The rut depth's and the DS's statistics over the specimens of one or more
# runs of vrut-rutting, from their seeds.csv files: the specimens of one mix
# may be run as several ensembles (seeds 1-3 one night, 4-5 the next), and
# this gives what one ensemble of them all would report for the rut: the
# mean, its 95 % interval (Student t) and sd; for the DS, the mean with its
# interval and the median. (An ensemble's "DS of the mean curve" needs the
# curves, not seeds.csv, and is not given.)
#   benchmarks/seeds_summary.sh RUN/seeds.csv [MORE/seeds.csv ...]
#   benchmarks/seeds_summary.sh --cells RUN/seeds.csv ...   # "mean (low to high) | DS median | mean", for gradation_study.sh
# Refused: a seed in two files, files whose columns differ, a run stopped
# before its end (its standard DS is nan), fewer than 2 or more than 30 specimens.
set -euo pipefail
cells=0
[ "${1:-}" = --cells ] && { cells=1; shift; }
[ $# -ge 1 ] || { echo "usage: $0 [--cells] SEEDS_CSV [SEEDS_CSV ...]" >&2; exit 2; }
for f in "$@"; do [ -r "$f" ] || { echo "$0: cannot read $f" >&2; exit 1; }; done
# seeds.csv columns: seed (1), ..., rut_depth_mm (5), ...,
# dynamic_stability_passes_per_mm (8), ..., ds_standard_passes_per_mm (14)
awk -F, -v cells="$cells" '
  FNR == 1 {
    if (header == "") header = $0
    else if ($0 != header) { print FILENAME ": its columns differ from those of " first > "/dev/stderr"; bad = 1; exit 1 }
    if (first == "") first = FILENAME
    if ($5 != "rut_depth_mm" || $8 != "dynamic_stability_passes_per_mm" || $14 != "ds_standard_passes_per_mm") {
      print FILENAME ": not a vrut-rutting seeds.csv" > "/dev/stderr"; bad = 1; exit 1
    }
    next
  }
  {
    if ($1 in from) { print "seed " $1 " is in " from[$1] " and in " FILENAME > "/dev/stderr"; bad = 1; exit 1 }
    if ($14 == "nan") { print FILENAME ": seed " $1 " was stopped before its end (no DS): resume it first" > "/dev/stderr"; bad = 1; exit 1 }
    from[$1] = FILENAME; r[++n] = $5; d[n] = $8; seeds = seeds " " $1
  }
  END {
    if (bad) exit 1
    if (n < 2 || n > 30) { print "need 2 to 30 specimens, got " n > "/dev/stderr"; exit 1 }
    # Student t, two-sided 95 %, for n - 1 = 1 ... 29 degrees of freedom
    split("12.706 4.303 3.182 2.776 2.571 2.447 2.365 2.306 2.262 2.228 2.201 2.179 2.160 2.145 2.131 2.120 2.110 2.101 2.093 2.086 2.080 2.074 2.069 2.064 2.060 2.056 2.052 2.048 2.045", t, " ")
    for (i = 1; i <= n; ++i) { rs += r[i]; ds += d[i] }
    rm = rs / n; dm = ds / n
    for (i = 1; i <= n; ++i) { rq += (r[i] - rm) ^ 2; dq += (d[i] - dm) ^ 2 }
    rsd = sqrt(rq / (n - 1)); dsd = sqrt(dq / (n - 1))
    rh = t[n - 1] * rsd / sqrt(n); dh = t[n - 1] * dsd / sqrt(n)
    for (i = 2; i <= n; ++i) { v = d[i]; for (j = i - 1; j >= 1 && d[j] > v; --j) d[j + 1] = d[j]; d[j + 1] = v }
    med = (n % 2) ? d[(n + 1) / 2] : 0.5 * (d[n / 2] + d[n / 2 + 1])
    if (cells) { printf "%.2f (%.2f to %.2f) | %.0f | %.4f\n", rm, rm - rh, rm + rh, med, rm; exit }
    printf "specimens: %d (seeds%s)\n", n, seeds
    printf "rut depth, mm: %.2f (95 %% interval %.2f to %.2f), sd %.2f\n", rm, rm - rh, rm + rh, rsd
    printf "DS, passes/mm: mean %.0f (95 %% interval %.0f to %.0f), median %.0f\n", dm, dm - dh, dm + dh, med
  }' "$@"

#!/usr/bin/env bash
# The plot of docs/validation.md's round three: rut depth against the coarse
# fraction (mass retained on 2.36 mm: 1# 52 %, 2# 66 %, 3# 80 %, docs/method.md
# section 2), one line per candidate with its 95 % intervals, and the
# laboratory's 2# (12.2 mm). It reads the candidates from the table that
# follows the line "<!-- gradation plot table -->" in the markdown file,
# rows "| name | 1# rut | 1# DS | 2# rut | 2# DS | 3# rut | 3# DS | 1#/3# |"
# with each rut "mean (low to high)", so the plot and the table cannot differ.
#   benchmarks/plot_gradation_study.sh docs/validation.md docs/images/rut_vs_coarse_fraction.png
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 MARKDOWN PNG" >&2; exit 2; }
md=$1 png=$2
command -v gnuplot >/dev/null || { echo "$0: gnuplot is not installed (scripts/setup.sh installs it)" >&2; exit 1; }
data=$(mktemp) && trap 'rm -f "$data"' EXIT
# One gnuplot data block per candidate: coarse fraction, mean, low, high.
awk -F'|' '
  /<!-- gradation plot table -->/ { on = 1; next }
  on && !/^\|/ && seen { exit }
  on && /^\|/ {
    seen = 1
    name = $2; gsub(/^ +| +$/, "", name)
    if (name == "candidate" || name ~ /^-+$/) next
    split("52 66 80", coarse, " ")
    printf "\"%s\"\n", name
    for (m = 1; m <= 3; ++m) {
      cell = $(2 * m + 1)
      if (!match(cell, /[0-9.]+ \([0-9.]+ to [0-9.]+\)/)) { print "bad cell in row " name ": " cell > "/dev/stderr"; bad = 1; exit 1 }
      s = substr(cell, RSTART, RLENGTH); gsub(/[()]/, "", s); split(s, v, " ")
      printf "%s %s %s %s\n", coarse[m], v[1], v[2], v[4]
    }
    printf "\n\n"; ++rows
  }
  END { if (bad) exit 1; if (!rows) { print "no table after <!-- gradation plot table -->" > "/dev/stderr"; exit 1 } }
' "$md" >"$data"
blocks=$(grep -c '^"' "$data")
gnuplot <<GP
set terminal pngcairo size 900,600 font ",11"
set output "$png"
set title "Rut depth at 60 min against the coarse fraction (2D, 10 specimens a mix, 95 % intervals)"
set xlabel "coarse aggregate, % of the mix's mass retained on 2.36 mm"
set ylabel "rut depth at 60 min, mm"
set xrange [48:84]
set xtics ("1# 52" 52, "2# 66" 66, "3# 80" 80)
set yrange [0:*]
set key left bottom box opaque
set grid ytics
plot for [i=0:$((blocks - 1))] "$data" index i using (\$1 + 0.6 * (i - ($blocks - 1) / 2.0)):2:3:4 \
       with yerrorlines lw 2 pt 7 title columnheader(1), \
     "-" using 1:2 with points pt 5 ps 2 lc rgb "black" title "laboratory 2# (12.2 mm)"
66 12.2
e
GP
echo "$png: $blocks candidates"

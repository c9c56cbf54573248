#!/usr/bin/env bash
# vrut-pool against statistics worked by hand, one run or several, and its
# refusals; and, given vrut-rutting, on a small ensemble's seeds.csv against
# the statistics that the ensemble printed itself (the writer's columns and
# the reader's agree).  Usage: pool.sh VRUT_POOL [VRUT_RUTTING]
set -u
exe=$1
rutting=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
header="seed,spheres,placed_stones,stone_volume_fraction,rut_depth_mm,deformation_45min_mm,deformation_60min_mm,dynamic_stability_passes_per_mm,dynamic_stability_is_lower_bound,deformation_resolution_mm,stones,stone_pairs_touching,steps,ds_standard_passes_per_mm,ds_standard_censored"
# row SEED RUT WINDOW DS [BOUND [STANDARD_DS]]: the deformation at minute 45
# is RUT - WINDOW; the standard's DS is DS unless given, censored with BOUND.
row() {
  local at45; at45=$(awk -v r="$2" -v w="$3" 'BEGIN { print r - w }')
  echo "$1,100,10,0.5,$2,$at45,$2,$4,${5:-0},0.001,10,5,1000,${6:-$4},${5:-0}"
}
# DS = 630 passes / window (mm) for the windows 6.3, 3.15 and 1.05 mm.
{ echo "$header"; row 1 11 6.3 100; row 2 12 3.15 200; row 3 13 1.05 600; } >"$work/all.csv"
{ echo "$header"; row 1 11 6.3 100; row 3 13 1.05 600; } >"$work/a.csv"
{ echo "$header"; row 2 12 3.15 200; } >"$work/b.csv"
{ echo "$header"; row 1 11 6.3 100; row 2 12 3.15 200 1; row 3 13 1.05 600; } >"$work/bound.csv"
{ echo "$header"; row 3 13 1.05 600; } >"$work/again.csv"
{ echo "$header"; row 4 14 1 600 0 nan; } >"$work/stopped.csv"
{ echo "${header/spheres/disks}"; row 4 14 1 600; } >"$work/other.csv"
{ echo "$header"; row 1 11 6.3 100; } >"$work/one.csv"
{ echo "seed,rut"; echo "1,2"; } >"$work/foreign.csv"

# Ruts 11, 12, 13 mm: mean 12, sd 1, half width t(0.975, 2) / sqrt(3) =
# 4.303 / 1.732 = 2.484. DS 100, 200, 600: mean 300 (its Student-t interval,
# -357 to 957, would reach below zero); the interval is the geometric mean's:
# ln DS 4.6052, 5.2983, 6.3969, mean 5.4335, so (100 x 200 x 600)^(1/3) =
# 228.9; sd sqrt((0.8283^2 + 0.1352^2 + 0.9635^2) / 2) = 0.9035, half width
# 4.303 x 0.9035 / 1.732 = 2.2444: exp(3.1891) = 24.3 to exp(7.6779) =
# 2160.0; median 200. The mean
# curve: the windows' mean 3.5 mm, so 630 / 3.5 = 180 passes/mm; their sd
# sqrt((2.8^2 + 0.35^2 + 2.45^2) / 2) = 2.642, half width 4.303 x 2.642 /
# 1.732 = 6.564: from 630 / (3.5 + 6.564) = 63 to above the cap (the
# interval reaches zero deformation). A median interval needs 6 specimens.
want="specimens: 3 (seeds 1 2 3)
rut depth, mm: 12.00 (95 % interval 9.52 to 14.48), sd 1.00
DS, passes/mm: mean 300, geometric mean 229 (95 % interval 24 to 2160), median 200
DS as the standard reports it (capped at 6000), passes/mm: median 200 (no interval below 6 specimens), of the mean curve 180 (95 % interval 63 to > 6000)"
# With seed 2's DS only a lower bound (200, censored): the mean and the
# median are lower bounds; the standard's Kaplan-Meier median: the survival
# falls to 2/3 at 100, the bound at 200 leaves the risk set, and it falls to
# 0 at 600, so the median is 600.
want_bound="specimens: 3 (seeds 1 2 3)
rut depth, mm: 12.00 (95 % interval 9.52 to 14.48), sd 1.00
DS, passes/mm: mean above 300 (interval not known: 1 of 3 are lower bounds), median above 200
DS as the standard reports it (capped at 6000), passes/mm: median 600 (no interval below 6 specimens), of the mean curve 180 (95 % interval 63 to > 6000)"
check() {  # check NAME WANT ARGS...
  local name=$1 expected=$2; shift 2
  local out code; out=$("$exe" "$@" 2>&1); code=$?
  if [ "$code" -eq 0 ] && [ "$out" = "$expected" ]; then echo "ok:   $name"
  else echo "FAIL: $name, exit $code, got:"; echo "$out"; failures=$((failures + 1)); fi
}
check "one run" "$want" "$work/all.csv"
check "two runs, seeds in any order, the same statistics" "${want/seeds 1 2 3/seeds 1 3 2}" "$work/a.csv" "$work/b.csv"
check "a DS that is only a lower bound" "$want_bound" "$work/bound.csv"
check "cells for gradation_study.sh" "12.00 (9.52 to 14.48) | 200 | 12.0000" --cells "$work/all.csv"
refused() {  # refused NAME PATTERN ARGS...
  local name=$1 pattern=$2; shift 2
  local out code; out=$("$exe" "$@" 2>&1); code=$?
  if [ "$code" -ne 0 ] && grep -q -- "$pattern" <<<"$out"; then echo "ok:   refused: $name"
  else echo "FAIL: $name -> exit $code, output:"; echo "$out"; failures=$((failures + 1)); fi
}
refused "a seed in two runs" "seed 3 is in .*all.csv and in .*again.csv" "$work/all.csv" "$work/again.csv"
refused "a run stopped before its end" "seed 4 was stopped before its end" "$work/a.csv" "$work/stopped.csv"
refused "runs with other columns" "columns differ" "$work/a.csv" "$work/other.csv"
refused "one specimen" "need at least 2 specimens, got 1" "$work/one.csv"
refused "no such file" "cannot read" "$work/none.csv"
refused "not a seeds.csv" "has no column rut_depth_mm" "$work/foreign.csv"
if [ -n "$rutting" ]; then
  printed=$("$rutting" --width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e5 --settle-steps 300 --seeds 1-2 \
    --out "$work/ensemble" 2>&1 | grep "2 specimens: rut depth")
  pooled=$("$exe" "$work/ensemble/seeds.csv" 2>&1)
  # The ensemble's "rut depth M mm at 60 min (sd S, 95 % CI L to H)", its DS
  # median, and the standard's mean curve with its interval, in vrut-pool's words.
  want_pooled=$(sed -E 's/.*rut depth ([0-9.]+) mm at [0-9]+ min \(sd ([0-9.]+), 95 % CI ([-0-9.]+) to ([-0-9.]+)\).*, median ([0-9]+), of the mean curve.*of the mean curve ([0-9]+) \(95 % interval ([0-9]+) to ([>0-9 ]+)\) passes.*/\1 (95 % interval \3 to \4), sd \2|median \5|of the mean curve \6 (95 % interval \7 to \8)/' <<<"$printed")
  IFS='|' read -r rut median curve <<<"$want_pooled"
  # Where no DS is a lower bound, the DS's geometric mean and its interval too.
  geometric=$(grep -oE "geometric mean [0-9]+ \(95 % CI [0-9]+ to [0-9]+\)" <<<"$printed" | sed 's/CI/interval/')
  if grep -qF "mean above" <<<"$printed" || [ -n "$geometric" ]; then geometric_ok=1; else geometric_ok=0; fi
  if [ -n "$printed" ] && grep -qF "rut depth, mm: $rut" <<<"$pooled" && grep -qF "), $median" <<<"$pooled" &&
     grep -qF "$curve" <<<"$pooled" && [ "$geometric_ok" -eq 1 ] && grep -qF "$geometric" <<<"$pooled"; then
    echo "ok:   an ensemble's seeds.csv pools to the statistics it printed"
  else
    echo "FAIL: pooled a vrut-rutting ensemble; it printed:"; echo "$printed"; echo "pooled:"; echo "$pooled"
    failures=$((failures + 1))
  fi
fi
echo "$failures failure(s)"
[ "$failures" -eq 0 ]

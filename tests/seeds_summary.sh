#!/usr/bin/env bash
# benchmarks/seeds_summary.sh against statistics worked by hand, one run or
# several, and its refusals.  Usage: seeds_summary.sh SCRIPT
set -u
script=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
header="seed,spheres,placed_stones,stone_volume_fraction,rut_depth_mm,deformation_45min_mm,deformation_60min_mm,dynamic_stability_passes_per_mm,dynamic_stability_is_lower_bound,deformation_resolution_mm,stones,stone_pairs_touching,steps,ds_standard_passes_per_mm,ds_standard_censored"
row() {  # row SEED RUT DS [STANDARD_DS]
  echo "$1,100,10,0.5,$2,$2,$2,$3,0,0.001,10,5,1000,${4:-$3},0"
}
{ echo "$header"; row 1 1 100; row 2 2 200; row 3 3 600; } >"$work/all.csv"
{ echo "$header"; row 1 1 100; row 3 3 600; } >"$work/a.csv"
{ echo "$header"; row 2 2 200; } >"$work/b.csv"
{ echo "$header"; row 3 3 600; } >"$work/again.csv"
{ echo "$header"; row 4 4 600 nan; } >"$work/stopped.csv"
{ echo "${header/spheres/disks}"; row 4 4 600; } >"$work/other.csv"
{ echo "$header"; row 1 1 100; } >"$work/one.csv"

# Ruts 1, 2, 3 mm: mean 2, sd 1, half width t(0.975, 2) / sqrt(3) = 4.303 / 1.732
# = 2.484. DS 100, 200, 600: mean 300, sd sqrt(140000 / 2) = 264.6, half
# width 4.303 x 264.6 / 1.732 = 657.3; median 200.
want="specimens: 3 (seeds 1 2 3)
rut depth, mm: 2.00 (95 % interval -0.48 to 4.48), sd 1.00
DS, passes/mm: mean 300 (95 % interval -357 to 957), median 200"
check() {  # check NAME WANT ARGS...
  local name=$1 expected=$2; shift 2
  local out; out=$("$script" "$@" 2>&1)
  if [ "$out" = "$expected" ]; then echo "ok:   $name"; else echo "FAIL: $name, got:"; echo "$out"; failures=$((failures + 1)); fi
}
check "one run" "$want" "$work/all.csv"
check "two runs, seeds in any order, the same statistics" "${want/seeds 1 2 3/seeds 1 3 2}" "$work/a.csv" "$work/b.csv"
check "cells for gradation_study.sh" "2.00 (-0.48 to 4.48) | 200 | 2.0000" --cells "$work/all.csv"
refused() {  # refused NAME PATTERN ARGS...
  local name=$1 pattern=$2; shift 2
  local out code; out=$("$script" "$@" 2>&1); code=$?
  if [ "$code" -ne 0 ] && grep -q -- "$pattern" <<<"$out"; then echo "ok:   refused: $name"
  else echo "FAIL: $name -> exit $code, output:"; echo "$out"; failures=$((failures + 1)); fi
}
refused "a seed in two runs" "seed 3 is in" "$work/all.csv" "$work/again.csv"
refused "a run stopped before its end" "stopped before its end" "$work/a.csv" "$work/stopped.csv"
refused "runs with other columns" "columns differ" "$work/a.csv" "$work/other.csv"
refused "one specimen" "need 2 to 30" "$work/one.csv"
refused "no such file" "cannot read" "$work/none.csv"
echo "$failures failure(s)"
[ "$failures" -eq 0 ]

#!/usr/bin/env bash
# vrut-pool against statistics worked by hand, one run or several, ensembles
# or single runs, and its refusals; and, given vrut-rutting, on a small
# ensemble's seeds.csv against the statistics that the ensemble printed
# itself (the writer's columns and the reader's agree), and with a single
# run's summary.json.  Usage: pool.sh VRUT_POOL [VRUT_RUTTING]
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
# single DIR SEED RUT WINDOW DS [GRADATION [DIMENSION [STOPPED]]]: a single
# run's folder (--seed), its summary.json as vrut-rutting writes it (2D where
# DIMENSION is not 3, with no such key; a run stopped before its end has its
# DS null and no standard's DS) and its config.ini.
single() {
  local dir=$work/$1 at45 dim="" ds=$5 interrupted=false standard='"dynamic_stability_standard": {"passes_per_mm": '$5', "censored": false}, '
  at45=$(awk -v r="$3" -v w="$4" 'BEGIN { print r - w }')
  [ "${7:-2}" = 3 ] && dim='"dimension": 3, '
  [ "${8:-0}" = 1 ] && { standard=""; ds=null; interrupted=true; }
  mkdir -p "$dir"
  echo "{$dim\"seed\": $2, \"rut_depth_mm\": $3, \"deformation_45min_mm\": $at45, \"deformation_60min_mm\": $3, $standard\"dynamic_stability_passes_per_mm\": $ds, \"dynamic_stability_is_lower_bound\": false, \"interrupted\": $interrupted}" >"$dir/summary.json"
  printf '# a comment\ngradation=%s\nseed=%s\nout="%s"\nthreads=%s\n' "${6:-2}" "$2" "$dir" "$2" >"$dir/config.ini"
}
single s1 1 11 6.3 100
single s2 2 12 3.15 200
single s3 3 13 1.05 600
single s2-mix3 2 12 3.15 200 3
single s2-3d 2 12 3.15 200 2 3  # 3D, as the hand-made seeds.csv (spheres)
single s4-stopped 4 14 1 600 2 2 1
single s2-f1 2 12 3.15 200
# Settings of the run only (the backend, checkpoints) may differ, a number
# be typed either way (0.35, .35), and a setting be missing (s3: a run of a
# version before the option); the stones' friction of the model may not.
printf 'backend="openmp"\ncheckpoint-every=0\nstone-friction=0.35\nshift=10000\n' >>"$work/s1/config.ini"
printf 'backend="serial"\ncheckpoint-every=600\nstone-friction=.35\nshift=1e4\n' >>"$work/s2/config.ini"
printf 'backend="serial"\nstone-friction=1\nshift=1e5\n' >>"$work/s2-f1/config.ini"
single img1 1 11 6.3 100
sed -i 's/^{/{"images": ["a.png"], /' "$work/img1/summary.json"
mkdir -p "$work/empty"
mkdir -p "$work/ensemble13" && cp "$work/a.csv" "$work/ensemble13/seeds.csv"
echo '{"seed": 1, "ensemble": {}}' >"$work/ensemble13/summary.json"

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
# Single runs (their folders or summary.json) pool as the rows of one
# seeds.csv; their config.ini differ only in what the run's settings allow.
check "three single runs" "$want" "$work/s1" "$work/s2/summary.json" "$work/s3"
check "an ensemble's folder and a single run's" "${want/seeds 1 2 3/seeds 1 3 2}" "$work/ensemble13" "$work/s2-3d"
refused() {  # refused NAME PATTERN ARGS...
  local name=$1 pattern=$2; shift 2
  local out code; out=$("$exe" "$@" 2>&1); code=$?
  if [ "$code" -ne 0 ] && grep -q -- "$pattern" <<<"$out"; then echo "ok:   refused: $name"
  else echo "FAIL: $name -> exit $code, output:"; echo "$out"; failures=$((failures + 1)); fi
}
# A finished single run whose DS window did not deform: its DS infinite, which
# summary.json writes null, a lower bound; pooled, not refused.
single s2-flat 2 12 0 200
sed -i 's/"dynamic_stability_passes_per_mm": 200, "dynamic_stability_is_lower_bound": false/"dynamic_stability_passes_per_mm": null, "dynamic_stability_is_lower_bound": true/' "$work/s2-flat/summary.json"
flat_out=$("$exe" "$work/s1" "$work/s2-flat" "$work/s3" 2>&1); flat_code=$?
if [ "$flat_code" -eq 0 ] && grep -qF "(interval not known: 1 of 3 are lower bounds)" <<<"$flat_out"; then
  echo "ok:   a single run's infinite DS (null in summary.json) pools as a lower bound"
else
  echo "FAIL: a single run's infinite DS (exit $flat_code):"; echo "$flat_out"; failures=$((failures + 1))
fi
refused "a seed in two runs" "seed 3 is in .*all.csv and in .*again.csv" "$work/all.csv" "$work/again.csv"
refused "a run stopped before its end" "seed 4 was stopped before its end" "$work/a.csv" "$work/stopped.csv"
refused "runs with other columns" "columns differ" "$work/a.csv" "$work/other.csv"
refused "one specimen" "need at least 2 specimens, got 1" "$work/one.csv"
refused "no such file" "none.csv: no such file or folder" "$work/none.csv"
refused "no such folder" "f060-s5: no such file or folder" "$work/s1" "$work/f060-s5"
mkdir -p "$work/.f060-s6.partial"  # a run still going: vrut-rutting stages its folder beside it until the end
refused "a run still going" "f060-s6 does not exist yet: its run is still going, or was killed (.f060-s6.partial holds it" "$work/s1" "$work/f060-s6"
refused "a run still going, named with a slash" "f060-s6/ does not exist yet" "$work/s1" "$work/f060-s6/"
refused "not a seeds.csv" "has no column rut_depth_mm" "$work/foreign.csv"
refused "a single run stopped before its end" "seed 4 was stopped before its end" "$work/s1" "$work/s4-stopped"
refused "another model" "other settings (their config.ini; .*): shift=1e5 against shift=10000, stone-friction=1 against stone-friction=0.35: pool one mix's runs of one model" "$work/s1" "$work/s2-f1"
refused "a run from images with another" "img1/summary.json was run from images" "$work/img1" "$work/s2"
refused "a folder with no results" "empty has no seeds.csv or summary.json: is its run still going" "$work/s1" "$work/empty"
refused "another mix" "other settings (their config.ini; .*): gradation=3 against gradation=2:" "$work/s1" "$work/s2-mix3"
refused "2D with 3D" "s2-3d/summary.json is a 3D run and .*s1/summary.json a 2D one" "$work/s1" "$work/s2-3d"
refused "an ensemble's summary.json" "is an ensemble's summary: give its seeds.csv" "$work/ensemble13/summary.json" "$work/s2"
# The model's options compared as each run resolved them: summary.json
# records the filler (mastic_by_filler, as typed) since c53d8f2 and the
# stones' friction (stone_friction) since 0.2, where 3D's defaults (-1,
# model) are 0.6 and 0.35. Before 0.2 a negative stone friction was the
# run's --friction (1), in 3D too; before c53d8f2 there was one mastic.
# config.ini as CLI11 writes it: text quoted, a number given to a text
# option bare.
resolved() {  # resolved DIR SEED CONFIG_LINES [SUMMARY_KEYS]
  single "$1" "$2" 12 3.15 200 2 3
  printf 'friction=1\n%b' "$3" >>"$work/$1/config.ini"
  [ -n "${4:-}" ] && sed -i "s/^{/{$4, /" "$work/$1/summary.json"
  return 0
}
resolved m3-defaults 5 'stone-friction=-1\nmastic-by-filler="model"\n' '"stone_friction": 0.6, "mastic_by_filler": "0.35"'
resolved m3-typed 6 'stone-friction=0.6\nmastic-by-filler=.35\n' '"stone_friction": 0.6, "mastic_by_filler": ".35"'
resolved m3-typed-0.1 11 'stone-friction=0.6\nmastic-by-filler=0.35\n' '"mastic_by_filler": "0.35"'
resolved m3-before 7 'stone-friction=1\nmastic-by-filler="none"\n' '"stone_friction": 1.0, "mastic_by_filler": "none"'
resolved m3-version-0.1 8 'stone-friction=-0.5\nmastic-by-filler="none"\n' '"mastic_by_filler": "none"'
resolved m3-before-filler 9 'stone-friction=-1\n'
resolved m3-no-filler-0.6 10 'stone-friction=0.6\n'
pools() {  # pools NAME SEEDS ARGS...: pooled, the specimens' line first
  local name=$1 seeds=$2; shift 2
  local out code; out=$("$exe" "$@" 2>&1); code=$?
  if [ "$code" -eq 0 ] && [ "$(head -n 1 <<<"$out")" = "specimens: 2 (seeds $seeds)" ]; then echo "ok:   $name"
  else echo "FAIL: $name, exit $code, got:"; echo "$out"; failures=$((failures + 1)); fi
}
pools "the 3D model at its defaults and typed out (.35)" "5 6" "$work/m3-defaults" "$work/m3-typed"
pools "the 3D model at its defaults and typed out before 0.2" "5 11" "$work/m3-defaults" "$work/m3-typed-0.1"
pools "a run before 0.2 at a negative friction and one typed as it ran" "7 8" "$work/m3-before" "$work/m3-version-0.1"
pools "a run before the filler option and one typed as it ran" "9 7" "$work/m3-before-filler" "$work/m3-before"
refused "the 3D model at its defaults and the model before" \
  'mastic-by-filler=none against mastic-by-filler=0.35, stone-friction=1.0 against stone-friction=0.6' \
  "$work/m3-defaults" "$work/m3-before"
refused "a negative friction of version 0.1 (the mastic's 1) and -1 of 0.2 (the model's 0.6)" \
  'stone-friction=1 against stone-friction=0.6' "$work/m3-defaults" "$work/m3-version-0.1"
refused "a run before the filler option (one mastic) and the 3D model" \
  'mastic-by-filler=none against mastic-by-filler=0.35' "$work/m3-defaults" "$work/m3-no-filler-0.6"
# The time step's safety as each run resolved it: -1 is the dimension's
# since 2026-12-06 (0.3 in 2D, 0.5 in 3D), recorded in summary.json
# (timestep_safety); before, the default was 0.3, written out as such.
resolved dt-3d-defaults 12 'timestep-safety=-1\n' '"timestep_safety": 0.5'
resolved dt-3d-typed 13 'timestep-safety=.5\n' '"timestep_safety": 0.5'
resolved dt-3d-before 14 'timestep-safety=0.3\n'
resolved dt-resolved-0.3 15 'timestep-safety=-1\n' '"timestep_safety": 0.3'
pools "the 3D step's safety at its default and typed out (.5)" "12 13" "$work/dt-3d-defaults" "$work/dt-3d-typed"
pools "a step's safety of -1 that resolved to 0.3 (2D's) and 0.3 from before -1" "15 14" "$work/dt-resolved-0.3" "$work/dt-3d-before"
refused "the 3D step at its default and a run from before (0.3 then)" \
  'timestep-safety=0.3 against timestep-safety=0.5' "$work/dt-3d-defaults" "$work/dt-3d-before"
# The settling's steps as each run resolved them: -1 lasts as long as 4,000
# steps at 0.3 since 2026-12-06 (4,000 in 2D, 2,400 at 3D's 0.5), recorded
# in summary.json (settle_steps); before, the default was 4,000, written out.
resolved settle-3d-defaults 16 'settle-steps=-1\n' '"settle_steps": 2400'
resolved settle-3d-typed 17 'settle-steps=2400\n' '"settle_steps": 2400'
resolved settle-before 18 'settle-steps=4000\n'
resolved settle-resolved-4000 19 'settle-steps=-1\n' '"settle_steps": 4000'
pools "the settling at its default and typed out (2400)" "16 17" "$work/settle-3d-defaults" "$work/settle-3d-typed"
pools "a settling of -1 that resolved to 4000 (2D's) and 4000 from before -1" "19 18" "$work/settle-resolved-4000" "$work/settle-before"
refused "the settling at its 3D default and a run from before (4000 then)" \
  'settle-steps=4000 against settle-steps=2400' "$work/settle-3d-defaults" "$work/settle-before"
if [ -n "$rutting" ]; then
  # Each program's output first, then what is read of it: a pipe would lose
  # the program's exit code.
  ran=$("$rutting" --width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e5 --settle-steps 300 --seeds 1-2 \
    --out "$work/ensemble" 2>&1); ran_code=$?
  [ "$ran_code" -eq 0 ] || { echo "FAIL: the ensemble run exited $ran_code: $(tail -n 3 <<<"$ran")"; failures=$((failures + 1)); }
  printed=$(grep "2 specimens: rut depth" <<<"$ran")
  pooled=$("$exe" "$work/ensemble/seeds.csv" 2>&1); pooled_code=$?
  [ "$pooled_code" -eq 0 ] || { echo "FAIL: pooling the ensemble exited $pooled_code"; failures=$((failures + 1)); }
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
  # A single run (--seed 3) pooled with the ensemble: the mean of the
  # ensemble's two ruts (seeds.csv) and the one the single run printed (to
  # 0.01 mm, so 0.0017 in the mean), against vrut-pool's mean (to 0.01 mm):
  # within 0.007 mm when summary.json carries the run's rut.
  ran=$("$rutting" --width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e5 --settle-steps 300 --seed 3 \
    --out "$work/single3" 2>&1); ran_code=$?
  [ "$ran_code" -eq 0 ] || { echo "FAIL: the single run exited $ran_code: $(tail -n 3 <<<"$ran")"; failures=$((failures + 1)); }
  single_rut=$(sed -nE 's/.*: rut depth ([0-9.]+) mm at 60 min.*/\1/p' <<<"$ran")
  two=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "rut_depth_mm") c = i } NR > 1 { s += $c } END { print s }' \
    "$work/ensemble/seeds.csv")
  pooled3=$("$exe" "$work/ensemble" "$work/single3" 2>&1); pooled_code=$?
  [ "$pooled_code" -eq 0 ] || { echo "FAIL: pooling the ensemble with the single run exited $pooled_code"; failures=$((failures + 1)); }
  mean3=$(sed -nE 's/^rut depth, mm: ([0-9.]+) .*/\1/p' <<<"$pooled3")
  if [ -n "$single_rut" ] && grep -qF "specimens: 3 (seeds 1 2 3)" <<<"$pooled3" &&
     awk -v a="$mean3" -v t="$two" -v r="$single_rut" 'BEGIN { d = a - (t + r) / 3; exit !(d < 0.007 && d > -0.007) }'; then
    echo "ok:   a single run's summary.json pools with an ensemble's seeds.csv"
  else
    echo "FAIL: pooled the ensemble with a single run (rut $single_rut, the ensemble's sum $two):"; echo "$pooled3"
    failures=$((failures + 1))
  fi
fi
echo "$failures failure(s)"
[ "$failures" -eq 0 ]

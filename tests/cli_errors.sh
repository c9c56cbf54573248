#!/usr/bin/env bash
# Bad input to an example gets a clear message and exit code 1 or 2, never a
# crash or a hang; --help exits 0.  Usage: cli_errors.sh demo|creep|specimen|rutting EXECUTABLE
# VRUT_ERRORS_ONLY=1 leaves out the rutting runs that succeed (for slow builds).
set -u
which=$1 exe=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

expect() {  # expect CODES PATTERN -- ARGS...
  local codes=$1 pattern=$2; shift 3
  local out code
  out=$(cd "$work" && timeout 60 "$exe" "$@" 2>&1); code=$?
  if [[ " $codes " != *" $code "* ]] || ! grep -qiE -- "$pattern" <<<"$out"; then
    echo "FAIL: $* -> exit $code (want $codes), output:"; echo "$out" | head -n 5
    failures=$((failures + 1))
  else
    echo "ok:   $* -> exit $code"
  fi
}

expect "0" "usage" -- --help
expect "1 2" "backend" -- --backend vulkan
expect "1 2" "not expected|extra|unknown|following argument" -- --no-such-option 3
mkdir -p "$work/taken" && touch "$work/taken/file"
expect "1 2" "exists" -- --out taken
# A folder that cannot be written is found before any work.
expect "1 2" "cannot write the output folder" -- --out /dev/null/results

case $which in
demo)
  expect "1 2" "columns" -- --columns -5
  expect "1 2" "radius" -- --radius-mm -0.5
  expect "1 2" "stress" -- --stress-mpa abc
  expect "1 2" "steps" -- --steps 0
  expect "1 2" "columns" -- --columns
  expect "0" "plate stress" -- --out taken --steps 10 --columns 4 --rows 4 --force
  [[ -f "$work/taken/summary.json" ]] || { echo "FAIL: no summary.json after --force"; failures=$((failures + 1)); }
  ;;
creep)
  expect "1 2" "eta1" -- --eta1 -5 --out a
  expect "1 2" "eta2" -- --eta2 0 --out b
  expect "1 2" "E1" -- --E1 0 --out c
  expect "1 2" "Poisson" -- --nu 0.5 --out d
  expect "1 2" "Poisson" -- --nu -0.1 --out e
  expect "1 2" "alpha_T" -- --shift 0 --out f
  expect "1 2" "alpha_T" -- --shift -1e4 --out g
  for d in a b c d e f g; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  expect "0" "apparent/macro" -- --out taken --force --stress-mpa 0.01 --time-s 20 --columns 6 --rows 4
  for f in creep.csv creep.json creep.png; do
    [[ -s "$work/taken/$f" ]] || { echo "FAIL: no $f"; failures=$((failures + 1)); }
  done
  ;;
specimen)
  printf 'sieve_mm,percent_passing\n19,100\n9.5,70\n12,40\n' >"$work/bad.csv"
  expect "1 2" "bad.csv:4" -- --gradation bad.csv --out a
  expect "1 2" "cannot open" -- --gradation 7 --out b
  expect "1 2" "disk-radius" -- --disk-radius-mm -0.5 --out c
  expect "1 2" "air-voids" -- --air-voids 0.5 --out d
  expect "1 2" "height" -- --height-mm -50 --out e
  expect "1 2" "cannot reach" -- --gradation 3 --height-mm 5 --out f
  for d in a b c d e f; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  expect "0" "area fraction" -- --gradation 3 --seed 5 --out one
  expect "0" "area fraction" -- --gradation 3 --seed 5 --out two
  for f in specimen.png specimen.json specimen.vtk; do
    if ! cmp -s "$work/one/$f" "$work/two/$f"; then echo "FAIL: $f differs between two runs"; failures=$((failures + 1)); fi
  done
  grep -q '"quantity_gradation"' "$work/one/specimen.json" || { echo "FAIL: no quantity_gradation"; failures=$((failures + 1)); }
  ;;
rutting)
  small=(--width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e5 --settle-steps 300)
  expect "1 2" "cannot open" -- --gradation 7 --out a
  expect "1 2" "pressure" -- --pressure-mpa -0.7 --out b
  expect "1 2" "longer than the specimen" -- --width-mm 20 --out c
  printf 'gradation=2\nno_such_key=3\n' >"$work/extra.ini"
  expect "1 2" "no_such_key" -- --config extra.ini --out d
  printf 'seed=abc\n' >"$work/badvalue.ini"
  expect "1 2" "seed" -- --config badvalue.ini --out e
  expect "1 2" "Poisson" -- --mastic-nu 0.6 --out f
  expect "1 2" "alpha_T" -- --shift 0 --out g
  expect "1" "unstable at step [0-9]+.*time step" -- "${small[@]}" --timestep-safety 1.0 --out h
  for d in a b c d e f g h; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  # The runs that succeed, which the sanitizer build (VRUT_ERRORS_ONLY) leaves out: too slow there.
  if [[ -z ${VRUT_ERRORS_ONLY:-} ]]; then
  expect "0" "rut depth" -- "${small[@]}" --out run1
  for f in summary.json deformation.csv deformation.png specimen.png rut_forming.png displacement.png final.vtk config.ini; do
    [[ -s "$work/run1/$f" ]] || { echo "FAIL: no $f"; failures=$((failures + 1)); }
  done
  for key in gradation seed disk_radius_mm shift_factor particles contacts steps wall_seconds backend threads \
             particle_steps_per_second deformation_45min_mm deformation_60min_mm rut_depth_mm dynamic_stability_passes_per_mm; do
    grep -q "\"$key\"" "$work/run1/summary.json" || { echo "FAIL: summary.json lacks $key"; failures=$((failures + 1)); }
  done
  expect "1 2" "exists" -- "${small[@]}" --out run1
  # The config written is the config used: reading it back gives the same result.
  expect "0" "rut depth" -- --config run1/config.ini --out run2
  cmp -s "$work/run1/deformation.csv" "$work/run2/deformation.csv" ||
    { echo "FAIL: the written config.ini does not reproduce the run"; failures=$((failures + 1)); }
  # Ctrl-C: the run stops at its next sample, writes the results so far, says
  # so and exits 130 (128 + SIGINT). A test of 10 times the usual length, so
  # that the signal comes while it loads.
  (cd "$work" && exec "$exe" --width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e4 --settle-steps 300 \
     --out intr >intr.out 2>intr.err) &
  pid=$!
  for _ in $(seq 150); do grep -q "specimen:" "$work/intr.err" 2>/dev/null && break; sleep 0.2; done
  sleep 2
  kill -INT "$pid"
  wait "$pid"; code=$?
  if [[ $code -ne 130 ]] || ! grep -q "partial results" "$work/intr.out" ||
     ! grep -q '"interrupted": true' "$work/intr/summary.json" 2>/dev/null ||
     [[ $(wc -l <"$work/intr/deformation.csv") -lt 3 ]]; then
    echo "FAIL: Ctrl-C gave exit $code and no partial results:"; cat "$work/intr.out" "$work/intr.err" | tail -n 5
    failures=$((failures + 1))
  else
    echo "ok:   Ctrl-C -> exit 130, partial results ($(($(wc -l <"$work/intr/deformation.csv") - 1)) samples)"
  fi
  fi
  # Ensembles: bad seed lists are refused before anything is written ...
  expect "2" "backwards" -- "${small[@]}" --seeds 5-1 --out s1
  expect "2" "not a seed" -- "${small[@]}" --seeds 1,x --out s2
  expect "2" "twice" -- "${small[@]}" --seeds 1-3,2 --out s3
  for d in s1 s2 s3; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  # ... and an ensemble of seeds 1 and 2 gives seed 1 the curve of its single run (run1).
  [[ -n ${VRUT_ERRORS_ONLY:-} ]] && { echo "$failures failure(s)"; exit $((failures > 0)); }
  expect "0" "2 specimens: rut depth" -- "${small[@]}" --seeds 1-2 --out ens
  for f in summary.json seeds.csv deformation.csv deformation.png specimen.png; do
    [[ -s "$work/ens/$f" ]] || { echo "FAIL: no ensemble $f"; failures=$((failures + 1)); }
  done
  grep -q '"ensemble"' "$work/ens/summary.json" || { echo "FAIL: no ensemble block in summary.json"; failures=$((failures + 1)); }
  alone=$(cut -d, -f3 "$work/run1/deformation.csv" | tail -n +2)
  inside=$(awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == "seed_1_mm") col = c; next } { print $col }' \
           "$work/ens/deformation.csv")
  [[ -n "$alone" && "$alone" == "$inside" ]] ||
    { echo "FAIL: seed 1 in the ensemble differs from its single run"; failures=$((failures + 1)); }
  ;;
esac

echo "$failures failure(s)"
exit $((failures > 0))

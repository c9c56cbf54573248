#!/usr/bin/env bash
# Bad input to an example gets a clear message and exit code 1 or 2, never a
# crash or a hang; --help exits 0.  Usage: cli_errors.sh demo|creep|specimen|rutting EXECUTABLE
# VRUT_ERRORS_ONLY=1 leaves out the rutting runs that succeed (for slow builds).
# Under the sanitizers (sanitize.sh sets VRUT_SANITIZED=1 and exit code 86
# for a report) any report fails the case, whatever the exit code.
set -u
which=$1 exe=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
sanitizer_report="ERROR: (Address|Leak)Sanitizer|runtime error:|SUMMARY: (Address|UndefinedBehavior)Sanitizer"

expect() {  # expect CODES PATTERN -- ARGS...
  local codes=$1 pattern=$2; shift 3
  local out code
  out=$(cd "$work" && timeout 60 "$exe" "$@" 2>&1); code=$?
  if [[ -n ${VRUT_SANITIZED:-} ]] && { [[ $code -eq 86 ]] || grep -qE "$sanitizer_report" <<<"$out"; }; then
    echo "FAIL: $* -> exit $code, a sanitizer report:"; grep -E -A 20 "$sanitizer_report" <<<"$out" | head -n 40
    failures=$((failures + 1))
  elif [[ " $codes " != *" $code "* ]] || ! grep -qiE -- "$pattern" <<<"$out"; then
    echo "FAIL: $* -> exit $code (want $codes), output:"; echo "$out" | head -n 5
    failures=$((failures + 1))
  else
    echo "ok:   $* -> exit $code"
  fi
}

# Gradation files that vrut-specimen and vrut-rutting must refuse: one sieve,
# a header alone, and one with no stone above 2.36 mm.
printf '19,100\n' >"$work/one_sieve.csv"
printf 'sieve_mm,percent_passing\n' >"$work/header_only.csv"
printf 'sieve_mm,percent_passing\n19,100\n4.75,100\n2.36,100\n0.075,6\n' >"$work/no_stones.csv"

expect "0" "usage" -- --help
expect "1 2" "backend" -- --backend vulkan
expect "1 2" "not expected|extra|unknown|following argument" -- --no-such-option 3
mkdir -p "$work/taken" && touch "$work/taken/file"
expect "1 2" "exists" -- --out taken
# A folder that cannot be written is found before any work.
expect "1 2" "cannot write the output folder" -- --out /dev/null/results

# Images that vrut-specimen and vrut-rutting must refuse (exit 2, a message,
# no output folder): a missing file, an empty one, text named .png, a 1 x 1
# image, an all-black one, and a pixel larger than a disk (a wrong scale).
# PGM files, which OpenCV reads, are written here byte by byte.
: >"$work/empty.png"
echo "not an image" >"$work/text.png"
printf 'P5\n1 1\n255\n\200' >"$work/one_pixel.pgm"
{ printf 'P5\n100 100\n255\n'; head -c 10000 /dev/zero; } >"$work/black.pgm"
# 200 x 100 pixels: black mastic above, grey stone below (20 x 10 mm at 0.1 mm).
{ printf 'P5\n200 100\n255\n'; head -c 10000 /dev/zero; head -c 10000 /dev/zero | tr '\0' '\200'; } >"$work/narrow.pgm"
bad_images() {  # bad_images: every refusal of a bad image
  expect "2" "--image.*(not exist|no such)" -- --image no_such.png --mm-per-pixel 0.1 --out img1
  expect "2" "cannot read the image" -- --image empty.png --mm-per-pixel 0.1 --out img2
  expect "2" "cannot read the image" -- --image text.png --mm-per-pixel 0.1 --out img3
  expect "2" "1 x 1 pixels: too small" -- --image one_pixel.pgm --mm-per-pixel 0.1 --out img4
  expect "2" "no stone in the image" -- --image black.pgm --mm-per-pixel 0.1 --out img5
  expect "2" "smaller than a pixel.*scale" -- --image narrow.pgm --mm-per-pixel 2 --phases mastic,stone --out img6
  expect "2" "needs a scale" -- --image narrow.pgm --phases mastic,stone --out img7
  for d in img1 img2 img3 img4 img5 img6 img7; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after a bad image"; failures=$((failures + 1)); }
  done
}

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
  expect "1 2" "--nu: .*0.5" -- --nu 0.5 --out d
  expect "1 2" "--nu: .*0.5" -- --nu -0.1 --out e
  expect "1 2" "alpha_T" -- --shift 0 --out f
  expect "1 2" "alpha_T" -- --shift -1e4 --out g
  expect "2" "--E1" -- --E1 nan --out h
  expect "2" "--eta2" -- --eta2 inf --out i
  expect "2" "--nu" -- --nu nan --out j
  for d in a b c d e f g h i j; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  expect "0" "apparent/macro" -- --out taken --force --stress-mpa 0.01 --time-s 20 --columns 6 --rows 4
  # The progress bar's rate in seconds of the test's loading a second.
  expect "0" "creep \[#+\] 100%  [0-9.e+-]+ test s/s  ETA" -- --out progress --stress-mpa 0.01 --time-s 20 \
    --columns 6 --rows 4
  for f in creep.csv creep.json creep.png; do
    [[ -s "$work/taken/$f" ]] || { echo "FAIL: no $f"; failures=$((failures + 1)); }
  done
  ;;
specimen)
  printf 'sieve_mm,percent_passing\n19,100\n9.5,70\n12,40\n' >"$work/bad.csv"
  expect "1 2" "bad.csv:4" -- --gradation bad.csv --out a
  expect "1 2" "neither a built-in mix \\(1, 2 or 3\\) nor a readable CSV file" -- --gradation 7 --out b
  expect "1 2" "disk-radius" -- --disk-radius-mm -0.5 --out c
  expect "1 2" "air-voids" -- --air-voids 0.5 --out d
  expect "1 2" "height" -- --height-mm -50 --out e
  expect "1 2" "cannot reach" -- --gradation 3 --height-mm 5 --out f
  expect "2" "at least two sieves" -- --gradation one_sieve.csv --out g
  expect "2" "no sieve lines" -- --gradation header_only.csv --out h
  expect "2" "retains nothing on the 2.36" -- --gradation no_stones.csv --out i
  expect "2" "GiB of memory.*available" -- --width-mm 10000 --height-mm 10000 --disk-radius-mm 0.05 --out j
  for d in a b c d e f g h i j; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  expect "0" "area fraction" -- --gradation 3 --seed 5 --out one
  expect "0" "area fraction" -- --gradation 3 --seed 5 --out two
  for f in specimen.png specimen.json specimen.vtk; do
    if ! cmp -s "$work/one/$f" "$work/two/$f"; then echo "FAIL: $f differs between two runs"; failures=$((failures + 1)); fi
  done
  grep -q '"quantity_gradation"' "$work/one/specimen.json" || { echo "FAIL: no quantity_gradation"; failures=$((failures + 1)); }
  bad_images
  # A generated specimen's section.png, read back: the stones' area fraction
  # within 0.01 of the generator's (test_image.cpp checks stone by stone).
  expect "0" "stones.*of the section" -- --image one/section.png --mm-per-pixel 0.1 --phases mastic,stone,void \
    --gradation 3 --out from_image
  for f in segmented.png specimen.png specimen.json specimen.vtk; do
    [[ -s "$work/from_image/$f" ]] || { echo "FAIL: no $f from an image"; failures=$((failures + 1)); }
  done
  generated=$(grep -A2 '"achieved"' "$work/one/specimen.json" | sed -n 's/.*"achieved": \([0-9.]*\).*/\1/p' | head -n 1)
  read_back=$(sed -n 's/.*"stone": \([0-9.]*\).*/\1/p' "$work/from_image/specimen.json" | head -n 1)
  if awk -v a="$generated" -v b="$read_back" 'BEGIN { d = a - b; exit !(a > 0 && (d < 0 ? -d : d) <= 0.01) }'; then
    echo "ok:   the image's stone fraction $read_back, the generator's $generated"
  else echo "FAIL: stone fraction from the image $read_back, generated $generated"; failures=$((failures + 1)); fi
  grep -q '"gradation_percent_passing"' "$work/from_image/specimen.json" ||
    { echo "FAIL: no gradation beside the image's quantity gradation"; failures=$((failures + 1)); }
  # 3D: the options of the other dimension refused, a depth too shallow for
  # the stones refused, and a small box made twice, the same bytes.
  expect "2" "disk-radius-mm is for 2D sections" -- --dim 3 --disk-radius-mm 0.5 --out k
  expect "2" "sphere-radius-mm is for 3D" -- --sphere-radius-mm 1 --out l
  expect "2" "too small for its stones.*at least twice" -- --dim 3 --depth-mm 20 --width-mm 60 --out m
  expect "1 2" "dim" -- --dim 4 --out n
  expect "2" "stone-packing is for 3D" -- --stone-packing compaction --out o
  expect "2" "threads is for 3D" -- --threads 2 --out o2
  expect "1 2" "threads" -- --dim 3 --threads -1 --out o3
  expect "1 2" "stone-packing" -- --dim 3 --stone-packing sideways --out p
  for d in k l m n o o2 o3 p; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  if [[ -n ${VRUT_SANITIZED:-} ]]; then
    # Under the sanitizers (-O0, where Eigen runs a hundred times slower) one
    # small box, once: 18 s for the box below.
    expect "0" "3D: .*volume fraction" -- --dim 3 --gradation 1 --width-mm 30 --height-mm 30 --sphere-radius-mm 1.5 --out three
    echo "$failures failure(s)"
    exit $((failures > 0))
  fi
  expect "0" "3D: .*volume fraction" -- --dim 3 --gradation 1 --width-mm 40 --sphere-radius-mm 1.5 --seed 2 --out three
  expect "0" "3D: .*volume fraction" -- --dim 3 --gradation 1 --width-mm 40 --sphere-radius-mm 1.5 --seed 2 --out three_again
  for f in specimen.json specimen.vtk section_mid_depth.png surface.png; do
    [[ -s "$work/three/$f" ]] || { echo "FAIL: no $f from --dim 3"; failures=$((failures + 1)); }
    [[ $f == specimen.json ]] && continue  # it holds the time taken
    cmp -s "$work/three/$f" "$work/three_again/$f" || { echo "FAIL: 3D $f differs between two runs"; failures=$((failures + 1)); }
  done
  grep -q '"dimension": 3' "$work/three/specimen.json" || { echo "FAIL: no dimension in the 3D specimen.json"; failures=$((failures + 1)); }
  ;;
rutting)
  small=(--width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e5 --settle-steps 300)
  expect "1 2" "neither a built-in mix \\(1, 2 or 3\\) nor a readable CSV file" -- --gradation 7 --out a
  expect "1 2" "pressure" -- --pressure-mpa -0.7 --out b
  expect "1 2" "longer than the specimen" -- --width-mm 20 --out c
  if [[ -n ${VRUT_NO_IMAGES:-} ]]; then  # built with VRUT_IMAGES=OFF: an image is refused with the reason
    expect "2" "built without OpenCV" -- --image narrow.pgm --mm-per-pixel 0.1 --out img0
  else
    bad_images
    expect "2" "narrow.pgm: .*longer than the specimen" -- --image narrow.pgm --mm-per-pixel 0.1 --phases mastic,stone --out img8
    expect "2" "--seed and --seeds do not go with it" -- --image narrow.pgm --mm-per-pixel 0.1 --seed 4 --out img9
  fi
  for d in img0 img8 img9; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after a bad image"; failures=$((failures + 1)); }
  done
  printf 'gradation=2\nno_such_key=3\n' >"$work/extra.ini"
  expect "1 2" "no_such_key" -- --config extra.ini --out d
  printf 'seed=abc\n' >"$work/badvalue.ini"
  expect "1 2" "seed" -- --config badvalue.ini --out e
  expect "1 2" "--mastic-nu: .*0.5" -- --mastic-nu 0.6 --out f
  expect "1 2" "alpha_T" -- --shift 0 --out g
  # The method's stiff stones blow up at the full critical step (rigid stones, softer, do not).
  expect "1" "unstable at step [0-9]+.*time step" -- "${small[@]}" --exact-stones --timestep-safety 1.0 --out h
  for d in a b c d e f g h; do
    [[ -e "$work/$d" ]] && { echo "FAIL: output folder $d written after an error"; failures=$((failures + 1)); }
  done
  # The default folder (no --out) is replaced by the next run, so the main
  # job runs twice; a folder named with --out is not, nor the default one
  # while it holds an unfinished run's checkpoint.
  if [[ -z ${VRUT_ERRORS_ONLY:-} ]]; then
    expect "0" "rut depth" -- "${small[@]}" --seed 1
    expect "0" "rut depth" -- "${small[@]}" --seed 2
    grep -q '"seed": 2' "$work/out/rutting/summary.json" ||
      { echo "FAIL: the second run did not replace the default folder's results"; failures=$((failures + 1)); }
    expect "2" "exists and is not empty \(use --force" -- "${small[@]}" --out out/rutting
    touch "$work/out/rutting/checkpoint.vrut"
    expect "2" "holds the checkpoint of an unfinished run: go on with it with vrut-rutting --resume out/rutting" -- \
      "${small[@]}"
    rm -rf "$work/out"
  fi
  # Negative, zero, NaN and infinite values: exit 2, the option named, no folder.
  for option in --E1 --eta1 --E2 --eta2 --aggregate-modulus-gpa --wheel-mass-kg --travel-mm --passes-per-minute \
                --minutes; do
    for value in -1 0 nan inf; do expect "2" "^$option: " -- "$option" "$value" --out bad; done
  done
  for option in --aggregate-nu --mastic-nu; do
    for value in -0.1 0.5 nan inf; do expect "2" "^$option: " -- "$option" "$value" --out bad; done
  done
  # The step's safety: -1 (the dimension's) or in [0.001, 2] (past 2 a spring
  # alone is unstable); no other negative.
  for value in -0.5 -2 0 2.5 nan inf; do
    expect "2" "^--timestep-safety: must be -1 or \\[0.001, 2\\], got" -- --timestep-safety "$value" --out bad
  done
  # The settling's steps: -1 (as long as 4,000 at 0.3) or a count; no other negative.
  expect "2" "^--settle-steps: " -- --settle-steps -2 --out bad
  expect "2" "must last longer than minute 45" -- --minutes 30 --out bad
  expect "2" "retains nothing on the 2.36" -- --gradation no_stones.csv --out bad
  expect "2" "at least two sieves" -- --gradation one_sieve.csv --out bad
  expect "2" "no sieve lines" -- --gradation header_only.csv --out bad
  # Work that cannot fit in memory is refused before it starts, with the estimate.
  expect "2" "needs about [0-9.e+]+ GiB of memory.*available" -- --width-mm 10000 --height-mm 10000 \
    --disk-radius-mm 0.05 --out bad
  [[ -e "$work/bad" ]] && { echo "FAIL: output folder bad written after an error"; failures=$((failures + 1)); }
  # 3D: what it does not have is refused by name, and the 3D options in 2D.
  small3=(--dim 3 --gradation 1 --width-mm 40 --sphere-radius-mm 1.5 --shift 1e5 --settle-steps 300)
  expect "2" "film per contact, or through none" -- "${small3[@]}" --stone-film mean --out bad3
  expect "2" "--exact-stones is not in the 3D test: its stones are rigid" -- "${small3[@]}" --exact-stones --out bad3
  expect "2" "--conversion calibrated is not in the 3D test" -- "${small3[@]}" --conversion calibrated --out bad3
  expect "2" "--image is not in the 3D test" -- "${small3[@]}" --image text.png --out bad3
  expect "2" "--disk-radius-mm is for 2D" -- "${small3[@]}" --disk-radius-mm 0.5 --out bad3
  expect "2" "--mastic-aggregate-factor is the 2D model's" -- "${small3[@]}" --mastic-aggregate-factor 3 --out bad3
  expect "2" "--depth-mm is for the 3D test" -- --depth-mm 30 --out bad3
  expect "2" "--mastic-aggregate-factor-3d is for the 3D test" -- --mastic-aggregate-factor-3d 3 --out bad3
  expect "2" "--stone-packing is for the 3D test" -- --stone-packing random --out bad3
  expect "2" "too small for its stones" -- "${small3[@]}" --depth-mm 20 --out bad3
  expect "2" "--plate patch is for the 3D test" -- --plate patch --out bad3
  expect "2" "--section transverse and --plate patch are two plates" -- "${small3[@]}" --section transverse --plate patch --out bad3
  expect "2" "--stone-shear-film: 'soap' is none, binder or a thickness" -- --stone-shear-film soap --out bad3
  expect "2" "relaxes through its binder film with the film per contact" -- --stone-film mean --stone-shear-film binder --out bad3
  expect "2" "patch needs a box at least 100 mm deep.*give --depth-mm 101.82" -- "${small3[@]}" --plate patch --out bad3
  expect "1 2" "plate" -- "${small3[@]}" --plate disk --out bad3
  expect "1 2" "is model, none or the filler's Rigden voids" -- "${small3[@]}" --mastic-by-filler 35 --out bad3
  [[ -e "$work/bad3" ]] && { echo "FAIL: output folder bad3 written after an error"; failures=$((failures + 1)); }
  # The runs that succeed, which the sanitizer build (VRUT_ERRORS_ONLY) leaves out: too slow there.
  if [[ -z ${VRUT_ERRORS_ONLY:-} ]]; then
  # A small 3D run end to end, its outputs, and the plate held at the pressure.
  expect "0" "3D: rut depth" -- "${small3[@]}" --out run3d
  for f in summary.json deformation.csv deformation.png section_mid_depth.png specimen_mid_depth.png surface.png \
           final.vtk config.ini; do
    [[ -s "$work/run3d/$f" ]] || { echo "FAIL: no 3D $f"; failures=$((failures + 1)); }
  done
  grep -q '"dimension": 3' "$work/run3d/summary.json" || { echo "FAIL: no dimension in the 3D summary"; failures=$((failures + 1)); }
  # The mean pressure over the last sample of the curve: 0.7 MPa within 2 %.
  pressure3=$(tail -n 1 "$work/run3d/deformation.csv" | cut -d, -f4)
  if awk -v p="$pressure3" 'BEGIN { exit !(p > 0.686 && p < 0.714) }'; then echo "ok:   3D plate pressure $pressure3 MPa"
  else echo "FAIL: 3D plate pressure $pressure3 MPa, not 0.7"; failures=$((failures + 1)); fi
  # Its config.ini runs it again, the same curve.
  expect "0" "3D: rut depth" -- --config run3d/config.ini --out run3d_again
  cmp -s "$work/run3d/deformation.csv" "$work/run3d_again/deformation.csv" ||
    { echo "FAIL: the 3D run's config.ini does not reproduce it"; failures=$((failures + 1)); }
  # The film between stones (the default, per contact) is softer than the
  # stones' spring alone at every overlap, as in 2D.
  grep -q '"stone_film": "per-contact"' "$work/run3d/summary.json" ||
    { echo "FAIL: the 3D summary does not say the stones meet through the film"; failures=$((failures + 1)); }
  expect "0" "3D: rut depth" -- "${small3[@]}" --stone-film none --out run3d_none
  # The 3D model's defaults (docs/rutting.md, "In 3D"): the stones' friction
  # 0.6 fitted on 2#, and the mastic stiffened by its filler at Rigden voids
  # 0.35: 1# holds more filler than 2#, the mastic's mix, so a stiffer mastic.
  for key in '"stone_friction": 0.6,' '"mastic_by_filler": "0.35",' '"calibrated": true,'; do
    grep -qF "$key" "$work/run3d/summary.json" || { echo "FAIL: the 3D summary lacks $key"; failures=$((failures + 1)); }
  done
  # By how much: 1.6906, Krieger-Dougherty's f(phi) of 1#'s filler over 2#'s
  # at voids 0.35, worked by hand in test_filler_mastic.cpp (to 1e-4).
  if awk -F': ' '/"mastic_scale"/ { s = $2 + 0 } END { exit !(s > 1.6906 * (1 - 1e-4) && s < 1.6906 * (1 + 1e-4)) }' \
       "$work/run3d/summary.json"; then
    echo "ok:   3D 1#'s mastic stiffened by its filler, 1.6906 times as worked by hand"
  else echo "FAIL: 3D 1#'s mastic not stiffened by its filler 1.6906 times: $(grep mastic_scale "$work/run3d/summary.json")"
    failures=$((failures + 1)); fi
  # At its defaults the command line runs the library's frozen 3D model
  # (protocol/rutting/model3.hpp) at the 3D step's safety (0.5): the box of
  # test_rutting3.cpp's "a short run of the frozen model" gives that test's
  # pinned rut, to the bit (a regression pin: it changes with that one).
  expect "0" "3D: rut depth" -- --dim 3 --gradation 1 --width-mm 40 --sphere-radius-mm 2 --shift 1e6 --settle-steps 300 \
    --samples 24 --out model3
  grep -qF '"rut_depth_mm": 3.16406393753757,' "$work/model3/summary.json" ||
    { echo "FAIL: the 3D defaults are not the library's frozen 3D model (pinned rut 3.1640639375375699)"; failures=$((failures + 1)); }
  # The same model typed out, the filler's voids as .35 and the 3D step's
  # safety as .5: the same run, and it says it is the model.
  expect "0" "3D: rut depth" -- --dim 3 --gradation 1 --width-mm 40 --sphere-radius-mm 2 --shift 1e6 --settle-steps 300 \
    --samples 24 --stone-friction 0.6 --mastic-by-filler .35 --timestep-safety .5 --out model3_typed
  cmp -s "$work/model3/deformation.csv" "$work/model3_typed/deformation.csv" ||
    { echo "FAIL: the 3D model typed out is not the same run as at the defaults"; failures=$((failures + 1)); }
  grep -qF '"calibrated": true,' "$work/model3_typed/summary.json" ||
    { echo "FAIL: the 3D model typed out (.35) is not said to be the model"; failures=$((failures + 1)); }
  grep -qF '"timestep_safety": 0.5,' "$work/model3/summary.json" ||
    { echo "FAIL: the 3D step's safety at its default is not 0.5 in summary.json"; failures=$((failures + 1)); }
  expect "0" "rut depth" -- "${small[@]}" --out run1
  grep -qF '"timestep_safety": 0.3,' "$work/run1/summary.json" ||
    { echo "FAIL: the 2D step's safety at its default is not 0.3 in summary.json"; failures=$((failures + 1)); }
  # The settling left to its default lasts as long as 4,000 steps at the
  # safety 0.3: 4,000 at 2D's 0.3, 4000 x 0.3 / 0.24 = 5,000 at 0.24.
  small_settling=(--width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e5)
  expect "0" "rut depth" -- "${small_settling[@]}" --out settle_default
  grep -qF '"settle_steps": 4000,' "$work/settle_default/summary.json" ||
    { echo "FAIL: the 2D settling at its default is not 4,000 steps in summary.json"; failures=$((failures + 1)); }
  expect "0" "rut depth" -- "${small_settling[@]}" --timestep-safety 0.24 --out settle_small_step
  grep -qF '"settle_steps": 5000,' "$work/settle_small_step/summary.json" ||
    { echo "FAIL: the settling at the safety 0.24 is not 5,000 steps (as long as 4,000 at 0.3)"; failures=$((failures + 1)); }
  for f in summary.json deformation.csv deformation.png specimen.png rut_forming.png displacement.png final.vtk config.ini; do
    [[ -s "$work/run1/$f" ]] || { echo "FAIL: no $f"; failures=$((failures + 1)); }
  done
  for key in gradation seed disk_radius_mm shift_factor particles contacts steps wall_seconds backend threads \
             particle_steps_per_second deformation_45min_mm deformation_60min_mm rut_depth_mm dynamic_stability_passes_per_mm; do
    grep -q "\"$key\"" "$work/run1/summary.json" || { echo "FAIL: summary.json lacks $key"; failures=$((failures + 1)); }
  done
  # The 2D model keeps its own: the stones' friction the mastic's, one mastic for every mix.
  for key in '"stone_friction": 1.0,' '"mastic_by_filler": "none",'; do
    grep -qF "$key" "$work/run1/summary.json" || { echo "FAIL: the 2D summary lacks $key"; failures=$((failures + 1)); }
  done
  expect "1 2" "exists" -- "${small[@]}" --out run1
  # The config written is the config used: reading it back gives the same
  # result. (Its progress bar's rate: minutes of the test a second.)
  expect "0" "loading \[#+\] 100%  [0-9.e+-]+ test min/s  ETA" -- --config run1/config.ini --out run2
  cmp -s "$work/run1/deformation.csv" "$work/run2/deformation.csv" ||
    { echo "FAIL: the written config.ini does not reproduce the run"; failures=$((failures + 1)); }
  # The options of the study and the calibrated conversion run end to end, and
  # each softens the model where it should: a film between stones (the
  # default, per contact, as run1; or the mean film) is softer than the rigid
  # stone contact alone (--stone-film none) at every overlap, an endless film
  # softer still, and the calibrated micro parameters are 0.74 of the seed
  # rules' (docs/burgers.md), so they rut more than run1.
  rut_of() { grep -o '"rut_depth_mm": [-0-9.e+]*' "$work/$1/summary.json" | head -n 1 | awk '{ print $2 }'; }
  deeper() {  # deeper A B: A ruts more than B
    if awk -v a="$(rut_of "$1")" -v b="$(rut_of "$2")" 'BEGIN { exit !(a > b) }'; then
      echo "ok:   $1 ruts $(rut_of "$1") mm, more than $2's $(rut_of "$2") mm"
    else echo "FAIL: $1 ruts $(rut_of "$1") mm, not more than $2's $(rut_of "$2") mm"; failures=$((failures + 1)); fi
  }
  expect "0" "rut depth" -- "${small[@]}" --stone-film none --out no_film
  expect "0" "rut depth" -- "${small[@]}" --stone-film mean --out film
  expect "0" "rut depth" -- "${small[@]}" --stone-film mean --film-endless --out endless
  expect "0" "rut depth" -- "${small[@]}" --conversion calibrated --out calibrated
  expect "1 2" "endless.*mean film" -- "${small[@]}" --stone-film none --film-endless --out endless_alone
  expect "1 2" "cannot be endless" -- "${small[@]}" --film-endless --out endless_per_contact
  expect "1 2" "stone-film" -- "${small[@]}" --stone-film thick --out bad_film
  deeper film no_film
  deeper run3d run3d_none
  deeper endless film
  deeper run1 no_film
  deeper calibrated run1
  grep -q '"conversion": "calibrated"' "$work/calibrated/summary.json" ||
    { echo "FAIL: summary.json does not say the conversion was calibrated"; failures=$((failures + 1)); }
  grep -q '"stone_film": "none"' "$work/no_film/summary.json" ||
    { echo "FAIL: summary.json does not say the stones met without a film"; failures=$((failures + 1)); }
  grep -qx 'stone-film="mean"' "$work/film/config.ini" ||
    { echo "FAIL: config.ini lacks stone-film=mean"; failures=$((failures + 1)); }
  # A DS past what the curve resolves (a mastic 1,200 times as viscous: the
  # plate hardly moves after minute 45) is a lower bound: "above N" in the
  # printout, a flag in summary.json and seeds.csv, and N = the passes of the
  # window (15 min x 42) over the resolution.
  stiff=(--eta1 1e5 --eta2 1e5 --E2 100)
  expect "0" "dynamic stability above [0-9]+ passes/mm" -- "${small[@]}" "${stiff[@]}" --out bound
  grep -q '"dynamic_stability_is_lower_bound": true' "$work/bound/summary.json" ||
    { echo "FAIL: summary.json does not flag the DS as a lower bound"; failures=$((failures + 1)); }
  ds_of_resolution() {  # the DS and the resolution of one summary.json, and whether DS = 630 / resolution
    awk -F': ' '/"dynamic_stability_passes_per_mm"/ { ds = $2 + 0 } /"deformation_resolution_mm"/ { res = $2 + 0 }
                END { printf "%s %s ", ds, res; exit !(res > 0 && ds > 0 && (ds * res / 630 - 1) ^ 2 < 1e-18) }' "$1"
  }
  if line=$(ds_of_resolution "$work/bound/summary.json"); then echo "ok:   DS above $line (resolution mm) = 630 / resolution"
  else echo "FAIL: the DS lower bound is not 630 over the resolution: $line"; failures=$((failures + 1)); fi
  expect "0" "dynamic stability: mean above .* are lower bounds \(seeds.csv\)" -- "${small[@]}" "${stiff[@]}" --seeds 1-2 \
    --out bounds
  if awk -F, 'NR > 1 { n++; if ($9 != 1 || $8 * $10 / 630 - 1 > 1e-9 || $8 * $10 / 630 - 1 < -1e-9) bad++ }
              END { exit !(n == 2 && bad == 0) }' "$work/bounds/seeds.csv"; then
    echo "ok:   seeds.csv flags both DS as lower bounds, each 630 / its resolution"
  else echo "FAIL: seeds.csv: $(cat "$work/bounds/seeds.csv")"; failures=$((failures + 1)); fi
  [[ $(grep -c '"dynamic_stability_is_lower_bound": true' "$work/bounds/summary.json") -ge 2 ]] ||
    { echo "FAIL: summary.json's per-seed entries do not flag the lower bounds"; failures=$((failures + 1)); }
  # As the standard reports them: each DS capped at 6000 and censored
  # (columns 14-15), and the median of two censored values censored too.
  if awk -F, 'NR > 1 { n++; cap = $8 < 6000 ? $8 : 6000; if ($15 != 1 || ($14 - cap) ^ 2 > 1e-12) bad++ }
              END { exit !(n == 2 && bad == 0) }' "$work/bounds/seeds.csv"; then
    echo "ok:   seeds.csv gives each DS as the standard does: min(DS, 6000), censored"
  else echo "FAIL: seeds.csv's standard DS: $(cat "$work/bounds/seeds.csv")"; failures=$((failures + 1)); fi
  grep -A 2 '"dynamic_stability_standard_median"' "$work/bounds/summary.json" | grep -q '"censored": true' ||
    { echo "FAIL: summary.json's standard median of two censored DS is not censored"; failures=$((failures + 1)); }
  # Ctrl-C: the run stops at its next sample, writes the results so far, says
  # so and exits 130 (128 + SIGINT). A test of 100 times the usual length
  # (alpha_T 1e3), so that the signal comes while it loads. An ensemble of
  # two: its seeds.csv has no DS as the standard reports it ("nan").
  (cd "$work" && exec "$exe" --width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 1e3 --settle-steps 300 \
     --seeds 1-2 --out intr >intr.out 2>intr.err) &
  pid=$!
  for _ in $(seq 150); do grep -q "specimens:" "$work/intr.err" 2>/dev/null && break; sleep 0.2; done
  sleep 2
  kill -INT "$pid"
  wait "$pid"; code=$?
  if [[ $code -ne 130 ]] || ! grep -q "partial results" "$work/intr.out" ||
     ! grep -q '"interrupted": true' "$work/intr/summary.json" 2>/dev/null ||
     [[ $(wc -l <"$work/intr/deformation.csv") -lt 3 ]] ||
     [[ $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
                   $col["ds_standard_passes_per_mm"] == "nan" && $col["ds_standard_censored"] == "nan"' \
          "$work/intr/seeds.csv" | wc -l) -ne 2 ]]; then
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
  # The rutting test on images: 60 x 30 mm at 0.1 mm per pixel, square 3 mm
  # stones (grey) in rows in mastic (black), the same image twice as an
  # ensemble: two specimens, each with the curve of the other.
  if [[ -z ${VRUT_NO_IMAGES:-} ]]; then
  head -c 18000 /dev/zero >"$work/mastic_band"  # 30 rows of 600 black pixels
  for _ in $(seq 10); do head -c 30 /dev/zero; head -c 30 /dev/zero | tr '\0' '\200'; done >"$work/stone_row"
  for _ in $(seq 30); do cat "$work/stone_row"; done >"$work/stone_band"
  { printf 'P5\n600 300\n255\n'; for _ in 1 2 3 4 5; do cat "$work/mastic_band" "$work/stone_band"; done; } >"$work/blocks.pgm"
  images=(--image blocks.pgm --image blocks.pgm --mm-per-pixel 0.1 --phases mastic,stone --disk-radius-mm 1 --shift 1e5
          --settle-steps 300)
  expect "0" "2 specimens: rut depth" -- "${images[@]}" --out from_images
  if awk -F, 'NR == 2 { a = $5 } NR == 3 { b = $5; img = $NF } END { exit !(NR == 3 && a == b && img == "blocks.pgm") }' \
       "$work/from_images/seeds.csv"; then
    echo "ok:   two runs of one image give one rut, and seeds.csv names the image"
  else echo "FAIL: seeds.csv of the images: $(cat "$work/from_images/seeds.csv")"; failures=$((failures + 1)); fi
  grep -q '"images"' "$work/from_images/summary.json" || { echo "FAIL: summary.json names no images"; failures=$((failures + 1)); }
  fi
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
  # An ensemble of one seed (a specimen to pool with other runs' by
  # vrut-pool) says it has no interval, not "nan", and writes its seeds.csv.
  expect "0" "1 specimen: rut depth [0-9.]+ mm at [0-9]+ min \(one specimen, no interval\), dynamic stability: mean [0-9]+ \(no interval\)" \
    -- "${small[@]}" --seeds 2 --out ens_one
  [[ $(wc -l <"$work/ens_one/seeds.csv") -eq 2 ]] || { echo "FAIL: the one-seed ensemble's seeds.csv"; failures=$((failures + 1)); }
  ;;
esac

echo "$failures failure(s)"
exit $((failures > 0))

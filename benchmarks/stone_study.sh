#!/usr/bin/env bash
# The rigid-stone study (docs/validation.md, "Rigid stones and the time step").
# For each mix, one ensemble per row on the same seeds (so every change is
# paired), then stone_study_table.sh prints the table:
#   exact      the method's stones: bonded disks on 2 t E springs (today's default)
#   control    a negligible change of it (stone E 55.0 against 55.5 GPa): how
#              much of a paired change is chaos
#   rigid-R    rigid stones, stone and wall springs R times the mastic's E1 t,
#              5 % of critical damping; rigid-R-undamped without the dashpot,
#              rigid-R-dZ with Z of critical
# A row whose summary.json exists is not run again.
#   Usage: stone_study.sh OUT_DIR "MIXES" SEEDS "ROWS" [vrut-rutting options...]
#   e.g.   stone_study.sh out/stones "1 2 3" 1-8 "exact control rigid-1000 rigid-300 rigid-100 rigid-30" --width-mm 100
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${VRUT_RUTTING:-$here/build/examples/vrut-rutting}
out=$1 mixes=$2 seeds=$3 rows=$4
shift 4
mkdir -p "$out"
for mix in $mixes; do
  for row in $rows; do
    case $row in
      exact) args=() ;;
      control) args=(--aggregate-modulus-gpa 55.0) ;;
      rigid-*-undamped) r=${row#rigid-}; args=(--rigid-stones --stone-contact-ratio "${r%-undamped}" --stone-damping 0) ;;
      rigid-*-d*) r=${row#rigid-}; args=(--rigid-stones --stone-contact-ratio "${r%-d*}" --stone-damping "${r#*-d}") ;;
      rigid-*) args=(--rigid-stones --stone-contact-ratio "${row#rigid-}" --stone-damping 0.05) ;;
      *) echo "unknown row $row" >&2; exit 2 ;;
    esac
    dir=$out/$mix-$row
    [[ -f $dir/summary.json ]] && continue
    echo "== $mix# $row: vrut-rutting --gradation $mix --seeds $seeds ${args[*]} $*" >&2
    "$exe" --gradation "$mix" --seeds "$seeds" "${args[@]}" "$@" --out "$dir" --force
  done
done

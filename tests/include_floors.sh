#!/usr/bin/env bash
# The folders of include/vrut stand on floors (docs/core.md, "Floors"): a
# header includes headers of its own folder and of lower floors only, never
# of its own floor's other folders or of a higher one. So no two folders
# include each other, and the engine never reaches up into a test protocol,
# the host's files or the application. Prints every include that breaks it.
#   Usage: include_floors.sh INCLUDE_DIR   (the folder holding vrut/)
set -uo pipefail
root=${1:?usage: include_floors.sh INCLUDE_DIR}
declare -A floor=(
  [data]=0 [version.hpp]=0 [backend.hpp]=0
  [contact]=1 [geometry]=1 [integrate]=1 [neighbor]=1 [control]=1 [specimen]=1
  [core]=2 [servo]=2 [material]=2 [io]=2
  [protocol]=3 [vrut.hpp]=3
  [analysis]=4
  [app]=5
)
# A header's room: its folder under vrut/, or its own name at the top.
room() { local p=${1#vrut/}; [[ $p == */* ]] && echo "${p%%/*}" || echo "$p"; }
bad=0 headers=0
while IFS= read -r file; do
  rel=${file#"$root"/}
  from=$(room "$rel")
  [[ -n ${floor[$from]+x} ]] || { echo "FAIL: $rel: its room '$from' has no floor (add it here and to docs/core.md)"; bad=1; continue; }
  headers=$((headers + 1))
  while IFS= read -r inc; do
    to=$(room "$inc")
    [[ $to == "$from" ]] && continue
    if [[ -z ${floor[$to]+x} ]]; then
      echo "FAIL: $rel includes $inc, whose room '$to' has no floor"; bad=1
    elif (( floor[$to] >= floor[$from] )); then
      echo "FAIL: $rel (floor ${floor[$from]}, $from) includes $inc (floor ${floor[$to]}, $to)"; bad=1
    fi
  done < <(sed -n 's|^[[:space:]]*#[[:space:]]*include[[:space:]]*<\(vrut/[^>]*\)>.*|\1|p' "$file")
done < <(find "$root/vrut" -name '*.hpp' | sort)
(( headers > 0 )) || { echo "FAIL: no headers under $root/vrut"; exit 1; }
(( bad == 0 )) && echo "PASS: $headers headers, every include on its own room or a lower floor"
exit $bad

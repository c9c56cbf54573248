#!/usr/bin/env bash
# The folders of include/vrut stand on floors (docs/core.md, "Floors"): a
# header includes headers of its own folder and of lower floors only, never
# of its own floor's other folders or of a higher one. So no two folders
# include each other, and the engine never reaches up into a test protocol,
# the host's files or the application. Prints every include that breaks it.
# Both forms are read: <vrut/...>, and "..." as the compiler finds it (beside
# the including header first, then from the include folder: "cli.hpp" in
# app/ is app/cli.hpp, "vrut/app/cli.hpp" anywhere is app/cli.hpp).
#   Usage: include_floors.sh INCLUDE_DIR   (the folder holding vrut/)
#          include_floors.sh --self-test  (shows that it fails on a bad include of each form)
set -uo pipefail
if [[ ${1:-} == --self-test ]]; then
  # A tree of three rooms, each with one bad include: the check must fail on
  # each and name it, and pass once the bad includes are gone.
  me=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")
  tree=$(mktemp -d)
  trap 'rm -rf "$tree"' EXIT
  mkdir -p "$tree/vrut/data" "$tree/vrut/app" "$tree/vrut/core"
  printf '#pragma once\n' >"$tree/vrut/app/cli.hpp"
  printf '#pragma once\n#include <vrut/data/vec2.hpp>\n#include "cli.hpp"\n' >"$tree/vrut/app/draw.hpp"
  printf '#pragma once\n' >"$tree/vrut/data/vec2.hpp"
  printf '#pragma once\n#include <vrut/data/vec2.hpp>\n' >"$tree/vrut/core/sim.hpp"
  "$me" "$tree" >"$tree/clean.out" || { echo "FAIL: a clean tree fails: $(cat "$tree/clean.out")"; exit 1; }
  failures=0
  for bad in '#include <vrut/app/cli.hpp>' '#include "vrut/app/cli.hpp"' '#include "../app/cli.hpp"' '#  include "vrut/core/sim.hpp"'; do
    cp "$tree/vrut/data/vec2.hpp" "$tree/vec2.keep"
    printf '%s\n' "$bad" >>"$tree/vrut/data/vec2.hpp"
    if "$me" "$tree" >"$tree/bad.out"; then
      echo "FAIL: data/ with '$bad' passes"; failures=$((failures + 1))
    elif ! grep -q "FAIL: vrut/data/vec2.hpp (floor 0, data) includes" "$tree/bad.out"; then
      echo "FAIL: data/ with '$bad' fails without naming it: $(cat "$tree/bad.out")"; failures=$((failures + 1))
    else
      echo "ok:   '$bad' in data/ fails: $(head -n 1 "$tree/bad.out")"
    fi
    mv "$tree/vec2.keep" "$tree/vrut/data/vec2.hpp"
  done
  exit $((failures > 0))
fi
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
# Every vrut header a header includes, as a path under the include folder.
includes() {  # includes REL (vrut/...)
  local dir quoted resolved
  dir=$(dirname "$1")
  sed -n 's|^[[:space:]]*#[[:space:]]*include[[:space:]]*<\(vrut/[^>]*\)>.*|\1|p' "$root/$1"
  while IFS= read -r quoted; do
    if [[ -e $root/$dir/$quoted ]]; then
      resolved=$(realpath -m --relative-to="$root" "$root/$dir/$quoted")
    else
      resolved=$(realpath -m --relative-to="$root" "$root/$quoted")
    fi
    [[ $resolved == vrut/* ]] && echo "$resolved"
  done < <(sed -n 's|^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*|\1|p' "$root/$1")
}
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
  done < <(includes "$rel")
done < <(find "$root/vrut" -name '*.hpp' | sort)
(( headers > 0 )) || { echo "FAIL: no headers under $root/vrut"; exit 1; }
(( bad == 0 )) && echo "PASS: $headers headers, every include on its own room or a lower floor"
exit $bad

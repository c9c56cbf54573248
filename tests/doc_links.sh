#!/usr/bin/env bash
# Links that cannot rot: every relative link in README.md, CHANGELOG.md and
# docs/ names a file that exists, and a heading there where it names one
# (#anchor, as GitHub spells a heading); every repository path cited in
# those pages and in the comments of include/ exists (a path under docs/,
# tests/, examples/, scripts/, benchmarks/, python/, cmake/ or include/, or
# one under include/vrut/ written as its folder and name,
# protocol/rutting/box.hpp say); no header carries a date. No page or
# comment cites SPEC.md, which users do not have, or an issue by its
# number, which they cannot follow.
#   Usage: doc_links.sh SOURCE_DIR
#          doc_links.sh --self-test SOURCE_DIR  (shows that it fails on a broken link of each kind)
set -uo pipefail
if [[ ${1:-} == --self-test ]]; then
  src=${2:?usage: doc_links.sh --self-test SOURCE_DIR}
  me=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")
  tree=$(mktemp -d)
  trap 'rm -rf "$tree"' EXIT
  mkdir -p "$tree/docs" "$tree/include/vrut/core" "$tree/tests"
  printf '# t\nSee [the guide](docs/guide.md#start) and `include/vrut/core/sim.hpp`.\n' >"$tree/README.md"
  printf '# guide\n## Start\nBack to [the readme](../README.md#t); `core/sim.hpp`.\n' >"$tree/docs/guide.md"
  printf '#pragma once\n// As docs/guide.md says.\n' >"$tree/include/vrut/core/sim.hpp"
  "$me" "$tree" >"$tree/clean.out" || { echo "FAIL: a clean tree fails: $(cat "$tree/clean.out")"; exit 1; }
  failures=0
  for bad in 'README.md|[gone](docs/gone.md)' 'docs/guide.md|`tests/gone.sh`' 'include/vrut/core/sim.hpp|// see docs/gone.md' \
             'docs/guide.md|`core/gone.hpp`' 'README.md|as SPEC.md says' 'docs/guide.md|(issue 44)' \
             'README.md|[gone](docs/guide.md#gone)' 'docs/guide.md|[gone](#gone)' \
             'include/vrut/core/sim.hpp|// the default since 2026-12-02'; do
    file=${bad%%|*} line=${bad#*|}
    cp "$tree/$file" "$tree/keep"
    printf '%s\n' "$line" >>"$tree/$file"
    if "$me" "$tree" >"$tree/bad.out"; then echo "FAIL: '$line' in $file passes"; failures=$((failures + 1))
    elif ! grep -q "^FAIL: $file:" "$tree/bad.out"; then echo "FAIL: '$line' in $file not named: $(cat "$tree/bad.out")"; failures=$((failures + 1))
    else echo "ok:   '$line' in $file fails: $(head -n 1 "$tree/bad.out")"; fi
    mv "$tree/keep" "$tree/$file"
  done
  exit $((failures > 0))
fi
root=${1:?usage: doc_links.sh SOURCE_DIR}
cd "$root" || exit 1
bad=0 checked=0
fail() { echo "FAIL: $*"; bad=1; }
pages=$(ls README.md CHANGELOG.md 2>/dev/null; find docs -name '*.md' 2>/dev/null | sort)
headers=$(find include -name '*.hpp' 2>/dev/null | sort)
repo_path='(docs|tests|examples|scripts|benchmarks|python|cmake|include)/[A-Za-z0-9_./-]*[A-Za-z0-9_]'
# A path cited in FILE (line LINE) exists from the root, or from include/vrut/.
check_path() {  # check_path FILE LINE PATH
  local p=${3%/}
  p=${p%.}
  checked=$((checked + 1))
  [[ -e $p || -e include/vrut/$p ]] || fail "$1:$2: '$3' does not exist"
}
for page in $pages; do
  dir=$(dirname "$page")
  # Markdown links [text](target): relative ones, less their #anchor.
  while IFS=: read -r n target; do
    target=${target%%#*}
    [[ -z $target || $target == *://* || $target == mailto:* ]] && continue
    checked=$((checked + 1))
    [[ -e $dir/$target ]] || fail "$page:$n: link to '$target' ($dir/$target does not exist)"
  done < <(grep -noE '\]\([^) ]+\)' "$page" | sed -E 's/^([0-9]+):\]\(([^) ]+)\)$/\1:\2/')
  # Paths in code spans: `include/vrut/core/simulation.hpp`, `protocol/rutting/box.hpp`.
  while IFS=: read -r n path; do check_path "$page" "$n" "$path"
  done < <(grep -noE '`[A-Za-z0-9_./-]+/[A-Za-z0-9_.-]+\.(hpp|cpp|sh|py|md|cmake|txt|csv)`' "$page" | tr -d '`')
done
for header in $headers; do
  while IFS=: read -r n path; do check_path "$header" "$n" "$path"
  done < <(grep -nE '^\s*//' "$header" | grep -oE "^[0-9]+:|$repo_path\.(hpp|cpp|sh|py|md)" |
           awk '/:$/ { n = $0; next } { print n $0 }')
done
# Anchors: [text](page.md#heading) and [text](#heading) name a heading of
# that page, as GitHub spells it: lower case, links and code marks
# dropped, every character but letters, digits, _, - and space dropped,
# spaces as -, and -1, -2 after a repeated one. (Emphasis, titled and
# reference links are not read: no page here uses them in a heading or a
# link to one.) A check that cannot run fails.
python=$(command -v /usr/bin/python3 || command -v python3) || fail "python3 is needed to check the anchors"
[[ -n $python ]] && "$python" - $pages <<'PY' >/tmp/doc_anchors.$$ 2>&1 || fail "the anchor check failed to run: $(tail -n 3 /tmp/doc_anchors.$$)"
import os, re, sys

def anchors(path, cache={}):
    if path not in cache:
        found, seen, fence = set(), {}, False
        for line in open(path, encoding="utf-8", errors="replace"):
            if line.startswith("```"):
                fence = not fence
            m = None if fence else re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
            if not m:
                continue
            text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", m.group(1)).replace("`", "")
            slug = re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")
            seen[slug] = seen.get(slug, -1) + 1
            found.add(slug if seen[slug] == 0 else f"{slug}-{seen[slug]}")
        cache[path] = found
    return cache[path]

for page in sys.argv[1:]:
    for n, line in enumerate(open(page, encoding="utf-8", errors="replace"), 1):
        for target in re.findall(r"\]\(([^) ]+)\)", line):
            if "://" in target or "#" not in target:
                continue
            name, anchor = target.split("#", 1)
            path = os.path.normpath(os.path.join(os.path.dirname(page), name)) if name else page
            if path.endswith(".md") and os.path.exists(path) and anchor not in anchors(path):
                print(f"FAIL: {page}:{n}: no heading '#{anchor}' in {path}")
PY
cat /tmp/doc_anchors.$$
[[ -s /tmp/doc_anchors.$$ ]] && bad=1
rm -f /tmp/doc_anchors.$$
# The headers say why, not when: no date in them but a study page's name.
for header in $headers; do
  sed -E 's#studies/[0-9]{4}-[0-9]{2}-[0-9]{2}##g' "$header" | grep -nE '\b20[0-9]{2}-[0-9]{2}-[0-9]{2}\b' |
    while IFS=: read -r n _; do echo "FAIL: $header:$n: carries a date (say why, not when)"; done
done | tee /tmp/doc_dates.$$ | head -n 50
[[ -s /tmp/doc_dates.$$ ]] && bad=1
rm -f /tmp/doc_dates.$$
for file in $pages $headers; do
  grep -nE 'SPEC\.md' "$file" | while IFS=: read -r n _; do echo "FAIL: $file:$n: cites SPEC.md, which users do not have"; done
  grep -niE '\b(issue|issues) #?[0-9]+' "$file" | while IFS=: read -r n _; do echo "FAIL: $file:$n: cites an issue by its number"; done
done | tee /tmp/doc_links.$$ | head -n 200
[[ -s /tmp/doc_links.$$ ]] && bad=1
rm -f /tmp/doc_links.$$
((checked > 0)) || fail "no link or path found to check"
((bad == 0)) && echo "PASS: $checked links and paths in $(wc -w <<<"$pages") pages and $(wc -w <<<"$headers") headers, all there"
exit $bad

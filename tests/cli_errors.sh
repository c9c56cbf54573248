#!/usr/bin/env bash
# Bad input to an example gets a clear message and exit code 1 or 2, never a
# crash or a hang; --help exits 0.  Usage: cli_errors.sh EXECUTABLE
set -u
exe=$1
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
expect "1 2" "columns" -- --columns -5
expect "1 2" "radius" -- --radius-mm -0.5
expect "1 2" "backend" -- --backend vulkan
expect "1 2" "stress" -- --stress-mpa abc
expect "1 2" "steps" -- --steps 0
expect "1 2" "not expected|extra|unknown|following argument" -- --no-such-option 3
expect "1 2" "columns" -- --columns
mkdir -p "$work/taken" && touch "$work/taken/file"
expect "1 2" "exists" -- --out taken --steps 10
expect "0" "plate stress" -- --out taken --steps 10 --columns 4 --rows 4 --force
[[ -f "$work/taken/summary.json" ]] || { echo "FAIL: no summary.json after --force"; failures=$((failures + 1)); }

echo "$failures failure(s)"
exit $((failures > 0))

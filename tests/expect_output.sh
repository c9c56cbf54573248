#!/usr/bin/env bash
# Runs a command and passes only if it exits 0 AND its output matches the
# pattern (CTest's PASS_REGULAR_EXPRESSION alone ignores the exit code, so a
# crash after the expected line would pass).  Usage: expect_output.sh REGEX CMD [ARGS...]
set -u
pattern=$1; shift
out=$("$@" 2>&1); code=$?
printf '%s\n' "$out"
if [[ $code -ne 0 ]]; then echo "FAIL: exit code $code"; exit 1; fi
grep -qE -- "$pattern" <<<"$out" || { echo "FAIL: no line matches '$pattern'"; exit 1; }
exit 0

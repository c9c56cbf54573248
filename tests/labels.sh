#!/usr/bin/env bash
# Every label of the suite selects at least one test, and every test carries
# one of them. A Catch2 label whose spec matches no test (a tag renamed or
# misspelt) only warns when the tests are discovered and then selects
# nothing, so "ctest -L physics" would pass having run nothing; a test added
# without a label would be in no selection. Read from the build folder's test
# list, by ctest -N run from a scratch folder that names the build folder as
# its one subdirectory: ctest -N run in the build folder itself rewrites
# Testing/Temporary/LastTest.log, the log of the ctest that runs this test
# (scripts/test.sh reads the skipped tests' reasons from it).
#   Usage: labels.sh CTEST BUILD_DIR LABEL...
set -uo pipefail
ctest=$1 build=$2
shift 2
[[ -f $build/CTestTestfile.cmake ]] || { echo "FAIL: no test list in $build"; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
echo "subdirs(\"$build\")" >"$scratch/CTestTestfile.cmake"
cd "$scratch" || exit 1
count() {  # count ARGS...: how many tests "ctest -N ARGS" lists; empty if ctest failed
  "$ctest" -N "$@" 2>/dev/null | sed -n 's/^Total Tests: \([0-9][0-9]*\)$/\1/p'
}
failures=0
for label in "$@"; do
  n=$(count -L "^$label\$")
  if [[ -z $n ]]; then echo "FAIL: ctest -N -L $label failed"; failures=$((failures + 1))
  elif [[ $n -eq 0 ]]; then echo "FAIL: the label $label selects no test"; failures=$((failures + 1))
  else echo "ok:   $label selects $n tests"; fi
done
all="^($(IFS='|'; echo "$*"))\$"
n=$(count -LE "$all")
if [[ -z $n ]]; then echo "FAIL: ctest -N -LE '$all' failed"; failures=$((failures + 1))
elif [[ $n -ne 0 ]]; then
  echo "FAIL: $n tests carry none of the labels $* (an unbuilt test binary shows as *_NOT_BUILT):"
  "$ctest" -N -LE "$all" 2>/dev/null | grep -E '^ *Test +#'
  failures=$((failures + 1))
else echo "ok:   every test carries one of these labels"; fi
exit $((failures > 0))

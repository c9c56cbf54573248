#!/usr/bin/env bash
# Builds a libFuzzer target with clang (AddressSanitizer and
# UndefinedBehaviorSanitizer on) and runs it for a while from its seed corpus.
# Any crash, sanitizer report or leak fails. Skipped (77) without clang's
# fuzzer runtime. docs/fuzzing.md says how to run longer.
#   Usage: fuzz.sh SOURCE_DIR BUILD_DIR TARGET SECONDS    (TARGET: gradation or config)
set -uo pipefail
src=$1 build=$2 target=$3 seconds=$4
mkdir -p "$build"
exe="$build/fuzz_$target"
if ! command -v clang++ >/dev/null; then echo "SKIPPED: no clang++"; exit 77; fi
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I"$src/include" -I/usr/include/eigen3 "$src/fuzz/fuzz_$target.cpp" -o "$exe" >"$exe.log" 2>&1 ||
  { if grep -q "libclang_rt.fuzzer\|fuzzer" "$exe.log" && ! grep -q "error:" "$exe.log"; then
      echo "SKIPPED: clang has no libFuzzer runtime (libclang-rt-dev)"; cat "$exe.log"; exit 77; fi
    cat "$exe.log"; echo "FAIL: building fuzz_$target"; exit 1; }
corpus="$build/corpus_$target"
mkdir -p "$corpus"
(cd "$build" && "$exe" -max_total_time="$seconds" -print_final_stats=1 "$corpus" "$src/fuzz/corpus/$target") >"$exe.run.log" 2>&1
code=$?
tail -n 12 "$exe.run.log"
[[ $code -eq 0 ]] || { echo "FAIL: fuzz_$target found a problem (see above; the input is saved in $build)"; exit 1; }
echo "PASS: fuzz_$target ran $seconds s without a finding"

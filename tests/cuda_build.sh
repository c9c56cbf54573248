#!/usr/bin/env bash
# The CUDA build, checked on every run of the suite: Kokkos with CUDA for
# sm_90 (scripts/setup_cuda.sh, built once and cached), then vrut-rutting
# and the block benchmark compiled and linked with nvcc_wrapper. Between them
# they hold, in 2D and in 3D, the kernels of every law the rutting test uses
# (Burger's with film and bond, the damped linear stones and walls, their
# choice), of the plain linear law, of the rigid bodies, the servo and load
# controls, and the periodic 3D cell list. Compiling needs no GPU. Without
# nvcc the test is skipped (77).
#
# The core benchmark and the rigid-body tests were compiled here too until
# 2026-12-02: they add no kernel the two above lack (the bonded linear law is
# the rutting law's bond slot), and with nvcc they took 400 of the test's
# 660 CPU seconds, which the suite's 15 minutes on 2 cores cannot spare.
#
# The test binary is compiled too, and run, where a GPU is found
# (nvidia-smi), or compiled only when VRUT_CUDA_TESTS=1: with nvcc it takes
# twice as long as the rest together (six minutes on 2 cores), which the
# suite cannot afford on a machine that could not run it anyway.
#   Usage: cuda_build.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
src=$1 build=$2
prefix=$("$src/scripts/setup_cuda.sh" | tail -n 1); code=${PIPESTATUS[0]}
if [[ $code -eq 77 ]]; then echo "SKIPPED: no nvcc on this machine, so no CUDA build"; exit 77; fi
if [[ $code -ne 0 ]]; then echo "FAIL: Kokkos with CUDA did not build"; exit 1; fi
# The host side at -O0: this test compiles and links, it does not run, and
# unoptimised host code compiles much faster. The device code is optimised
# as ever (ptxas), so the sm_90 kernels checked below are the real ones.
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS=-O0 -DKokkos_ROOT="$prefix" \
  -DCMAKE_CXX_COMPILER="$prefix/bin/nvcc_wrapper" -DVRUT_PYTHON=OFF >"$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; echo "FAIL: configuring the CUDA build"; exit 1; }
gpu=0
nvidia-smi -L 2>/dev/null | grep -q '^GPU' && gpu=1
targets=(vrut-rutting vrut-bench-block)
exes=(examples/vrut-rutting benchmarks/vrut-bench-block)
if [[ $gpu -eq 1 || ${VRUT_CUDA_TESTS:-0} == 1 ]]; then targets+=(vrut-tests) exes+=(tests/vrut-tests); fi
# Eigen's headers warn under nvcc; only errors matter here.
cmake --build "$build" --target "${targets[@]}" 2>&1 | grep -E "error|\[[0-9]+/[0-9]+\]"
[[ ${PIPESTATUS[0]} -eq 0 ]] || { echo "FAIL: the CUDA build of vrut"; exit 1; }
# The device code really is there: vrut's contact-force kernel (core/force_pass.hpp),
# compiled for sm_90, in 2D and in 3D (Dim2, Dim3 in its mangled name), in each
# binary's fat binary.
for exe in "${exes[@]}"; do
  objcopy -O binary --only-section=.nv_fatbin "$build/$exe" "$build/fatbin.bin" &&
    strings "$build/fatbin.bin" >"$build/fatbin.txt" && grep -q sm_90 "$build/fatbin.txt" &&
    grep -q 'vrut14contact_forces.*Dim2' "$build/fatbin.txt" &&
    grep -q 'vrut14contact_forces.*Dim3' "$build/fatbin.txt" ||
    { echo "FAIL: no sm_90 device code for vrut's 2D and 3D kernels in $exe"; exit 1; }
done
echo "PASS: ${targets[*]} compile and link with CUDA for sm_90"
if [[ $gpu -eq 1 ]]; then
  "$build/tests/vrut-tests" || { echo "FAIL: vrut-tests on the GPU"; exit 1; }
  echo "PASS: vrut-tests on the GPU"
elif [[ ! " ${targets[*]} " == *" vrut-tests "* ]]; then
  echo "(no GPU here: vrut-tests not compiled for CUDA; VRUT_CUDA_TESTS=1 compiles it)"
fi

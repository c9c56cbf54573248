#!/usr/bin/env bash
# Builds Debian's Kokkos 3.4.01 with CUDA (and Serial) for NVIDIA Hopper
# (H100/H200, sm_90) with the CUDA toolkit found on PATH or in
# /usr/local/cuda, and prints the install prefix on its last line of stdout.
# Kokkos 3.4 predates CUDA 13 and Hopper; four small fixes, each explained
# below, make it build. Exits 77 when no nvcc is found.
#   VRUT_CACHE=DIR   where it is kept (default ${XDG_CACHE_HOME:-$HOME/.cache}/vrut)
#   VRUT_CUDA_OPENMP=1  the host side on OpenMP too (Serial, OpenMP and CUDA):
#                    the specimens' placement and compaction then use the host's
#                    cores beside the GPU, as on a CPU build (a GPU machine has
#                    many). Kept apart, in a prefix ending in -openmp.
set -euo pipefail

say() { echo "[vrut setup-cuda] $*" >&2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export PATH="$PATH:/usr/local/cuda/bin"
if ! command -v nvcc >/dev/null; then say "no nvcc found (PATH, /usr/local/cuda/bin)"; exit 77; fi
cuda_version=$(nvcc --version | sed -n 's/.*release \([0-9.]*\),.*/\1/p')

cache=${VRUT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/vrut}
host_openmp=()
suffix=""
if [[ ${VRUT_CUDA_OPENMP:-0} == 1 ]]; then host_openmp=(-DKokkos_ENABLE_OPENMP=ON) suffix="-openmp"; fi
prefix="$cache/kokkos-3.4.01-cuda${cuda_version}-sm90${suffix}"
if [[ -f "$prefix/.complete" ]]; then echo "$prefix"; exit 0; fi

say "building Kokkos 3.4.01 (CUDA $cuda_version for sm_90 + Serial${suffix:+ + OpenMP}) into $prefix"
work="$cache/work-cuda${suffix}"; rm -rf "$work"
# shellcheck source=kokkos_source.sh
source "$here/scripts/kokkos_source.sh"
src=$(kokkos_source "$work") || exit 1

# 1. Kokkos_Cuda_Half.hpp passes a half_t where CUDA 13's conversion functions
#    take a __half (and calls __half2double, which CUDA 13 lacks): convert
#    explicitly, as the rest of that file does.
# 2. CUDA 13's cudaMemPrefetchAsync takes a cudaMemLocation and flags instead of
#    a device number.
# 3. nvcc_wrapper defaults to sm_35, which CUDA 13 no longer compiles for.
# 4. Kokkos 3.4 knows no Hopper: its AMPERE80 option is pointed at sm_90.
half="$src/core/src/Cuda/Kokkos_Cuda_Half.hpp"
perl -pi -e 's/__half2(float|short_rz|ushort_rz|int_rz|uint_rz|ll_rz|ull_rz)\(val\)/__half2$1(half_t::impl_type(val))/g;
             s/__half2double\(val\)/static_cast<double>(__half2float(half_t::impl_type(val)))/g' "$half"
grep -q '__half2int_rz(half_t::impl_type(val))' "$half" || { say "fix 1 did not apply"; exit 1; }
perl -0pi -e 's/CUDA_SAFE_CALL\(cudaMemPrefetchAsync\(ptr, bytes, space\.cuda_device\(\),\s*space\.cuda_stream\(\)\)\);/{
#if CUDART_VERSION >= 13000
      cudaMemLocation location{};
      location.type = cudaMemLocationTypeDevice;
      location.id   = space.cuda_device();
      CUDA_SAFE_CALL(cudaMemPrefetchAsync(ptr, bytes, location, 0, space.cuda_stream()));
#else
      CUDA_SAFE_CALL(cudaMemPrefetchAsync(ptr, bytes, space.cuda_device(), space.cuda_stream()));
#endif
    }/' "$src/core/src/Cuda/Kokkos_CudaSpace.cpp"
grep -q cudaMemLocationTypeDevice "$src/core/src/Cuda/Kokkos_CudaSpace.cpp" || { say "fix 2 did not apply"; exit 1; }
sed -i 's/^default_arch="sm_35"/default_arch="sm_90"/' "$src/bin/nvcc_wrapper"
grep -q '^default_arch="sm_90"' "$src/bin/nvcc_wrapper" || { say "fix 3 did not apply"; exit 1; }
sed -i 's/CHECK_CUDA_ARCH(AMPERE80  sm_80)/CHECK_CUDA_ARCH(AMPERE80  sm_90)/' "$src/cmake/kokkos_arch.cmake"
grep -q 'CHECK_CUDA_ARCH(AMPERE80  sm_90)' "$src/cmake/kokkos_arch.cmake" || { say "fix 4 did not apply"; exit 1; }

kokkos_build "$src" "$work" "$prefix" "$cache/kokkos-cuda${suffix}-build.log" -DCMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper" \
  -DKokkos_ENABLE_SERIAL=ON "${host_openmp[@]}" -DKokkos_ENABLE_CUDA=ON -DKokkos_ENABLE_CUDA_LAMBDA=ON \
  -DKokkos_ARCH_AMPERE80=ON || exit 1
say "Kokkos (CUDA) installed in $prefix"
echo "$prefix"

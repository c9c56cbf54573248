#!/usr/bin/env bash
# Installs what vrut needs on a Debian bookworm machine and prints the Kokkos
# install prefix on its last line of stdout (everything else goes to stderr).
#
#   VRUT_KOKKOS_ROOT=DIR   use the Kokkos installed under DIR (must have Serial
#                          and OpenMP; CUDA too if you want the GPU backend)
#   VRUT_CACHE=DIR         where a Kokkos built here is kept (default
#                          ${XDG_CACHE_HOME:-$HOME/.cache}/vrut)
set -euo pipefail

say() { echo "[vrut setup] $*" >&2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# --- Debian packages -------------------------------------------------------
packages=(g++ cmake ninja-build make pkg-config libeigen3-dev libboost-dev catch2 libcli11-dev
          libbenchmark-dev nlohmann-json3-dev gnuplot-nox libcairo2-dev clang libclang-rt-14-dev
          libopenmpi-dev openmpi-bin libopencv-imgproc-dev libopencv-imgcodecs-dev libqhull-dev libccd-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-jsonschema doxygen)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -ne 0 ]]; then
    say "missing Debian packages: ${missing[*]}"
    say "install them with: sudo apt-get install ${missing[*]}"
    exit 1
  fi
  say "installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >&2 || say "apt-get update failed; trying the install anyway"
  apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
fi

# --- Kokkos -----------------------------------------------------------------
# An installed Kokkos is used when it has the backends we need.
has_backends() {  # $1 = prefix
  local probe; probe=$(mktemp -d)
  cat >"$probe/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.16)
project(probe CXX)
find_package(Kokkos 3.4 REQUIRED)
kokkos_check(DEVICES Serial OpenMP)
CM
  if cmake -S "$probe" -B "$probe/b" -DCMAKE_PREFIX_PATH="$1" >/dev/null 2>&1; then
    rm -rf "$probe"; return 0
  fi
  rm -rf "$probe"; return 1
}

if [[ -n "${VRUT_KOKKOS_ROOT:-}" ]]; then
  has_backends "$VRUT_KOKKOS_ROOT" || { say "VRUT_KOKKOS_ROOT=$VRUT_KOKKOS_ROOT has no Kokkos >= 3.4 with Serial and OpenMP"; exit 1; }
  echo "$VRUT_KOKKOS_ROOT"; exit 0
fi

cache=${VRUT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/vrut}
prefix="$cache/kokkos-3.4.01-serial-openmp"
if [[ -f "$prefix/.complete" ]] && has_backends "$prefix"; then
  echo "$prefix"; exit 0
fi

say "building Kokkos 3.4.01 (Serial + OpenMP) into $prefix"
work="$cache/work"; rm -rf "$work"
# shellcheck source=kokkos_source.sh
source "$here/scripts/kokkos_source.sh"
src=$(kokkos_source "$work") || exit 1

kokkos_build "$src" "$work" "$prefix" "$cache/kokkos-build.log" \
  -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON -DCMAKE_POSITION_INDEPENDENT_CODE=ON || exit 1
say "Kokkos installed in $prefix"
echo "$prefix"

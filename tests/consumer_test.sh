#!/usr/bin/env bash
# Installs vrut from the build folder into a scratch prefix, then builds and
# runs tests/consumer against it with find_package(vrut).
# Usage: consumer_test.sh BUILD_DIR SOURCE_DIR KOKKOS_PREFIX
set -euo pipefail
build=$1 source=$2 kokkos=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$source/tests/consumer" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix;$kokkos"
cmake --build "$work/build"
"$work/build/consumer"

#!/usr/bin/env bash
# Installs a configured build (default: build) into a temporary prefix, then builds the consumer
# project examples/consumer against it twice, through find_package(sphereset) and through
# pkg-config, runs both on examples/spot.obj and checks that they write the same spheres as the
# installed `sphereset fit` with the same options.
#   bash scripts/check_install.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-${BUILD_DIR:-build}}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
jobs=$(( $(nproc) < 2 ? $(nproc) : 2 ))

echo "== install $build into a temporary prefix"
cmake --install "$build" --prefix "$prefix" > "$tmp/install.log"
test -x "$prefix/bin/sphereset"
pc=$(find "$prefix" -name sphereset.pc)
config=$(find "$prefix" -name spheresetConfig.cmake)
test -n "$pc" && test -n "$config"

echo "== consumer through find_package(sphereset)"
cmake -S examples/consumer -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$tmp/configure.log"
cmake --build "$tmp/consumer" -j "$jobs" > "$tmp/build.log"
"$tmp/consumer/consumer" examples/spot.obj 8 "$tmp/cmake_8.txt"

echo "== consumer through pkg-config"
export PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
# shellcheck disable=SC2046  # pkg-config prints several words on purpose
# (the rpath finds a shared libsphereset in the prefix; a static one needs none)
g++ -std=c++20 -O2 examples/consumer/main.cpp -o "$tmp/consumer_pc" \
  $(pkg-config --cflags --libs sphereset) -Wl,-rpath,"$(pkg-config --variable=libdir sphereset)"
"$tmp/consumer_pc" examples/spot.obj 8 "$tmp/pkgconfig_8.txt"

echo "== same spheres as the installed command"
"$prefix/bin/sphereset" fit examples/spot.obj -n 8 --quality fast -q -o "$tmp/cli_8.txt"
cmp "$tmp/cmake_8.txt" "$tmp/cli_8.txt"
cmp "$tmp/pkgconfig_8.txt" "$tmp/cli_8.txt"
echo "install check passed: $(find "$prefix" -type f | wc -l) files installed"

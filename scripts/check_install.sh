#!/usr/bin/env bash
# Installs a configured build (default: build) into a temporary prefix, then builds the consumer
# project examples/consumer (the core library alone) against it twice, through
# find_package(sphereset COMPONENTS core) and through pkg-config, runs both on the bundled
# examples/spot.obj written as OFF, and checks that they find the same spheres as the installed
# `sphereset fit` with the same options.
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

# The consumer reads OFF itself (the core has no file formats): spot's positions and faces.
python3 - examples/spot.obj "$tmp/spot.off" << 'PY'
import sys
v, f = [], []
for line in open(sys.argv[1]):
    w = line.split()
    if w and w[0] == "v":
        v.append(w[1:4])
    elif w and w[0] == "f":
        f.append([int(c.split("/")[0]) - 1 for c in w[1:4]])
with open(sys.argv[2], "w") as out:
    out.write("OFF\n%d %d 0\n" % (len(v), len(f)))
    out.writelines(" ".join(p) + "\n" for p in v)
    out.writelines("3 %d %d %d\n" % tuple(t) for t in f)
PY

echo "== consumer (core alone) through find_package(sphereset COMPONENTS core)"
cmake -S examples/consumer -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$tmp/configure.log"
cmake --build "$tmp/consumer" -j "$jobs" > "$tmp/build.log"
"$tmp/consumer/consumer" "$tmp/spot.off" 8 "$tmp/cmake_8.txt"
# It links the core and nothing of the file formats.
if ldd "$tmp/consumer/consumer" | grep -Eq 'assimp|yaml-cpp|urdfdom|png'; then
  echo "the core consumer links a file-format library:" >&2
  ldd "$tmp/consumer/consumer" >&2
  exit 1
fi

echo "== consumer through pkg-config"
export PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
# shellcheck disable=SC2046  # pkg-config prints several words on purpose
# (the rpath finds shared sphereset libraries in the prefix; static ones need none)
g++ -std=c++20 -O2 examples/consumer/main.cpp -o "$tmp/consumer_pc" \
  $(pkg-config --cflags --libs sphereset) -Wl,-rpath,"$(pkg-config --variable=libdir sphereset)"
"$tmp/consumer_pc" "$tmp/spot.off" 8 "$tmp/pkgconfig_8.txt"

echo "== same spheres as the installed command"
"$prefix/bin/sphereset" fit "$tmp/spot.off" -n 8 --quality fast -q -o "$tmp/cli_8.json"
python3 - "$tmp/cli_8.json" > "$tmp/cli_8.txt" << 'PY'
import json, sys
for s in json.load(open(sys.argv[1]))["spheres"]:
    print("%.17g %.17g %.17g %.17g" % (*s["center"], s["radius"]))
PY
cmp "$tmp/cmake_8.txt" "$tmp/cli_8.txt"
cmp "$tmp/pkgconfig_8.txt" "$tmp/cli_8.txt"
echo "install check passed: $(find "$prefix" -type f | wc -l) files installed"

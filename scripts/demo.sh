#!/usr/bin/env bash
# The main job on the bundled example (Keenan Crane's "spot", CC0): diagnose the mesh and
# measure a sphere set against it. Installs and builds first when needed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if [ ! -x build/apps/sphereset ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j "$(nproc)" --target sphereset_cli
fi
./build/apps/sphereset check examples/spot.obj
./build/apps/sphereset eval examples/spot.obj examples/spot_bounding_sphere.txt

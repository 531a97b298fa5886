#!/usr/bin/env bash
# The main job on the bundled example (Keenan Crane's "spot", CC0): diagnose the mesh, fit 32
# spheres, and measure them. Installs and builds first when needed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if [ ! -x build/apps/sphereset ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j "$(nproc)" --target sphereset_cli
fi
mkdir -p out
./build/apps/sphereset check examples/spot.obj
./build/apps/sphereset fit examples/spot.obj -n 32 -o out/spot_32.json
./build/apps/sphereset eval examples/spot.obj out/spot_32.json
echo "For comparison, one sphere around the bounding box:"
./build/apps/sphereset eval examples/spot.obj examples/spot_bounding_sphere.txt

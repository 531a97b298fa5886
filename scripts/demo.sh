#!/usr/bin/env bash
# The main job on the bundled example (Keenan Crane's "spot", CC0): diagnose the mesh, fit 32
# spheres, measure them and draw them. Installs and builds first when needed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh demo  # only the command's dependencies; the test command adds the rest
# The command alone: no tests, benchmarks or Python module to configure (their packages are
# installed by scripts/build_and_test.sh, which turns them on in the same build folder).
[ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release \
  -DSPHERESET_BUILD_TESTS=OFF -DSPHERESET_BUILD_BENCH=OFF -DSPHERESET_BUILD_PYTHON=OFF >/dev/null
cmake --build build -j "$(nproc)" --target sphereset_cli
mkdir -p out
./build/apps/sphereset check examples/spot.obj
./build/apps/sphereset fit examples/spot.obj -n 32 -o out/spot_32.json
./build/apps/sphereset eval examples/spot.obj out/spot_32.json
echo "For comparison, one sphere around the bounding box:"
./build/apps/sphereset eval examples/spot.obj examples/spot_bounding_sphere.txt
./build/apps/sphereset export out/spot_32.json -o out/spot_32_spheres.ply
./build/apps/sphereset render examples/spot.obj out/spot_32.json -o out/spot_32.png
echo "Picture: out/spot_32.png (front, side, top, three-quarter); spheres as a mesh: out/spot_32_spheres.ply"
echo "To check and edit the set in the browser: ./build/apps/sphereset view examples/spot.obj out/spot_32.json"

#!/usr/bin/env bash
# The benchmark suite (see bench/suite.py): builds the command if needed, then runs every
# method over the meshes and writes bench/results/suite/{suite.csv, er.png, time.png,
# proximity.png, shadow.png}. Installs what it needs (scripts/setup.sh) and uses Debian's
# python3 with its python3-matplotlib.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh >/dev/null
[ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target sphereset_cli >/dev/null
exec /usr/bin/python3 bench/suite.py "$@"

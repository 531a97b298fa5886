#!/usr/bin/env bash
# Installs the dependencies, builds from scratch and runs every test. This is the README's
# test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=${BUILD_DIR:-build}
# Tests and the Python module on (a build folder configured by the demo has them off); the
# Python module's default depends on the sanitizer options, so its cached value is dropped and
# recomputed. The view's page is required (its browser tests run here). The benchmark programs
# are not part of the tests: off here (bench/*.sh turn them on; CI builds them after the tests).
# Later arguments ("$@") override these.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSPHERESET_BUILD_TESTS=ON \
  -DSPHERESET_BUILD_BENCH=OFF -DSPHERESET_VIEW_PAGE=ON -DSPHERESET_WITH_MUJOCO=ON \
  -USPHERESET_BUILD_PYTHON "$@"
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure

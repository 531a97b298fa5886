#!/usr/bin/env bash
# Writes python/sphereset/_sphereset.pyi, the stubs of the extension module, with mypy's stubgen
# (Debian package mypy) from the module built in BUILD_DIR (default build). The tests check that
# the file equals stubgen's output (python/tests/test_stubs.py).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
PYTHONPATH="$build/python" stubgen -p sphereset._sphereset -o "$out" > /dev/null
cp "$out/sphereset/_sphereset.pyi" python/sphereset/_sphereset.pyi
echo "wrote python/sphereset/_sphereset.pyi"

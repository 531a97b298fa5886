#!/usr/bin/env bash
# Writes python/sphereset/_sphereset.pyi, the stubs of the extension module, with mypy's stubgen
# (Debian package mypy), and python/sphereset/_results.py, the result classes made from the
# library's result field lists (scripts/gen_results.py), from the module built in BUILD_DIR
# (default build). The tests check that both files equal what this writes
# (python/tests/test_stubs.py).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
PYTHONPATH="$build/python" /usr/bin/python3 scripts/gen_results.py python/sphereset/_results.py
cp python/sphereset/_results.py "$build/python/sphereset/_results.py"
echo "wrote python/sphereset/_results.py"
PYTHONPATH="$build/python" stubgen -p sphereset._sphereset -o "$out" > /dev/null
cp "$out/sphereset/_sphereset.pyi" python/sphereset/_sphereset.pyi
echo "wrote python/sphereset/_sphereset.pyi"

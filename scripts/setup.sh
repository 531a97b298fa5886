#!/usr/bin/env bash
# Installs the dependencies of sphereset from Debian 12 packages. Idempotent: packages already
# present are left as they are.
#   bash scripts/setup.sh        everything: build, tests, Python module, benchmarks, fuzzing,
#                                the view's page (Node.js, npm) and its browser tests (Chromium)
#   bash scripts/setup.sh demo   only what the command needs (scripts/demo.sh)
set -euo pipefail

# The sphereset command: the library's dependencies.
demo_packages=(
  build-essential cmake pkg-config
  libassimp-dev        # mesh import (OBJ, PLY, STL, OFF, DAE, glTF/GLB)
  libeigen3-dev        # small dense linear algebra
  libtbb-dev           # parallel loops
  libcli11-dev         # command-line parsing
  nlohmann-json3-dev   # JSON input and output
  libyaml-cpp-dev      # YAML sphere files (cuRobo)
  liburdfdom-dev       # robot descriptions (URDF parser)
  libmujoco-dev        # MJCF robots in and out, read and checked by MuJoCo itself (Apache-2.0)
  libtinyxml-dev       # URDF elements read and rewritten (the XML library urdfdom uses)
  libnlopt-cxx-dev     # derivative-free and gradient optimisers
  coinor-libcbc-dev    # integer programs: the best preset's selection among its restarts' spheres
  libpng-dev           # PNG pictures
  libcgal-dev          # repair: corefinement and alpha wrapping, GPL, see README
  libgmp-dev           # exact arithmetic linked by CGAL's CMake target (CGAL::CGAL)
  libmpfr-dev          # exact arithmetic linked by CGAL's CMake target (CGAL::CGAL)
)
# Tests, the Python module, benchmarks and fuzzing: what scripts/build_and_test.sh and CI add.
test_packages=(
  time                 # wall time and peak memory in the benchmark scripts
  ccache               # compiler cache (used by CMake when present)
  libgtest-dev         # unit tests
  libcpp-httplib-dev   # tests: an HTTP client for the server of `sphereset view`
  libbenchmark-dev     # micro-benchmarks
  libfcl-dev           # tests: FCL, an independent collision check of the robot spheres
  clang                # fuzzing (fuzz/run.sh): libFuzzer needs clang
  libclang-rt-14-dev   # libFuzzer and the sanitizer runtimes for clang 14
  python3              # benchmark scripts (CSV tables)
  python3-matplotlib   # benchmark plots (PNG)
  python3-dev          # Python module: headers of the interpreter it is built for
  pybind11-dev         # Python module: C++ bindings
  python3-numpy        # Python module: arrays in and out
  python3-pytest       # Python module: its tests (python/tests, run by CTest)
  python3-yaml         # tests: an independent reader of the robot YAML files
  mypy                 # Python module: stubgen, the stubs of the extension (checked by a test)
  python3-distributed  # Python module: the batch on a Dask cluster (sphereset.batch)
  python3-venv         # Python module: `pip install .` into a virtual environment
  python3-pip          # Python module: `pip install .`
  chromium             # tests: the view's page in a real browser, headless (tests/browser)
  locales              # tests: a comma-decimal locale (de_DE.UTF-8) for the number readers
)
# The view's page is built with Node.js and npm (web/, three.js pinned by web/package-lock.json).
# A machine that already has them keeps its own (Debian's npm conflicts with a Node.js installed
# from elsewhere); Debian's are installed only where `node` or `npm` is missing.
node_packages=(nodejs npm)

case "${1:-all}" in
  demo) packages=("${demo_packages[@]}") ;;
  all)
    packages=("${demo_packages[@]}" "${test_packages[@]}")
    if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
      packages+=("${node_packages[@]}")
    fi
    ;;
  *) echo "usage: bash scripts/setup.sh [demo]" >&2; exit 2 ;;
esac

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# The tests read numbers under a comma-decimal locale: de_DE.UTF-8 is made once (localedef).
comma_locale() {
  [ "${1:-all}" = all ] || return 0
  locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$' && return 0
  echo "setup: making the locale de_DE.UTF-8 (tests)"
  $SUDO localedef -i de_DE -c -f UTF-8 de_DE.UTF-8 || echo "setup: could not make de_DE.UTF-8"
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  comma_locale "${1:-all}"
  exit 0
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
comma_locale "${1:-all}"

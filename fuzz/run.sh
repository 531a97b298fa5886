#!/usr/bin/env bash
# Builds the libFuzzer targets with clang in their own build directory and runs each for a
# bounded time on a seed corpus (fuzz/corpus/<target>/ and the matching files of tests/data),
# after replaying the inputs that once crashed (fuzz/regressions/<target>/). Fails when any
# target crashes, leaks, times out or breaks an invariant; the input is kept in
# <build>/crashes/. Environment: FUZZ_SECONDS (per target, default 6), FUZZ_BUILD_DIR
# (default build-fuzz), FUZZ_TARGETS (default all), FUZZ_SEED (default 1: the same mutations on
# every run, so that CI's short run gives the same verdict each time; 0 draws a new seed, for
# longer runs that look for new inputs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
root=$PWD
build=${FUZZ_BUILD_DIR:-build-fuzz}
seconds=${FUZZ_SECONDS:-6}
seed=${FUZZ_SEED:-1}
targets=${FUZZ_TARGETS:-"off ply stl obj spheres_txt spheres_json spheres_sph spheres_yaml tree repair urdf mjcf animation trajectory point_cloud view_request planner"}

launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
echo "== fuzz: configure and build ($build, clang)"
mkdir -p "$build"
CC=clang CXX=clang++ cmake -S . -B "$build" -DSPHERESET_BUILD_FUZZERS=ON \
  -DSPHERESET_BUILD_TESTS=OFF -DSPHERESET_BUILD_BENCH=OFF -DSPHERESET_UNITY=OFF -DSPHERESET_PCH=OFF \
  -DSPHERESET_VIEW_PAGE=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" "${launcher[@]}" > "$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)" --target sphereset_fuzzers

# Seeds from tests/data by extension, per target (the tree target takes a format byte first).
seed_data() {
  local target=$1 dir=$2 f
  case $target in
    stl) cp "$root"/tests/data/*.stl "$dir"/ 2> /dev/null || true ;;
    spheres_yaml) cp "$root"/tests/data/*.yml "$dir"/ 2> /dev/null || true ;;
    mjcf) cp "$root"/tests/data/robot/mjcf/*.xml "$root"/tests/hostile/mjcf_*.xml "$dir"/ ;;
    tree)
      for f in "$root"/tests/data/*.yml; do
        [ -e "$f" ] && { printf '\003'; cat "$f"; } > "$dir/$(basename "$f").tree"
      done ;;
  esac
}

mkdir -p "$build/crashes"
# Leaks inside assimp (malformed OBJ files) and urdfdom (malformed URDFs) are theirs, not ours:
# suppressed, see the file.
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$root/fuzz/lsan_assimp.supp"
failed=()
for t in $targets; do
  bin="$build/fuzz/fuzz_$t"
  corpus="$build/corpus/$t"
  mkdir -p "$corpus"
  cp "$root/fuzz/corpus/$t"/* "$corpus"/
  seed_data "$t" "$corpus"
  opts=(-timeout=10 -rss_limit_mb=4096 -malloc_limit_mb=3072 "-artifact_prefix=$build/crashes/$t-"
    "-seed=$seed")
  log="$build/fuzz_$t.log"
  if [ -d "$root/fuzz/regressions/$t" ]; then
    if ! "$bin" "${opts[@]}" "$root/fuzz/regressions/$t"/* > "$log" 2>&1; then
      echo "fuzz_$t: a regression input fails again"; tail -n 40 "$log"; failed+=("$t"); continue
    fi
  fi
  if "$bin" "${opts[@]}" -max_total_time="$seconds" -print_final_stats=1 "$corpus" > "$log" 2>&1
  then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    echo "fuzz_$t: ${seconds}s, ${runs:-?} runs, no crash ($(ls "$corpus" | wc -l) inputs in corpus)"
  else
    echo "fuzz_$t: CRASH (input in $build/crashes/)"; tail -n 40 "$log"; failed+=("$t")
  fi
done
if ((${#failed[@]})); then
  echo "fuzz: failed: ${failed[*]}"
  exit 1
fi
echo "fuzz: all targets ran without a crash"

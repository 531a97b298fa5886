# Shared start of the bench/*_table.sh scripts (sourced): work from the repository root with
# the command-line tool built and bench/results present; `meshes` takes the script's
# arguments, or the defaults given to bench_meshes when there are none.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
[ -x build/apps/sphereset ] || cmake --build build --target sphereset_cli
mkdir -p bench/results
# bench_program NAME...: the benchmark programs built (the README's test command leaves them
# off; this turns SPHERESET_BUILD_BENCH on in build/ when one is missing).
bench_program() {
  local name
  for name in "$@"; do
    if [ ! -x "build/bench/$name" ]; then
      cmake -S . -B build -DSPHERESET_BUILD_BENCH=ON > /dev/null
      cmake --build build -j "$(nproc)" --target "$name"
    fi
  done
}
# skip_without_shared NAME: `shared` (SHARED, default ../shared), or exit 0 saying NAME was
# skipped when it has no meshes (the benchmarks on ../shared's meshes run only where it is).
skip_without_shared() {
  shared=${SHARED:-../shared}
  if [ ! -d "$shared/meshes" ]; then
    echo "$1: skipped, $shared/meshes is absent" >&2
    exit 0
  fi
}
# The page's packages (puppeteer-core) and Chromium, for the view benchmarks: sets `modules`,
# or exits saying how to get them.
require_view_page() {
  modules=$PWD/build/web/npm/node_modules
  if [ ! -d "$modules/puppeteer-core" ] || ! command -v chromium > /dev/null; then
    echo "$1: needs the page's packages ($modules) and Chromium:" \
      "bash scripts/build_and_test.sh" >&2
    exit 1
  fi
}
bench_meshes() {
  if [ ${#args[@]} -gt 0 ]; then meshes=("${args[@]}"); else meshes=("$@"); fi
}
# link_closed_meshes MESH_DIR DEST: links every mesh under MESH_DIR that is a closed solid
# as loaded (`sphereset check --repair off` exits 0) into DEST with the same layout; sets
# `count` to how many.
link_closed_meshes() {
  local mesh_dir=$1 dest=$2 mesh rel
  mkdir -p "$dest"
  count=0
  while IFS= read -r -d '' mesh; do
    rel=${mesh#"$mesh_dir"/}
    if build/apps/sphereset check "$mesh" --repair off >/dev/null 2>&1; then
      mkdir -p "$dest/$(dirname "$rel")"
      ln -s "$(realpath "$mesh")" "$dest/$rel"
      count=$((count + 1))
    fi
  done < <(find "$mesh_dir" -type f ! -name '*.tsv' ! -name '*.md' -print0 | sort -z)
  echo "$count closed meshes under $mesh_dir" >&2
}

# wall_seconds OUT CMD...: runs CMD with its stdout into OUT (/dev/null to drop it) and its
# stderr dropped, fails when CMD fails, and prints its wall-clock seconds.
wall_seconds() {
  /usr/bin/python3 -c 'import subprocess, sys, time
t = time.monotonic()
with open(sys.argv[1], "w") as out:
    subprocess.run(sys.argv[2:], stdout=out, stderr=subprocess.DEVNULL, check=True)
print(round(time.monotonic() - t, 3))' "$@"
}
# kinova_robot: sets `root` and `urdf`, the Kinova Gen3 of $shared/robots (after
# skip_without_shared), for the scripts that fit the robot.
kinova_robot() {
  root=$shared/robots/kinova_gen3
  urdf=$root/kortex_description/arms/gen3/7dof/urdf/GEN3-7DOF-VISION_ARM_URDF_V12.urdf
}

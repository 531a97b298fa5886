#!/usr/bin/env bash
# Tightness and time of the fit against a baseline commit, side by side in one run: for each
# mesh, n and seed, `sphereset fit --json` of the baseline and of this build (alternating, so
# that both see the same machine load), E_r after the bound, the clustering's own E_r (before
# the bound), wall time, the seconds after the clustering (seconds.bounding), the peak resident
# memory and whether the fit's certificates hold, into
# bench/results/tightness.csv; then the summary of bench/tightness_summary.py (per mesh and
# overall geometric means of the ratios, the bound overhead) into bench/results/tightness.txt.
#   bash bench/tightness.sh [MESH ...]        (default: the 12 closed meshes of ../shared/meshes)
#   BASE=REF          the baseline commit (default: the fit before the coverage refinement)
#   N_LIST="16 32"    SEEDS="1 2"    VARIANTS="base:default new:default new:fast"
#   QUICK=1           spot, fandisk, fertility and fr3_link1 at n = 16 and 32, seed 1
# A variant is BUILD:QUALITY, BUILD being `base` (the baseline) or `new` (this build).
set -euo pipefail
args=("$@")
source "$(dirname "$0")/common.sh"
skip_without_shared tightness
m=$shared/meshes
if [ -n "${QUICK:-}" ]; then
  bench_meshes examples/spot.obj $m/cad/fandisk.obj $m/organic/fertility.off \
    $m/robot/fr3_link1_collision.stl
  n_list=${N_LIST:-16 32} seeds=${SEEDS:-1}
else
  bench_meshes $m/organic/spot.obj $m/organic/decimated-knight.off $m/organic/fertility.off \
    $m/organic/bunny_hr_oded.obj $m/organic/armadillo_libigl.obj $m/big/dragon_vrip_bin.ply \
    $m/cad/fandisk.obj $m/cad/plate_holes_trimesh.stl $m/cad/rocker-arm.obj \
    $m/robot/fr3_link1_collision.stl $m/robot/ur5_forearm_visual.dae \
    $m/robot/ur5_upperarm_collision.stl
  n_list=${N_LIST:-16 32 64 128} seeds=${SEEDS:-1 2 3}
fi
variants=${VARIANTS:-base:default new:default new:fast}
# The baseline: the commit's sources exported (no worktree is registered) and only the command
# built, Release, into build/tightness-base (kept between runs; rebuilt when BASE changes).
base_ref=${BASE:-b6d6b7d}
base_dir=build/tightness-base
base_bin=$base_dir/build/apps/sphereset
if [ "$(cat "$base_dir/ref" 2>/dev/null)" != "$(git rev-parse "$base_ref")" ] || [ ! -x "$base_bin" ]; then
  rm -rf "$base_dir" && mkdir -p "$base_dir/src"
  git archive "$base_ref" | tar -x -C "$base_dir/src"
  cmake -S "$base_dir/src" -B "$base_dir/build" -DCMAKE_BUILD_TYPE=Release \
    -DSPHERESET_BUILD_TESTS=OFF -DSPHERESET_BUILD_BENCH=OFF -DSPHERESET_BUILD_PYTHON=OFF \
    -DSPHERESET_VIEW_PAGE=OFF >/dev/null
  cmake --build "$base_dir/build" -j "$(nproc)" --target sphereset_cli >/dev/null
  git rev-parse "$base_ref" >"$base_dir/ref"
fi
out=${OUT:-bench/results/tightness.csv}
echo "mesh,n,seed,variant,er_sum,er_before_bounding,wall_s,spheres,covered,bounding_s,peak_kb" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for mesh in "${meshes[@]}"; do
  for n in $n_list; do
    for seed in $seeds; do
      for variant in $variants; do
        build=${variant%%:*} quality=${variant#*:}
        bin=build/apps/sphereset
        [ "$build" = base ] && bin=$base_bin
        /usr/bin/time -f "%e %M" -o "$tmp/time" "$bin" fit "$mesh" -n "$n" --seed "$seed" \
          --quality "$quality" -o "$tmp/spheres.json" --json -q >"$tmp/summary.json"
        /usr/bin/python3 - "$mesh" "$n" "$seed" "$variant" "$tmp" >>"$out" <<'PY'
import json, os, sys
mesh, n, seed, variant, tmp = sys.argv[1:6]
s = json.load(open(os.path.join(tmp, "summary.json")))
wall, peak = open(os.path.join(tmp, "time")).read().split()[-2:]
covered = all(s.get(k, True) for k in ("surface_covered", "interior_covered", "original_covered"))
print(",".join([os.path.basename(mesh), n, seed, variant, "%.6f" % s["er_sum"],
                "%.6f" % s["er_sum_before_bounding"], wall, str(s["spheres"]), str(covered),
                "%.3f" % s["seconds"]["bounding"], peak]))
PY
      done
    done
  done
done
/usr/bin/python3 bench/tightness_summary.py "$out" | tee "${out%.csv}.txt"

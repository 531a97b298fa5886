#!/usr/bin/env bash
# Self-collision sampling on a whole robot: the Kinova Gen3 (../shared/robots/kinova_gen3)
# fitted once with --budget B (default 60), then the pairs per reason (Adjacent, Default, Always,
# Never, left to check) and the sampling's time for SAMPLES configurations (default 10000), on
# the spheres and on the link solids, on one thread and on two. Into
# bench/results/self_collision.csv.
# ROBOT_ROOT=DIR overrides the robot folder.
#   bash bench/self_collision_table.sh            SAMPLES=2000 BUDGET=40 bash bench/self_collision_table.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
bench_program self_collision_table
root=${ROBOT_ROOT:-../shared/robots/kinova_gen3}
urdf=$root/kortex_description/arms/gen3/7dof/urdf/GEN3-7DOF-VISION_ARM_URDF_V12.urdf
budget=${BUDGET:-60}
samples=${SAMPLES:-10000}
tmp=$(mktemp -d)
build/apps/sphereset robot "$urdf" --package-path "$root" --budget "$budget" -o "$tmp/spheres.yml" -q
out=${OUT:-bench/results/self_collision.csv}
build/bench/self_collision_table --header >"$out"
for check in spheres meshes; do
  for threads in 1 2; do
    build/bench/self_collision_table "$urdf" "$root" "$tmp/spheres.yml" "$samples" "$check" \
      "$threads" >>"$out"
  done
done
rm -rf "$tmp"
cat "$out"

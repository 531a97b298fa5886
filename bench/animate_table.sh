#!/usr/bin/env bash
# Sphere sets following a motion (paper Sec. 6): for each motion, a set fitted at the rest pose
# (sphereset fit, default options) moved by mean value coordinates and by bone weights;
# weight precomputation and per-frame update time, frames covered with fixed radii, E_r with
# fixed radii, with the rebound and of a fresh fit per frame. Motions: the clip of
# assimp-testmodels' FBX/animation_with_skeleton.fbx (32 spheres), and the armadillo bent by
# 45 degrees about a horizontal axis through its middle in 8 frames (a smooth two-bone blend
# over the middle 40% of its height, 128 spheres); and X/anim_test.x (see below). Into
# bench/results/animate.csv.
#   bash bench/animate_table.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
bench_program animate_table
tmp=$(mktemp -d)
fbx=/usr/share/assimp/models/FBX/animation_with_skeleton.fbx
armadillo=../shared/meshes/organic/armadillo_libigl.obj
out=${OUT:-bench/results/animate.csv}
build/bench/animate_table --header >"$out"
build/apps/sphereset fit "$fbx" -n 32 -o "$tmp/fbx.json" -q
build/bench/animate_table --animation "$fbx" "$tmp/fbx.json" --fresh >>"$out"
build/apps/sphereset fit "$armadillo" -n 128 -o "$tmp/armadillo.json" -q
build/bench/animate_table --bend "$armadillo" "$tmp/armadillo.json" --frames 8 --angle 45 \
  --band 0.4 --fresh >>"$out"
# DirectX anim_test.x (16 spheres): the tip cap's centre vertex has no bone weight, so most
# frames fold the cap through the tube (frames_crossing); no fresh fits there.
xfile=/usr/share/assimp/models/X/anim_test.x
build/apps/sphereset fit "$xfile" -n 16 -o "$tmp/x.json" -q
build/bench/animate_table --animation "$xfile" "$tmp/x.json" >>"$out"
rm -rf "$tmp"
cat "$out"

#!/usr/bin/env bash
# Time until the page of `sphereset view` is interactive (bench/view_interactive.mjs) for large
# meshes: the armadillo of ../shared/meshes subdivided twice (bench/subdivide.py: 1.38M
# triangles, the same solid), the Stanford dragon (871k) and the armadillo (86k), each with n
# spheres fitted by `sphereset fit`, in Debian's headless Chromium. One CSV row per mesh
# into bench/results/view_interactive.csv: the command's start to its URL (load, repair check,
# index, certificate), the page's load to ready (scene, geometry, first frame), their sum, one
# edit's round trip through the page and the server's incremental certificate of it.
#   bash bench/view_interactive.sh      (N=64 SHARED=../shared OUT=... MESHES="a.ply b.obj")
set -euo pipefail
cd "$(dirname "$0")/.."
args=()
source bench/common.sh
skip_without_shared view_interactive.sh
require_view_page view_interactive.sh
n=${N:-64}
out=${OUT:-bench/results/view_interactive.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
armadillo=$shared/meshes/organic/armadillo_libigl.obj
/usr/bin/python3 bench/subdivide.py "$armadillo" 2 "$tmp/armadillo_x16.ply"
meshes=${MESHES:-"$tmp/armadillo_x16.ply $shared/meshes/big/dragon_vrip_bin.ply $armadillo"}
mkdir -p "$(dirname "$out")"
header=""
rows=()
for mesh in $meshes; do
  set_file="$tmp/$(basename "${mesh%.*}").txt"
  build/apps/sphereset fit "$mesh" -n "$n" -o "$set_file" -q
  result=$(node bench/view_interactive.mjs --cli build/apps/sphereset --node-modules "$modules" \
    --work "$tmp/work" -- "$mesh" "$set_file")
  header=$(echo "$result" | head -1)
  rows+=("$(echo "$result" | tail -1)")
done
{ echo "$header"; printf '%s\n' "${rows[@]}"; } > "$out"
cat "$out"

#!/usr/bin/env bash
# Time until the page of `sphereset view` is interactive for robots, and its round trips
# (bench/view_robot_interactive.mjs): the Kinova Gen3 of ../shared/robots (8 links with
# geometry) and two of it side by side under one world link (bench/two_arms.py: 16 links), each
# with the spheres `sphereset robot --budget` fits (8 a link), in Debian's headless Chromium.
# One CSV row per robot into bench/results/view_robot_interactive.csv.
#   bash bench/view_robot_interactive.sh      (SHARED=../shared OUT=...)
set -euo pipefail
cd "$(dirname "$0")/.."
args=()
source bench/common.sh
skip_without_shared view_robot_interactive.sh
require_view_page view_robot_interactive.sh
out=${OUT:-bench/results/view_robot_interactive.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
packages=$shared/robots/kinova_gen3
gen3=$packages/kortex_description/arms/gen3/7dof/urdf/GEN3-7DOF-VISION_ARM_URDF_V12.urdf
/usr/bin/python3 bench/two_arms.py "$gen3" "$tmp/two_gen3.urdf"
mkdir -p "$(dirname "$out")"
header=""
rows=()
for robot in "$gen3" "$tmp/two_gen3.urdf"; do
  name=$(basename "${robot%.*}")
  links=$(grep -c '<link ' "$robot")
  build/apps/sphereset robot "$robot" --package-path "$packages" --budget $((8 * links)) \
    -o "$tmp/$name.yml" -q > /dev/null
  result=$(node bench/view_robot_interactive.mjs --cli build/apps/sphereset --node-modules "$modules" \
    --work "$tmp/work" -- "$robot" "$tmp/$name.yml" --package-path "$packages")
  header=$(echo "$result" | head -1)
  rows+=("$(echo "$result" | tail -1)")
done
{ echo "$header"; printf '%s\n' "${rows[@]}"; } > "$out"
cat "$out"

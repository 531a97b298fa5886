#!/usr/bin/env bash
# Tolerance asked -> count found -> protrusion certified -> time, per link of the Kinova Gen3
# (../shared/robots/kinova_gen3: each link's collision STL fitted alone, in metres, as its
# envelope (--fill-openings auto, the robot command's default solid; SOLID=walls fits the walls
# as they are), for 5 mm, 1 cm and 2 cm (TOLERANCES overrides), quality QUALITY (default:
# default), at most MAX_SPHERES (256). Into bench/results/tolerance.csv.
#   bash bench/tolerance_table.sh          QUALITY=fast TOLERANCES="0.01" bash bench/tolerance_table.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
root=${ROBOT_ROOT:-../shared/robots/kinova_gen3}
meshes=$root/kortex_description/arms/gen3/7dof/meshes
quality=${QUALITY:-default}
out=${OUT:-bench/results/tolerance.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "link,tolerance,met,n,protrusion,er_sum,counts_tried,seconds" >"$out"
for mesh in "$meshes"/*.STL; do
  link=$(basename "$mesh" .STL)
  for d in ${TOLERANCES:-0.005 0.01 0.02}; do
    solid=(--fill-openings auto)
    [ "${SOLID:-envelope}" = walls ] && solid=(--fill-openings 0)
    build/apps/sphereset fit "$mesh" --max-protrusion "$d" --quality "$quality" "${solid[@]}" \
      --max-spheres "${MAX_SPHERES:-256}" \
      -o "$tmp/$link.json" --json -q >"$tmp/r.json" || [ $? -eq 10 ]
    /usr/bin/python3 - "$tmp/r.json" "$link" "$d" >>"$out" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
t = r["tolerance"]
print(f"{sys.argv[2]},{sys.argv[3]},{int(t['met'])},{t['n']},{r['protrusion']['bound']:.6g},"
      f"{r['er_sum']:.4f},{len(t['curve'])},{t['seconds']:.2f}")
PY
  done
done
cat "$out"

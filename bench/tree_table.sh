#!/usr/bin/env bash
# Sphere-tree levels with both kinds of parents, side by side: for each mesh, the same fitted
# leaves (same seed) under minimal-enclosing-ball parents and under least-outside-volume
# parents; per level the sphere count and E_r (summed, exact) of each kind, into
# bench/results/tree.csv.
#   bash bench/tree_table.sh [MESH ...]   (default: spot and armadillo from ../shared/meshes)
#   BRANCH=4 DEPTH=3 bash bench/tree_table.sh ...   (default 8 and 2)
set -euo pipefail
args=("$@")
source "$(dirname "$0")/common.sh"
bench_meshes ../shared/meshes/organic/spot.obj ../shared/meshes/organic/armadillo_libigl.obj
out=bench/results/tree.csv
echo "mesh,branching,depth,level,spheres,er_sum_minimal,er_sum_outside,ratio,tree_s_minimal,tree_s_outside" >"$out"
for mesh in "${meshes[@]}"; do
  tmp=$(mktemp -d)
  for kind in minimal outside; do
    build/apps/sphereset tree "$mesh" --branch "${BRANCH:-8}" --depth "${DEPTH:-2}" \
      --parents "$kind" -o "$tmp/$kind.sph" --json -q >"$tmp/$kind.json"
  done
  python3 - "$mesh" "$tmp" >>"$out" <<'PY'
import json, os, sys
mesh, tmp = sys.argv[1], sys.argv[2]
a = json.load(open(os.path.join(tmp, "minimal.json")))
b = json.load(open(os.path.join(tmp, "outside.json")))
for la, lb in zip(a["levels"], b["levels"]):
    assert la["spheres"] == lb["spheres"]
    print(",".join(str(x) for x in [
        os.path.basename(mesh), a["branching"], a["depth"], la["level"], la["spheres"],
        "%.4f" % la["er_sum"], "%.4f" % lb["er_sum"], "%.3f" % (lb["er_sum"] / la["er_sum"]),
        "%.3f" % a["seconds"]["tree"], "%.3f" % b["seconds"]["tree"]]))
PY
  rm -rf "$tmp"
done
cat "$out"

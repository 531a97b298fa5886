#!/usr/bin/env bash
# Fit quality and cost against the number of spheres: for each mesh and n, E_r (summed, before
# bounding, union), coverage, wall time, peak memory, SOV queries and the time of each phase,
# into bench/results/fit.csv.
#   bash bench/fit_table.sh [MESH ...]   (default: armadillo and fandisk from ../shared/meshes)
#   N_LIST="16 32" bash bench/fit_table.sh ...
#   N_LIST="256 512 1024 2048" bash bench/fit_table.sh examples/spot.obj   (large sets)
#   FIT_ARGS="--decimation 0.5" OUT=bench/results/fit_decimation.csv bash bench/fit_table.sh
set -euo pipefail
args=("$@")
source "$(dirname "$0")/common.sh"
bench_meshes ../shared/meshes/organic/armadillo_libigl.obj ../shared/meshes/cad/fandisk.obj
out=${OUT:-bench/results/fit.csv}
echo "mesh,n,er_sum,er_sum_before_bounding,er_union,er_union_stderr,surface_covered,interior_covered,wall_s,peak_mb,sov_queries,sov_queries_culled,points,rounds,s_sampling,s_assignment,s_update,s_teleport,s_bounding" >"$out"
for mesh in "${meshes[@]}"; do
  for n in ${N_LIST:-16 32 64 128}; do
    tmp=$(mktemp -d)
    /usr/bin/time -f "%e %M" -o "$tmp/time" build/apps/sphereset fit "$mesh" -n "$n" \
      -o "$tmp/spheres.json" --json -q ${FIT_ARGS:-} >"$tmp/summary.json"
    python3 - "$mesh" "$n" "$tmp" >>"$out" <<'PY'
import json, os, sys
mesh, n, tmp = sys.argv[1], sys.argv[2], sys.argv[3]
s = json.load(open(os.path.join(tmp, "summary.json")))
wall, peak_kb = open(os.path.join(tmp, "time")).read().split()[-2:]
print(",".join(str(x) for x in [
    os.path.basename(mesh), n, "%.4f" % s["er_sum"], "%.4f" % s["er_sum_before_bounding"],
    "%.4f" % s["er_union"], "%.4f" % s["er_union_stderr"], s["surface_covered"],
    s["interior_covered"], wall, "%.0f" % (int(peak_kb) / 1024), s["sov_queries"],
    s["sov_queries_culled"], s["points"], s["rounds"]] +
    ["%.2f" % s["seconds"][k] for k in ("sampling", "assignment", "update", "teleport", "bounding")]))
PY
    rm -rf "$tmp"
  done
done
cat "$out"

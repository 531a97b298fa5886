#!/usr/bin/env bash
# Broken and clean meshes through the repair: for each mesh and n, the repair chosen, its time,
# the fit's wall time, E_r (relative to the repaired solid), the wrap's volume over the input's
# (where defined; otherwise over the input's winding-number volume, a Monte Carlo estimate by
# bench/winding_volume.cpp, for inputs up to 30k triangles), the library's coverage
# certificates and an independent brute-force check of the original triangles
# (bench/cover_check.cpp), into bench/results/repair.csv.
#   bash bench/repair_table.sh [MESH ...]   (default: every mesh of ../shared/meshes but the
#                                            dragon, and the Kinova Gen3 links)
#   N_LIST="16" bash bench/repair_table.sh ...
#   DRAGON=1 bash bench/repair_table.sh     (also: the 871k dragon with one triangle deleted,
#                                            n = 128)
set -euo pipefail
args=("$@")
source "$(dirname "$0")/common.sh"
bench_program cover_check
bench_program winding_volume
shared=../shared/meshes
kinova=../shared/robots/kinova_gen3/kortex_description/arms/gen3/7dof/meshes
bench_meshes "$shared"/defect/* "$shared"/robot/* "$shared"/cad/* "$shared"/organic/* \
  "$kinova"/*.STL
out=${OUT:-bench/results/repair.csv}
echo "mesh,n,input_triangles,repair,solid_triangles,repair_s,wall_s,er_sum,volume_ratio,volume_ratio_winding,surface_covered,interior_covered,original_covered,check_points,check_missed" >"$out"

run() {  # mesh n
  local mesh=$1 n=$2 tmp
  tmp=$(mktemp -d)
  /usr/bin/time -f "%e" -o "$tmp/time" build/apps/sphereset fit "$mesh" -n "$n" \
    -o "$tmp/spheres.txt" --json -q ${FIT_ARGS:-} >"$tmp/summary.json" || true
  build/bench/cover_check "$mesh" "$tmp/spheres.txt" >"$tmp/check.json" || true
  build/apps/sphereset check "$mesh" --json --repair off >"$tmp/input.json" 2>/dev/null || true
  # The winding-number volume, once per mesh, where the input's own volume is undefined.
  if [ "$n" = "$first_n" ] && python3 -c "import json,sys; s=json.load(open(sys.argv[1])); \
      i=json.load(open(sys.argv[2])); sys.exit(0 if s['repair']['volume_ratio'] is None and \
      i['triangles'] <= 30000 else 1)" "$tmp/summary.json" "$tmp/input.json" 2>/dev/null; then
    build/bench/winding_volume "$mesh" 200000 >"$winding" || echo '{}' >"$winding"
  elif [ "$n" = "$first_n" ]; then
    echo '{}' >"$winding"
  fi
  python3 - "$mesh" "$n" "$tmp" "$winding" >>"$out" <<'PY'
import json, os, sys
mesh, n, tmp, winding = sys.argv[1:5]
name = os.path.basename(mesh)
try:
    s = json.load(open(os.path.join(tmp, "summary.json")))
    c = json.load(open(os.path.join(tmp, "check.json")))
    i = json.load(open(os.path.join(tmp, "input.json")))
except (OSError, ValueError):
    print(f"{name},{n},,failed,,,,,,,,,,,")
    sys.exit()
r = s["repair"]
w = json.load(open(winding))
wall = open(os.path.join(tmp, "time")).read().split()[-1]
ratio = "" if r["volume_ratio"] is None else "%.4f" % r["volume_ratio"]
wratio = "%.4f" % (r["volume"] / w["volume"]) if w.get("volume") else ""
print(",".join(str(x) for x in [
    name, n, i["triangles"], r["kind"], r["triangles"], "%.2f" % r["seconds"], wall,
    "%.4f" % s["er_sum"], ratio, wratio, s["surface_covered"], s["interior_covered"],
    s["original_covered"], c["points"], c["missed"]]))
PY
  rm -rf "$tmp"
}

n_list=(${N_LIST:-16 64})
first_n=${n_list[0]}
winding=$(mktemp)
for mesh in "${meshes[@]}"; do
  for n in "${n_list[@]}"; do run "$mesh" "$n"; done
done
if [ "${DRAGON:-0}" = 1 ]; then
  # The dragon with its first triangle deleted (binary PLY: 13 bytes per face).
  holed=$(mktemp -d)/dragon_minus_one.ply
  python3 - "$shared/big/dragon_vrip_bin.ply" "$holed" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
end = data.index(b"end_header\n") + len(b"end_header\n")
header = data[:end].decode()
nv = int(header.split("element vertex ")[1].split()[0])
nf = int(header.split("element face ")[1].split()[0])
header = header.replace("element face %d" % nf, "element face %d" % (nf - 1))
faces = end + 12 * nv
open(sys.argv[2], "wb").write(header.encode() + data[end:faces] + data[faces + 13:])
PY
  first_n=128
  run "$holed" 128
  rm -rf "$(dirname "$holed")"
fi
rm -f "$winding"
cat "$out"

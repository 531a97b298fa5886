#!/usr/bin/env bash
# Broken and clean meshes through the repair: for each mesh and n, the repair chosen, its time,
# the fit's wall time, E_r (relative to the repaired solid), the wrap's volume over the input's
# (where defined), the library's coverage certificates and an independent brute-force check of
# the original triangles (bench/cover_check.cpp), into bench/results/repair.csv.
#   bash bench/repair_table.sh [MESH ...]   (default: every mesh of ../shared/meshes but the
#                                            dragon, and the Kinova Gen3 links)
#   N_LIST="16" bash bench/repair_table.sh ...
#   DRAGON=1 bash bench/repair_table.sh     (also: the 871k dragon with one triangle deleted,
#                                            n = 128)
set -euo pipefail
args=("$@")
source "$(dirname "$0")/common.sh"
[ -x build/bench/cover_check ] || cmake --build build --target cover_check
shared=../shared/meshes
kinova=../shared/robots/kinova_gen3/kortex_description/arms/gen3/7dof/meshes
bench_meshes "$shared"/defect/* "$shared"/robot/* "$shared"/cad/* "$shared"/organic/* \
  "$kinova"/*.STL
out=${OUT:-bench/results/repair.csv}
echo "mesh,n,triangles,repair,repair_s,wall_s,er_sum,volume_ratio,surface_covered,interior_covered,original_covered,check_points,check_missed" >"$out"

run() {  # mesh n
  local mesh=$1 n=$2 tmp
  tmp=$(mktemp -d)
  /usr/bin/time -f "%e" -o "$tmp/time" build/apps/sphereset fit "$mesh" -n "$n" \
    -o "$tmp/spheres.txt" --json -q ${FIT_ARGS:-} >"$tmp/summary.json" || true
  build/bench/cover_check "$mesh" "$tmp/spheres.txt" >"$tmp/check.json" || true
  python3 - "$mesh" "$n" "$tmp" >>"$out" <<'PY'
import json, os, sys
mesh, n, tmp = sys.argv[1], sys.argv[2], sys.argv[3]
name = os.path.basename(mesh)
try:
    s = json.load(open(os.path.join(tmp, "summary.json")))
    c = json.load(open(os.path.join(tmp, "check.json")))
except (OSError, ValueError):
    print(f"{name},{n},,failed,,,,,,,,,")
    sys.exit()
r = s["repair"]
wall = open(os.path.join(tmp, "time")).read().split()[-1]
ratio = "" if r["volume_ratio"] is None else "%.4f" % r["volume_ratio"]
print(",".join(str(x) for x in [
    name, n, r["triangles"], r["kind"], "%.2f" % r["seconds"], wall, "%.4f" % s["er_sum"], ratio,
    s["surface_covered"], s["interior_covered"], s["original_covered"], c["points"],
    c["missed"]]))
PY
  rm -rf "$tmp"
}

for mesh in "${meshes[@]}"; do
  for n in ${N_LIST:-16 64}; do run "$mesh" "$n"; done
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
  run "$holed" 128
  rm -rf "$(dirname "$holed")"
fi
cat "$out"

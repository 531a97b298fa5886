#!/usr/bin/env bash
# The batch on Dask against `sphereset batch`: every closed mesh of a folder (closed: `sphereset
# check --repair off` exits 0; the selection of bench/batch_table.sh), at n = 32, with the command
# (one item at a time, each fit on every core) and with `python3 -m sphereset.batch
# --local-workers K` (K worker processes, one item each, cores / K threads per fit): items per
# minute, CPU utilisation ((user + sys of the run and its children) / (wall × cores)), peak
# memory of the largest process, and whether both wrote the same sphere files and report (timings
# aside). Into bench/results/dask_batch.csv (columns of batch.csv, with the runner first).
#   bash bench/dask_batch.sh [MESH_DIR]      (default ../shared/meshes)
#   N=32 QUALITY=default WORKERS=2 bash bench/dask_batch.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
[ -f build/python/sphereset/__init__.py ] || cmake --build build --target _sphereset
mesh_dir=${1:-../shared/meshes}
n=${N:-32}
quality=${QUALITY:-default}
workers=${WORKERS:-2}
out=${OUT:-bench/results/dask_batch.csv}
cores=$(nproc)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

link_closed_meshes "$mesh_dir" "$tmp/in"

echo "runner,workers,items,ok,failed,n,quality,wall_s,user_s,sys_s,cpu_utilisation,items_per_min,peak_mb,cores,load_1min_before,same_as_cli" >"$out"
row() {  # runner workers name same
  python3 - "$tmp" "$@" "$n" "$quality" "$cores" "$load" >>"$out" <<'PY'
import json, os, sys
tmp, runner, workers, name, same, n, quality, cores, load = sys.argv[1:]
wall, user, sys_s, peak_kb = (float(x) for x in open(os.path.join(tmp, name + ".time")).read().split()[-4:])
lines = [json.loads(l) for l in open(os.path.join(tmp, name, "report.jsonl"))]
ok = sum(l["status"] == "ok" for l in lines)
failed = sum(l["status"] == "error" for l in lines)
print(",".join(str(x) for x in [
    runner, workers, len(lines), ok, failed, n, quality, "%.2f" % wall, "%.2f" % user,
    "%.2f" % sys_s, "%.3f" % ((user + sys_s) / (wall * int(cores))),
    "%.2f" % (60.0 * len(lines) / wall), "%.0f" % (peak_kb / 1024), cores, load, same]))
PY
}
load=$(cut -d' ' -f1 /proc/loadavg)
/usr/bin/time -f "%e %U %S %M" -o "$tmp/cli.time" build/apps/sphereset batch "$tmp/in" \
  -o "$tmp/cli" -n "$n" --quality "$quality" -q || true
row cli 1 cli n/a
load=$(cut -d' ' -f1 /proc/loadavg)
PYTHONPATH=build/python /usr/bin/time -f "%e %U %S %M" -o "$tmp/dask.time" \
  /usr/bin/python3 -m sphereset.batch "$tmp/in" -o "$tmp/dask" -n "$n" --quality "$quality" \
  --local-workers "$workers" -q || true
same=$(python3 - "$tmp/cli" "$tmp/dask" <<'PY'
import json, pathlib, sys
a, b = (pathlib.Path(p) for p in sys.argv[1:3])
ra = [json.loads(l) for l in open(a / "report.jsonl")]
rb = [json.loads(l) for l in open(b / "report.jsonl")]
for r in ra + rb:
    r.pop("seconds")
same = ra == rb and all((a / r["output"]).read_bytes() == (b / r["output"]).read_bytes()
                        for r in ra if r["status"] == "ok")
print("yes" if same else "no")
PY
)
row dask "$workers" dask "$same"
cat "$out"

#!/usr/bin/env bash
# The batch over the closed meshes of ../shared/meshes (watertight "yes" in MANIFEST.tsv) at
# n = 32, with `sphereset batch` and with the Dask runner on K local worker processes: items per
# minute, and CPU utilisation = (user + system CPU time of the run and its children) / (wall time
# x cores), into bench/results/dask_batch.csv. Both runs start from an empty output folder.
#   bash bench/dask_batch.sh                 (K = 2, n = 32)
#   WORKERS=2 N=32 EXCLUDE=big/ bash bench/dask_batch.sh   (skip files matching a pattern)
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
workers=${WORKERS:-2}
n=${N:-32}
shared=../shared/meshes
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# A manifest of absolute paths, so that every worker reads the same files.
echo "mesh" >"$tmp/closed.csv"
awk -F'\t' 'NR > 1 && $5 == "yes" {print $1}' "$shared/MANIFEST.tsv" |
  { if [ -n "${EXCLUDE:-}" ]; then grep -v -- "$EXCLUDE"; else cat; fi; } |
  while read -r f; do echo "$(realpath "$shared/$f")"; done >>"$tmp/closed.csv"
items=$(($(wc -l <"$tmp/closed.csv") - 1))
cores=$(nproc)
out=bench/results/dask_batch.csv
echo "runner,workers,items,ok,n,wall_s,cpu_s,items_per_min,cpu_utilisation,cores" >"$out"
row() {  # runner workers dir time-file
  python3 - "$@" "$items" "$n" "$cores" >>"$out" <<'PY'
import json, sys
runner, workers, d, tf, items, n, cores = sys.argv[1:8]
wall, user, sys_ = map(float, open(tf).read().split()[-3:])
rep = [json.loads(l) for l in open(d + "/report.jsonl")]
ok = sum(r["status"] == "ok" for r in rep)
print(f"{runner},{workers},{items},{ok},{n},{wall:.1f},{user + sys_:.1f},"
      f"{int(items) / wall * 60:.2f},{(user + sys_) / (wall * int(cores)):.2f},{cores}")
PY
}
/usr/bin/time -f "%e %U %S" -o "$tmp/cli.time" \
  build/apps/sphereset batch "$tmp/closed.csv" -o "$tmp/cli" -n "$n" -q || true
row cli 1 "$tmp/cli" "$tmp/cli.time"
PYTHONPATH=build/python /usr/bin/time -f "%e %U %S" -o "$tmp/dask.time" \
  /usr/bin/python3 -m sphereset.batch "$tmp/closed.csv" -o "$tmp/dask" -n "$n" \
  --local-workers "$workers" -q || true
row dask "$workers" "$tmp/dask" "$tmp/dask.time"
# Same spheres and the same report (timings aside) from both runners.
python3 - "$tmp/cli" "$tmp/dask" <<'PY'
import json, sys, pathlib
a, b = (pathlib.Path(p) for p in sys.argv[1:3])
ra = [json.loads(l) for l in open(a / "report.jsonl")]
rb = [json.loads(l) for l in open(b / "report.jsonl")]
for r in ra + rb:
    r.pop("seconds")
same = ra == rb and all((a / r["output"]).read_bytes() == (b / r["output"]).read_bytes()
                        for r in ra if r["status"] == "ok")
print("identical files and reports:", same)
PY
cat "$out"

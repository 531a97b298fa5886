#!/usr/bin/env bash
# Batch throughput: `sphereset batch` over every closed mesh of a folder (closed: `sphereset
# check --repair off` exits 0), at n = 32, with 1 and 2 items fitted at once (--jobs): items per
# minute, CPU utilisation ((user + sys) / (wall × cores)), peak memory, and whether --jobs 2
# wrote the same files as --jobs 1. Into bench/results/batch.csv (one row per --jobs) and
# bench/results/batch_items.csv (each item's report line of the --jobs 1 run).
#   bash bench/batch_table.sh [MESH_DIR]   (default ../shared/meshes)
#   N=32 QUALITY=default JOBS_LIST="1 2" bash bench/batch_table.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
mesh_dir=${1:-../shared/meshes}
n=${N:-32}
quality=${QUALITY:-default}
out=${OUT:-bench/results/batch.csv}
items_out=${ITEMS_OUT:-bench/results/batch_items.csv}
cores=$(nproc)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The closed meshes, linked into one folder with the same layout.
link_closed_meshes "$mesh_dir" "$tmp/in"

echo "jobs,items,ok,failed,n,quality,wall_s,user_s,sys_s,cpu_utilisation,items_per_min,peak_mb,cores,load_1min_before,same_as_jobs_1" >"$out"
for jobs in ${JOBS_LIST:-1 2}; do
  load=$(cut -d' ' -f1 /proc/loadavg)
  /usr/bin/time -f "%e %U %S %M" -o "$tmp/time_$jobs" build/apps/sphereset batch "$tmp/in" \
    -o "$tmp/out_$jobs" -n "$n" --quality "$quality" --jobs "$jobs" --force -q || true
  same=n/a
  if [ "$jobs" != 1 ] && [ -d "$tmp/out_1" ]; then
    if diff -r -q -x report.jsonl -x .sphereset-batch "$tmp/out_1" "$tmp/out_$jobs" >/dev/null; then
      same=yes
    else
      same=no
    fi
  fi
  python3 - "$tmp" "$jobs" "$n" "$quality" "$cores" "$load" "$same" >>"$out" <<'PY'
import json, os, sys
tmp, jobs, n, quality, cores, load, same = sys.argv[1:]
wall, user, sys_s, peak_kb = (float(x) for x in open(os.path.join(tmp, "time_" + jobs)).read().split()[-4:])
lines = [json.loads(l) for l in open(os.path.join(tmp, "out_" + jobs, "report.jsonl"))]
ok = sum(l["status"] == "ok" for l in lines)
failed = sum(l["status"] == "error" for l in lines)
print(",".join(str(x) for x in [
    jobs, len(lines), ok, failed, n, quality, "%.2f" % wall, "%.2f" % user, "%.2f" % sys_s,
    "%.3f" % ((user + sys_s) / (wall * int(cores))), "%.2f" % (60.0 * len(lines) / wall),
    "%.0f" % (peak_kb / 1024), cores, load, same]))
PY
done
python3 - "$tmp/out_$(echo ${JOBS_LIST:-1 2} | cut -d' ' -f1)/report.jsonl" >"$items_out" <<'PY'
import json, sys
print("mesh,status,spheres,er_sum,er_union,covered,repair,seconds")
for l in open(sys.argv[1]):
    r = json.loads(l)
    er = lambda v: "" if v is None else "%.4f" % v
    print(",".join(str(x) for x in [r["output"], r["status"], r["spheres"], er(r["er_sum"]),
                                    er(r["er_union"]), r["covered"], r["repair"],
                                    "%.2f" % r["seconds"]]))
PY
cat "$out" "$items_out"

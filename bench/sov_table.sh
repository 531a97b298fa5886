#!/usr/bin/env bash
# SOV queries per second, hierarchy against brute force, for spot, armadillo and the dragon.
# Writes bench/results/sov.json (raw Google Benchmark output) and bench/results/sov.csv
# (mesh, centres: surface or interior, triangles, radius fraction, microseconds per query
# each way, speed-up, closed-form evaluations per query each way).
#   bash bench/sov_table.sh [--mesh-dir DIR]
set -euo pipefail
source "$(dirname "$0")/common.sh"
bench_program bench_outside_volume
build/bench/bench_outside_volume "$@" --benchmark_out=bench/results/sov.json \
  --benchmark_out_format=json >/dev/null
python3 - <<'PY'
import csv, json
runs = json.load(open("bench/results/sov.json"))["benchmarks"]
rows = {}
for b in runs:
    if b.get("error_occurred"):
        continue
    family, mesh, kind, arg = b["run_name"].split("/")[:4]
    centres = "interior" if family.endswith("interior") else "surface"
    key = (mesh, centres, int(arg))
    r = rows.setdefault(key, {"mesh": mesh, "centres": centres,
                              "triangles": int(b["triangles"]),
                              "radius_frac": b["radius_frac"]})
    r[kind + "_us"] = b["real_time"] / 1e3 if b["time_unit"] == "ns" else b["real_time"]
    r[kind + "_kernel_evals"] = round(b["tris_tested"], 1)
with open("bench/results/sov.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["mesh", "centres", "triangles", "radius_frac", "bvh_us", "brute_us", "speedup",
                "bvh_kernel_evals", "brute_kernel_evals"])
    for key in sorted(rows):
        r = rows[key]
        if "bvh_us" not in r or "brute_us" not in r:
            continue
        w.writerow([r["mesh"], r["centres"], r["triangles"], r["radius_frac"], "%.1f" % r["bvh_us"],
                    "%.1f" % r["brute_us"], "%.1f" % (r["brute_us"] / r["bvh_us"]),
                    r["bvh_kernel_evals"], r["brute_kernel_evals"]])
print(open("bench/results/sov.csv").read())
PY

#!/usr/bin/env bash
# The robot budget's links against independent fits at the same counts, beside the spread of
# independent fits themselves: the Kinova Gen3 (../shared/robots/kinova_gen3) at --budget B
# (60), seeds 1..SEEDS (3). For each seed S:
#   budget   `robot --budget B --seed S`;
#   fixed    the same robot with no budget and every link's count fixed to the budget's
#            (`--link-spheres LINK=N` for each), seed S: each link an independent fit;
#   other    the same fixed counts with seed S + 100: independent fits from other points.
# Per link: budget / fixed (how far the budget's warm-started link is from an independent fit at
# its count) and other / fixed (how far two independent fits at one count are from each other).
# Into bench/results/robot_equal_counts.csv (OUT), a summary into ..._summary.txt beside it.
#   bash bench/robot_equal_counts.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
skip_without_shared robot_equal_counts
kinova_robot
budget=${BUDGET:-60}
out=${OUT:-bench/results/robot_equal_counts.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
robot() { build/apps/sphereset robot "$urdf" --package-path "$root" -o "$tmp/r.yml" --json -q "$@"; }
rows() {  # RUN SEED JSON: one line per fitted link
  /usr/bin/python3 - "$@" <<'PY'
import json, sys
run, seed, path = sys.argv[1:4]
for l in json.load(open(path))["links"]:
    if l["fitted"]:
        print(f'{run},{seed},{l["link"]},{l["count"]},{l["outside_volume"]}')
PY
}
echo "run,seed,link,count,outside_volume" >"$out"
for seed in $(seq 1 "${SEEDS:-3}"); do
  robot --budget "$budget" --seed "$seed" >"$tmp/budget.json"
  rows budget "$seed" "$tmp/budget.json" >>"$out"
  fixed=()
  while IFS=, read -r _ _ link count _; do
    fixed+=(--link-spheres "$link=$count")
  done < <(rows budget "$seed" "$tmp/budget.json")
  robot "${fixed[@]}" --seed "$seed" >"$tmp/fixed.json"
  rows fixed "$seed" "$tmp/fixed.json" >>"$out"
  robot "${fixed[@]}" --seed $((seed + 100)) >"$tmp/other.json"
  rows other "$seed" "$tmp/other.json" >>"$out"
  echo "robot_equal_counts: seed $seed done" >&2
done
/usr/bin/python3 - "$out" <<'PY' | tee "${out%.csv}_summary.txt"
import collections, csv, math, sys
vol = collections.defaultdict(dict)
for r in csv.DictReader(open(sys.argv[1])):
    vol[(r["seed"], r["link"])][r["run"]] = (int(r["count"]), float(r["outside_volume"]))
g = lambda v: math.exp(sum(math.log(x) for x in v) / len(v))
for run in ("budget", "other"):
    ratios = []
    for (seed, link), v in sorted(vol.items()):
        assert v[run][0] == v["fixed"][0], (seed, link)
        ratios.append((v[run][1] / v["fixed"][1], seed, link, v[run][0]))
    over = [r for r in ratios if r[0] > 1.02]
    worst = max(ratios)
    print(f"{run} / fixed, {len(ratios)} links: geometric mean {g([r[0] for r in ratios]):.3f}, "
          f"{min(ratios)[0]:.3f} to {worst[0]:.3f} (worst: {worst[2]}, {worst[3]} spheres, "
          f"seed {worst[1]}); above 1.02: {len(over)}; below 0.98: "
          f"{sum(r[0] < 0.98 for r in ratios)}")
PY

#!/usr/bin/env bash
# The robot budget's time and outside volume against another build of the command (a baseline,
# e.g. an earlier commit built beside this one): the Kinova Gen3 (../shared/robots/kinova_gen3)
# at --budget B (60), seeds 1..SEEDS (3), both commands run one after the other for each seed
# on the same machine. Per run: wall seconds, the robot's outside volume and each link's count
# and outside volume (from --json), into bench/results/robot_speed.csv (OUT); a summary (time
# ratio, outside-volume ratio of the totals and per link) into robot_speed_summary.txt beside it.
#   BASELINE=/tmp/old/build/apps/sphereset bash bench/robot_speed.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
skip_without_shared robot_speed
baseline=${BASELINE:?BASELINE=path of the baseline sphereset command}
kinova_robot
budget=${BUDGET:-60}
out=${OUT:-bench/results/robot_speed.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "build,seed,wall_s,outside_volume,link,count,link_outside_volume" >"$out"
for seed in $(seq 1 "${SEEDS:-3}"); do
  for build in baseline this; do
    cmd=build/apps/sphereset
    [ "$build" = baseline ] && cmd=$baseline
    /usr/bin/time -f "%e" -o "$tmp/t" "$cmd" robot "$urdf" --package-path "$root" \
      --budget "$budget" --seed "$seed" -o "$tmp/r.yml" --json -q >"$tmp/r.json"
    /usr/bin/python3 - "$build" "$seed" "$(cat "$tmp/t")" "$tmp/r.json" >>"$out" <<'PY'
import json, sys
build, seed, wall, path = sys.argv[1:5]
r = json.load(open(path))
for l in r["links"]:
    if l["fitted"]:
        print(f'{build},{seed},{wall},{r["outside_volume"]},{l["link"]},{l["count"]},{l["outside_volume"]}')
PY
    echo "robot_speed: $build seed $seed: $(cat "$tmp/t") s" >&2
  done
done
/usr/bin/python3 - "$out" <<'PY' | tee "${out%.csv}_summary.txt"
import collections, csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
runs = collections.defaultdict(dict)
links = collections.defaultdict(dict)
for r in rows:
    runs[(r["build"], r["seed"])] = (float(r["wall_s"]), float(r["outside_volume"]))
    links[(r["build"], r["seed"])][r["link"]] = (int(r["count"]), float(r["link_outside_volume"]))
seeds = sorted({s for _, s in runs}, key=int)
g = lambda v: math.exp(sum(math.log(x) for x in v) / len(v))
t = [runs[("this", s)][0] / runs[("baseline", s)][0] for s in seeds]
v = [runs[("this", s)][1] / runs[("baseline", s)][1] for s in seeds]
for s in seeds:
    print(f"seed {s}: time {runs[('baseline', s)][0]:.2f} s -> {runs[('this', s)][0]:.2f} s, "
          f"outside volume {runs[('baseline', s)][1]:.6g} -> {runs[('this', s)][1]:.6g}")
print(f"time ratio (this / baseline): geometric mean {g(t):.3f}, max {max(t):.3f}")
print(f"outside volume ratio of the robot: geometric mean {g(v):.4f}, max {max(v):.4f}")
per_link = collections.defaultdict(list)
for s in seeds:
    for link, (n, vol) in links[("this", s)].items():
        per_link[link].append(vol / links[("baseline", s)][link][1])
print("outside volume ratio per link (geometric mean over the seeds):")
for link, r in per_link.items():
    print(f"  {link}: {g(r):.4f}")
PY

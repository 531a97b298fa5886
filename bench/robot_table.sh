#!/usr/bin/env bash
# A whole robot: the Kinova Gen3 (../shared/robots/kinova_gen3) with --budget B (default 60)
# against the same total split evenly over the links (--link-spheres), both with default
# options. Per link and split: spheres, E_r and outside volume (sphereset eval --link on the
# link's collision mesh, which the URDF places at the link origin unscaled), the eval's
# coverage certificates, and the independent brute-force check of bench/cover_check; wall time
# of each robot command. Into bench/results/robot.csv.
# SEED=S (default 1) is passed to both robot commands; fits vary by several per cent with the
# seed, so compare splits over a few seeds.
#   bash bench/robot_table.sh            BUDGET=40 SEED=2 bash bench/robot_table.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
bench_program cover_check
root=../shared/robots/kinova_gen3
urdf=$root/kortex_description/arms/gen3/7dof/urdf/GEN3-7DOF-VISION_ARM_URDF_V12.urdf
meshes=$root/kortex_description/arms/gen3/7dof/meshes
budget=${BUDGET:-60}
seed=${SEED:-1}
links=(base_link shoulder_link half_arm_1_link half_arm_2_link forearm_link
       spherical_wrist_1_link spherical_wrist_2_link bracelet_link)
files=(base_link shoulder_link half_arm_1_link half_arm_2_link forearm_link
       spherical_wrist_1_link spherical_wrist_2_link bracelet_with_vision_link)
tmp=$(mktemp -d)
# The even split: budget / links each, the remainder to the first links.
even=()
for i in "${!links[@]}"; do
  n=$((budget / ${#links[@]} + (i < budget % ${#links[@]} ? 1 : 0)))
  even+=(--link-spheres "${links[$i]}=$n")
done
/usr/bin/time -f "%e" -o "$tmp/t_budget" build/apps/sphereset robot "$urdf" --package-path "$root" \
  --budget "$budget" --seed "$seed" -o "$tmp/budget.yml" -q
/usr/bin/time -f "%e" -o "$tmp/t_even" build/apps/sphereset robot "$urdf" --package-path "$root" \
  "${even[@]}" --seed "$seed" -o "$tmp/even.yml" -q
out=${OUT:-bench/results/robot.csv}
echo "split,wall_s,link,spheres,er_sum,outside_volume,surface_covered,interior_covered,original_covered,check_points,check_missed" >"$out"
for split in budget even; do
  for i in "${!links[@]}"; do
    link=${links[$i]} mesh=$meshes/${files[$i]}.STL
    build/apps/sphereset eval "$mesh" "$tmp/$split.yml" --link "$link" --json --samples 0 \
      --segments 0 --shadow-resolution 0 >"$tmp/eval.json"
    build/bench/cover_check "$mesh" "$tmp/$split.yml" 10 "$link" >"$tmp/check.json" || true
    python3 - "$split" "$(cat "$tmp/t_$split")" "$link" "$tmp" >>"$out" <<'PY'
import json, os, sys
split, wall, link, tmp = sys.argv[1:5]
e = json.load(open(os.path.join(tmp, "eval.json")))
c = json.load(open(os.path.join(tmp, "check.json")))
print(",".join(str(x) for x in [split, wall, link, e["spheres"], "%.4f" % e["er_sum"],
    "%.6g" % (e["er_sum"] * e["mesh_volume"]), e["surface_covered"], e["interior_covered"],
    e.get("original_covered", True), c["points"], c["missed"]]))
PY
  done
done
rm -rf "$tmp"
python3 - "$out" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for split in ("budget", "even"):
    r = [x for x in rows if x["split"] == split]
    print("%s: %s s, %d spheres, total outside volume %.6g, missed %d" % (split, r[0]["wall_s"],
          sum(int(x["spheres"]) for x in r), sum(float(x["outside_volume"]) for x in r),
          sum(int(x["check_missed"]) for x in r)))
PY
cat "$out"

#!/usr/bin/env bash
# mj_step of sphere models against mesh models, in a scene with contacts (the robot released
# under gravity from a start pose, falling onto a table beside it and folding onto itself): the
# Kinova Gen3 of ../shared (its URDF as MuJoCo reads it, STL meshes; start joint_2=0.4,
# joint_4=2.5, joint_6=2.0) and the MJCF arm of the tests (start at its reference), each fitted
# by `sphereset robot` (--budget B, default 60, for the Kinova; 4 spheres per link for the arm)
# and written as an MJCF with sphere geoms. STEPS steps each (default 20000, 40 s of simulated
# time), one thread; the contacts are counted in a second, untimed run. Into
# bench/results/mujoco_step.csv and mujoco_step.png.
#   bash bench/mujoco_step.sh          STEPS=1000 bash bench/mujoco_step.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
bench_program mujoco_step
steps=${STEPS:-20000}
budget=${BUDGET:-60}
out=${OUT:-bench/results/mujoco_step.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
build/bench/mujoco_step --header >"$out"

arm=tests/data/robot/mjcf/arm.xml
build/apps/sphereset robot "$arm" --default-link-spheres 4 -o "$tmp/arm_spheres.xml" -q
build/bench/mujoco_step test_arm "$arm" "$tmp/arm_spheres.xml" "$steps" 0.75 0.32 >>"$out"

root=${ROBOT_ROOT:-../shared/robots/kinova_gen3}
urdf=$root/kortex_description/arms/gen3/7dof/urdf/GEN3-7DOF-VISION_ARM_URDF_V12.urdf
if [ -f "$urdf" ]; then
  build/bench/mujoco_step --mesh-model "$urdf" "$root" "$tmp/kinova_meshes.xml"
  build/apps/sphereset robot "$urdf" --package-path "$root" --budget "$budget" \
    -o "$tmp/kinova_spheres.xml" -q
  build/bench/mujoco_step kinova_gen3 "$tmp/kinova_meshes.xml" "$tmp/kinova_spheres.xml" \
    "$steps" 0.55 0.3 joint_2=0.4,joint_4=2.5,joint_6=2.0 >>"$out"
else
  echo "mujoco_step: the Kinova Gen3 skipped, $urdf is absent" >&2
fi
cat "$out"
/usr/bin/python3 - "$out" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1])))
robots = sorted({r["robot"] for r in rows})
fig, ax = plt.subplots(figsize=(6, 3.2))
width = 0.38
for k, model in enumerate(["meshes", "spheres"]):
    ys = [float(next(r for r in rows if r["robot"] == rb and r["model"] == model)["us_per_step"])
          for rb in robots]
    ax.bar([i + (k - 0.5) * width for i in range(len(robots))], ys, width, label=model)
for rb in robots:
    pair = {r["model"]: float(r["us_per_step"]) for r in rows if r["robot"] == rb}
    col = {r["model"]: float(r["collision_us_per_step"]) for r in rows if r["robot"] == rb}
    print(f"{rb}: spheres / meshes, time per step {pair['spheres'] / pair['meshes']:.3f}, "
          f"collision detection {col['spheres'] / col['meshes']:.3f}")
ax.set_xticks(range(len(robots)), robots)
ax.set_ylabel("µs per mj_step")
ax.set_title("mj_step: sphere model against mesh model (1 thread)")
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[1].replace(".csv", ".png"), dpi=120)
PY

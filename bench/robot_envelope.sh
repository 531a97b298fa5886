#!/usr/bin/env bash
# Link envelopes against walls on the Kinova Gen3 (../shared/robots/kinova_gen3): the whole
# robot fitted with --link-solid walls (the fit before envelopes) and with --link-solid envelope
# (the default), at budgets 30 and 60, seeds 1 to 3, default quality. Each link's spheres of
# both fits are measured against the link's envelope and its walls by `sphereset eval --link
# --fill-openings auto` on the link's collision mesh (which the URDF places at the link origin
# unscaled, so the envelope is the one the robot command fits). Per row: E_r and outside volume
# against the envelope and against the walls, the fit's own coverage certificates, and the
# robot command's wall time. Into bench/results/robot_envelope.csv, with a summary on stdout.
#   bash bench/robot_envelope.sh         BUDGETS="60" SEEDS="1" bash bench/robot_envelope.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
root=../shared/robots/kinova_gen3
urdf=$root/kortex_description/arms/gen3/7dof/urdf/GEN3-7DOF-VISION_ARM_URDF_V12.urdf
meshes=$root/kortex_description/arms/gen3/7dof/meshes
links=(base_link shoulder_link half_arm_1_link half_arm_2_link forearm_link
       spherical_wrist_1_link spherical_wrist_2_link bracelet_link)
files=(base_link shoulder_link half_arm_1_link half_arm_2_link forearm_link
       spherical_wrist_1_link spherical_wrist_2_link bracelet_with_vision_link)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=${OUT:-bench/results/robot_envelope.csv}
echo "budget,seed,fit,wall_s,link,spheres,covered,envelope_volume,walls_volume,er_envelope,er_walls,outside_envelope,outside_walls" >"$out.tmp"
for budget in ${BUDGETS:-30 60}; do
  for seed in ${SEEDS:-1 2 3}; do
    for fit in walls envelope; do
      run=$tmp/${fit}_${budget}_$seed
      start=$(date +%s.%N)
      build/apps/sphereset robot "$urdf" --package-path "$root" --budget "$budget" --seed "$seed" \
        --link-solid "$fit" -o "$run.yml" --json -q >"$run.json"
      wall=$(echo "$(date +%s.%N) - $start" | bc)
      for i in "${!links[@]}"; do
        build/apps/sphereset eval "$meshes/${files[$i]}.STL" "$run.yml" --link "${links[$i]}" \
          --fill-openings auto --json --samples 0 --segments 0 --shadow-resolution 0 \
          >"$run.${links[$i]}.json"
      done
      python3 - "$budget" "$seed" "$fit" "$wall" "$run" "${links[@]}" >>"$out.tmp" <<'PY'
import json, sys
budget, seed, fit, wall, run = sys.argv[1:6]
robot = {l["link"]: l for l in json.load(open(run + ".json"))["links"]}
for link in sys.argv[6:]:
    e = json.load(open("%s.%s.json" % (run, link)))
    print(",".join(str(x) for x in [
        budget, seed, fit, "%.2f" % float(wall), link, robot[link]["count"], robot[link]["covered"],
        "%.6g" % e["mesh_volume"], "%.6g" % e["walls_volume"], "%.4f" % e["er_sum"],
        "%.4f" % e["er_walls"], "%.6g" % (e["er_sum"] * e["mesh_volume"]),
        "%.6g" % (e["er_walls"] * e["walls_volume"])]))
PY
    done
  done
done
mv "$out.tmp" "$out"
python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
budgets = sorted({int(r["budget"]) for r in rows})
seeds = sorted({r["seed"] for r in rows})
links = list(dict.fromkeys(r["link"] for r in rows))
def pick(budget, fit, seed=None, link=None):
    return [r for r in rows if int(r["budget"]) == budget and r["fit"] == fit and
            (seed is None or r["seed"] == seed) and (link is None or r["link"] == link)]
print("Outside volume against each link's envelope (cm^3), mean over seeds %s" % ",".join(seeds))
for b in budgets:
    print("\nbudget %d" % b)
    print("%-24s %14s %14s %8s %12s %12s" % ("link", "walls fit", "envelope fit", "ratio",
                                              "E_r env (w)", "E_r env (e)"))
    for link in links:
        w = statistics.mean(float(r["outside_envelope"]) for r in pick(b, "walls", link=link))
        e = statistics.mean(float(r["outside_envelope"]) for r in pick(b, "envelope", link=link))
        ew = statistics.mean(float(r["er_envelope"]) for r in pick(b, "walls", link=link))
        ee = statistics.mean(float(r["er_envelope"]) for r in pick(b, "envelope", link=link))
        print("%-24s %14.2f %14.2f %8.3f %12.3f %12.3f" % (link, w * 1e6, e * 1e6, e / w, ew, ee))
    for s in seeds:
        w, e = pick(b, "walls", s), pick(b, "envelope", s)
        tw = sum(float(r["outside_envelope"]) for r in w)
        te = sum(float(r["outside_envelope"]) for r in e)
        print("seed %s: total %.2f -> %.2f cm^3 (ratio %.3f); spheres %d -> %d; time %s -> %s s; "
              "every link covered: %s" % (s, tw * 1e6, te * 1e6, te / tw,
                                           sum(int(r["spheres"]) for r in w),
                                           sum(int(r["spheres"]) for r in e), w[0]["wall_s"],
                                           e[0]["wall_s"],
                                           all(r["covered"] == "True" for r in w + e)))
PY

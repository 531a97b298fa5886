#!/usr/bin/env bash
# Link envelopes against walls on the Kinova Gen3 (../shared/robots/kinova_gen3): the whole
# robot fitted with --link-solid walls (the fit before envelopes) and with --link-solid envelope
# (the default), at budgets 30 and 60, seeds 1 to 3, default quality. Each link's spheres of
# both fits are measured against the link's envelope and its walls by `sphereset eval --link
# --fill-openings auto` on the link's collision mesh (which the URDF places at the link origin
# unscaled, so the envelope is the one the robot command fits). Per row: E_r and outside volume
# against the envelope and against the walls, the fit's own coverage certificates, and the
# robot command's wall time. Into bench/results/robot_envelope.csv, with a summary on stdout.
# BASELINE=PATH adds a third fit, "today": the robot command of another build (an earlier
# commit's, whose only link solid is the walls), run side by side in the same session.
# WALLS_LINKS="LINK ..." adds a fit "chosen": the default with --link-solid-for LINK=walls for
# those links, which every fit is then measured against as walls.
#   bash bench/robot_envelope.sh         BUDGETS="60" SEEDS="1" bash bench/robot_envelope.sh
#   git worktree add /tmp/base COMMIT && cmake -S /tmp/base -B /tmp/base/build && \
#     cmake --build /tmp/base/build --target sphereset_cli && \
#     BASELINE=/tmp/base/build/apps/sphereset bash bench/robot_envelope.sh
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
    for fit in ${BASELINE:+today} walls envelope ${WALLS_LINKS:+chosen}; do
      run=$tmp/${fit}_${budget}_$seed
      cli=(build/apps/sphereset) solid=(--link-solid "$fit")
      [ "$fit" = today ] && cli=("$BASELINE") solid=()
      if [ "$fit" = chosen ]; then
        solid=()
        for l in $WALLS_LINKS; do solid+=(--link-solid-for "$l=walls"); done
      fi
      start=$(date +%s.%N)
      "${cli[@]}" robot "$urdf" --package-path "$root" --budget "$budget" --seed "$seed" \
        "${solid[@]}" -o "$run.yml" --json -q >"$run.json"
      wall=$(echo "$(date +%s.%N) - $start" | bc)
      for i in "${!links[@]}"; do
        openings=(--fill-openings auto)
        for l in ${WALLS_LINKS:-}; do [ "$l" = "${links[$i]}" ] && openings=(); done
        build/apps/sphereset eval "$meshes/${files[$i]}.STL" "$run.yml" --link "${links[$i]}" \
          "${openings[@]}" --json --samples 0 --segments 0 --shadow-resolution 0 \
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
[ -z "${WALLS_LINKS:-}" ] || echo "$WALLS_LINKS: measured against the walls in every fit"
python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
budgets = sorted({int(r["budget"]) for r in rows})
seeds = sorted({r["seed"] for r in rows})
links = list(dict.fromkeys(r["link"] for r in rows))
fits = list(dict.fromkeys(r["fit"] for r in rows))
def pick(budget, fit, seed=None, link=None):
    return [r for r in rows if int(r["budget"]) == budget and r["fit"] == fit and
            (seed is None or r["seed"] == seed) and (link is None or r["link"] == link)]
def mean(budget, fit, key, link=None, seed=None, total=False):
    sel = pick(budget, fit, seed, link)
    if total:
        return statistics.mean(sum(float(r[key]) for r in pick(budget, fit, s)) for s in seeds)
    return statistics.mean(float(r[key]) for r in sel)
print("Outside volume against each link's envelope (cm^3), mean over seeds %s; ratios to %s"
      % (",".join(seeds), fits[0]))
for b in budgets:
    print("\nbudget %d" % b)
    print("%-24s" % "link" + "".join(" %12s" % f for f in fits) +
          "".join(" %9s" % ("/" + fits[0])[:9] for f in fits[1:]) +
          "".join(" %9s" % ("E_r " + f)[:9] for f in fits))
    for link in links + ["total"]:
        if link == "total":
            v = [mean(b, f, "outside_envelope", total=True) for f in fits]
            e = [float("nan")] * len(fits)
        else:
            v = [mean(b, f, "outside_envelope", link) for f in fits]
            e = [mean(b, f, "er_envelope", link) for f in fits]
        print("%-24s" % link + "".join(" %12.2f" % (x * 1e6) for x in v) +
              "".join(" %9.3f" % (x / v[0]) for x in v[1:]) + "".join(" %9.3f" % x for x in e))
    for f in fits:
        t = [float(pick(b, f, s)[0]["wall_s"]) for s in seeds]
        print("%-9s time %s s (mean %.1f), spheres %s, every link covered: %s" % (
            f, " ".join("%.1f" % x for x in t), statistics.mean(t),
            " ".join(str(sum(int(r["spheres"]) for r in pick(b, f, s))) for s in seeds),
            all(r["covered"] == "True" for r in pick(b, f))))
PY

#!/usr/bin/env bash
# Runs the same commands with two builds of sphereset and compares every file they write, byte
# for byte, and what they print (times removed): the check that a change which should not
# change results does not. About 60 commands on the benchmark meshes (fits with every method
# and quality, decimation, trees, eval, check, export, query, render); a few minutes.
#   bash bench/same_outputs.sh OLD_SPHERESET NEW_SPHERESET [--mesh-dir DIR] [--out DIR]
# Exit status 0 when everything is the same, 1 otherwise (the differing files are listed).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
old=$(realpath "$1")
new=$(realpath "$2")
shift 2
mesh_dir="$here/../../shared/meshes"
out=${TMPDIR:-/tmp}/sphereset-same-outputs
while (($#)); do
  case $1 in
    --mesh-dir) mesh_dir=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "same_outputs.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
M=$(realpath "$mesh_dir")

# Every command runs inside the build's own folder with relative output names, so that what
# the two builds print names the same files.
run_all() {
  local bin=$1 dir=$2
  rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
  run() { local name=$1; shift; "$bin" "$@" > "$name.stdout" 2> "$name.stderr" || true; }
  local m s
  for m in organic/spot.obj organic/decimated-knight.off organic/fertility.off cad/fandisk.obj \
    cad/plate_holes_trimesh.stl cad/rocker-arm.obj robot/fr3_link1_collision.stl \
    robot/ur5_upperarm_collision.stl organic/bunny_hr_oded.obj organic/armadillo_libigl.obj; do
    s=$(basename "${m%.*}")
    run "fit_${s}_32" fit --quiet "$M/$m" -n 32 -o "${s}_32.txt"
    run "fit_${s}_8km" fit --quiet "$M/$m" -n 8 --method kmeans -o "${s}_8km.txt"
    run "fit_${s}_8oc" fit --quiet "$M/$m" -n 8 --method octree -o "${s}_8oc.txt"
  done
  for m in organic/spot.obj cad/fandisk.obj organic/decimated-knight.off; do
    s=$(basename "${m%.*}")
    run "fit_${s}_16dec" fit --quiet "$M/$m" -n 16 --decimation 0.5 -o "${s}_16dec.txt"
    run "fit_${s}_12best" fit --quiet "$M/$m" -n 12 --quality best -o "${s}_12best.json"
    run "fit_${s}_20fast" fit --quiet "$M/$m" -n 20 --quality fast --seed 3 --init random \
      -o "${s}_20fast.sph"
    run "fit_${s}_10grad" fit --quiet "$M/$m" -n 10 --optimizer gradient --padding 0.01 \
      -o "${s}_10grad.yaml"
    run "tree_${s}" tree --quiet "$M/$m" --branch 4 --depth 2 -o "${s}_tree.sph"
    run "treeo_${s}" tree --quiet "$M/$m" --branch 3 --depth 2 --parents outside \
      -o "${s}_treeo.json"
  done
  run fit_spot_128 fit --quiet "$M/organic/spot.obj" -n 128 -o spot_128.txt
  run fit_dragon_16 fit --quiet "$M/big/dragon_vrip_bin.ply" -n 16 --quality fast -o dragon_16.txt
  run fit_iiwa fit --quiet "$M/robot/iiwa14_link3_collision.stl" -n 8 --weld-tolerance 1e-4 \
    -o iiwa_8.txt
  run eval_spot eval "$M/organic/spot.obj" spot_32.txt --json
  run eval_fandisk eval "$M/cad/fandisk.obj" fandisk_32.txt --json
  for m in defect/chair_model_trimesh.obj defect/blobby-shuffled_cgal.off defect/stanford-bunny.obj; do
    run "check_$(basename "${m%.*}")" check "$M/$m" --json
  done
  run export_spot export spot_32.txt -o spot_32.ply
  run export_spotg export spot_32.txt -o spot_32.glb
  run query_spot query spot_32.txt --point 0,0,0 --segment 0,0,0,1,1,1 --other spot_128.txt \
    --pose 0.1,0,0,1,0,0,0 --json
  run render_spot render "$M/organic/spot.obj" spot_32.txt -o spot_32.png --size 320x240
}

echo "same_outputs: running $old" >&2
(run_all "$old" "$out/old")
echo "same_outputs: running $new" >&2
(run_all "$new" "$out/new")

# Times are the one thing allowed to differ in what is printed: JSON time fields and the
# "(1.86 s)" that repair notes end with.
strip_times() {
  sed -E -e 's/"(seconds|time|total|sampling|assignment|update|teleport|bounding)":[-0-9.e]+//g' \
    -e 's/\([0-9.]+ s\)//g' "$1"
}
same=0 differ=0
for f in "$out"/old/*; do
  b=$(basename "$f")
  case $b in *.stderr) continue ;; esac
  g="$out/new/$b"
  if [[ $b == *.stdout ]]; then
    if [ -f "$g" ] && cmp -s <(strip_times "$f") <(strip_times "$g"); then ok=1; else ok=0; fi
  else
    if cmp -s "$f" "$g"; then ok=1; else ok=0; fi
  fi
  if ((ok)); then same=$((same + 1)); else differ=$((differ + 1)); echo "differs: $b"; fi
done
echo "same_outputs: $same files the same, $differ different ($out)"
((differ == 0))

#!/usr/bin/env bash
# Curves of E_r and certified protrusion against the sphere count, each from one progressive run
# (bench/progressive_curve.cpp --only-progressive --protrusion): four shared meshes at n = 1 ...
# 64 and the Kinova Gen3's links (each made a solid as `sphereset fit` makes it) at n = 1 ... 32.
# Into bench/results/progressive_curves.csv (OUT), plotted by bench/progressive_plot.py into
# progressive_curves_meshes.png and progressive_curves_kinova.png beside it.
#   bash bench/progressive_curves.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
skip_without_shared progressive_curves
bench_program progressive_curve
out=${OUT:-bench/results/progressive_curves.csv}
mesh_counts=1,2,3,4,6,8,12,16,24,32,48,64
link_counts=1,2,3,4,6,8,12,16,24,32
echo "group,$(build/bench/progressive_curve --header)" >"$out"
for m in organic/spot.obj cad/fandisk.obj organic/armadillo_libigl.obj cad/rocker-arm.obj; do
  echo "progressive_curves: $m" >&2
  build/bench/progressive_curve "$shared/meshes/$m" --counts "$mesh_counts" --only-progressive \
    --protrusion | sed 's/^/meshes,/' >>"$out"
done
links=$shared/robots/kinova_gen3/kortex_description/arms/gen3/7dof/meshes
for link in base_link shoulder_link half_arm_1_link half_arm_2_link forearm_link \
            spherical_wrist_1_link spherical_wrist_2_link bracelet_with_vision_link; do
  echo "progressive_curves: $link" >&2
  build/bench/progressive_curve "$links/$link.STL" --counts "$link_counts" --only-progressive \
    --protrusion --repair | sed 's/^/kinova,/' >>"$out"
done
/usr/bin/python3 bench/progressive_plot.py "$out"

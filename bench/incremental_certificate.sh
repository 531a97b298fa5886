#!/usr/bin/env bash
# The incremental coverage certificate (certificate.hpp) against the full evaluation's
# certificate, per hand edit: for the armadillo (86k triangles) and four Kinova Gen3 links, a
# set of n = 64 fitted by `sphereset fit` (default options), then 30 seeded successive
# single-sphere edits (centre moved by up to a quarter of the radius, radius scaled by 0.9 to
# 1.1), each timed through CoverageCertificate::setSphere and through evaluateSpheres with the
# same depths and the certificates only (bench/certificate_table.cpp). One row per mesh into
# bench/results/incremental_certificate.csv, one per edit into
# bench/results/incremental_certificate_edits.csv. Skipped when ../shared is absent.
#   bash bench/incremental_certificate.sh          (N=64 EDITS=30 SHARED=../shared OUT=...)
set -euo pipefail
cd "$(dirname "$0")/.."
args=()
source bench/common.sh
skip_without_shared incremental_certificate.sh
bench_program certificate_table
n=${N:-64}
edits=${EDITS:-30}
out=${OUT:-bench/results/incremental_certificate.csv}
edit_out=${out%.csv}_edits.csv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
meshes=("$shared/meshes/organic/armadillo_libigl.obj")
kinova=$shared/robots/kinova_gen3/kortex_description/arms/gen3/7dof/meshes
for link in shoulder_link half_arm_1_link forearm_link bracelet_with_vision_link; do
  if [ -f "$kinova/$link.STL" ]; then meshes+=("$kinova/$link.STL"); fi
done
build/bench/certificate_table --header >"$out"
build/bench/certificate_table --edit-header >"$edit_out"
for mesh in "${meshes[@]}"; do
  set_file="$tmp/$(basename "${mesh%.*}").txt"
  build/apps/sphereset fit "$mesh" -n "$n" -o "$set_file" -q
  build/bench/certificate_table "$mesh" "$set_file" --edits "$edits" --per-edit "$edit_out" \
    >>"$out"
done
cat "$out"

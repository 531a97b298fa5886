#!/usr/bin/env bash
# Progressive fitting against independent fits (bench/progressive_curve.cpp) on the closed
# meshes of ../shared/meshes (or the meshes given): E_r of each at n = 8, 16, 32, 64 (COUNTS),
# the time of one progressive run through them against one independent fit at the largest, for
# each seed of SEEDS (1), into bench/results/progressive.csv (OUT), summarised by
# bench/progressive_summary.py (geometric means of the E_r ratios over meshes and seeds, the
# spread of independent fits between seeds, time ratios) into progressive_summary.txt beside it.
#   bash bench/progressive_table.sh            COUNTS=8,16,32 bash bench/progressive_table.sh MESH
#   SEEDS="1 2 3" bash bench/progressive_table.sh
set -euo pipefail
args=("$@")
source "$(dirname "$0")/common.sh"
bench_program progressive_curve
out=${OUT:-bench/results/progressive.csv}
counts=${COUNTS:-8,16,32,64}
if [ ${#args[@]} -eq 0 ]; then
  skip_without_shared progressive_table
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  link_closed_meshes "$shared/meshes" "$tmp/closed"
  mapfile -t meshes < <(find "$tmp/closed" -type l | sort)
else
  meshes=("${args[@]}")
fi
build/bench/progressive_curve --header >"$out"
for seed in ${SEEDS:-1}; do
  for mesh in "${meshes[@]}"; do
    echo "progressive_table: $mesh, seed $seed" >&2
    build/bench/progressive_curve "$mesh" --counts "$counts" --seed "$seed" \
      ${PROTRUSION:+--protrusion} >>"$out"
  done
done
/usr/bin/python3 bench/progressive_summary.py "$out" | tee "${out%.csv}_summary.txt"

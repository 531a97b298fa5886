#!/usr/bin/env bash
# The whole curve against one fit: on four shared meshes, `sphereset fit MESH -n 64` and
# `sphereset curve MESH --max-spheres 64` (every count 1 ... 64 from one progressive run, the
# counts between powers of two stepped: evaluate.hpp, fitCurve), timed one after the other, and
# independent fits at the stretches' middles (12, 24, 48) against the curve's sets there.
# Into bench/results/curve_table.csv (OUT): mesh, fit and curve seconds (wall clock, the check
# included in both), their ratio; where the curve's time goes (from its CSV's per-count seconds,
# each count's making and check): the fitted counts (1, 2, 4, ... 64), the fitted counts from 8
# up (the four the curve must match independent fits at), the stepped counts kept, and the rest
# of the command (loading, repair, index, the run's points, the steps of the direction not kept,
# writing); then E_r curve / independent at 12, 24, 48 and 64.
#   bash bench/curve_table.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
skip_without_shared curve_table
out=${OUT:-bench/results/curve_table.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
exe=build/apps/sphereset
er() { /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['er_sum'])"; }
echo "mesh,fit64_s,curve_s,ratio,fitted_s,fitted_8_up_s,stepped_s,rest_s,er12_curve,er12_fit,er24_curve,er24_fit,er48_curve,er48_fit,er64_curve,er64_fit" >"$out"
for m in organic/spot.obj cad/fandisk.obj organic/armadillo_libigl.obj cad/rocker-arm.obj; do
  echo "curve_table: $m" >&2
  mesh=$shared/meshes/$m
  tf=$(wall_seconds /dev/null "$exe" fit "$mesh" -n 64 -o "$tmp/f64.sph" -q)
  tc=$(wall_seconds /dev/null "$exe" curve "$mesh" --max-spheres 64 -o "$tmp/curve.csv" -q)
  row="$(basename "$m"),$tf,$tc,$(/usr/bin/python3 -c "print(round($tc / $tf, 3))")"
  row="$row,$(/usr/bin/python3 - "$tmp/curve.csv" "$tc" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
last = max(int(r["n"]) for r in rows)
fitted = lambda n: n & (n - 1) == 0 or n == last
s = lambda keep: sum(float(r["seconds"]) for r in rows if keep(int(r["n"])))
a, b, c = s(fitted), s(lambda n: fitted(n) and n >= 8), s(lambda n: not fitted(n))
print(f"{a:.3f},{b:.3f},{c:.3f},{float(sys.argv[2]) - a - c:.3f}")
EOF
)"
  for n in 12 24 48 64; do
    c=$(awk -F, -v n="$n" 'NR > 1 && $1 == n { print $2 }' "$tmp/curve.csv")
    f=$("$exe" fit "$mesh" -n "$n" -o "$tmp/f.sph" -q --json | er)
    row="$row,$c,$f"
  done
  echo "$row" >>"$out"
done
cat "$out"

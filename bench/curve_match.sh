#!/usr/bin/env bash
# The whole curve against independent fits: on the closed meshes of ../shared/meshes (or the
# meshes given), `sphereset curve MESH --max-spheres 64` (every count 1 ... 64 from one run) and
# `sphereset fit MESH -n N` for N in COUNTS (8 16 32 64), for each seed of SEEDS (1): E_r of the
# curve's set and of the independent fit at each N, and the wall seconds of the curve and of that
# fit, into bench/results/curve_match.csv (OUT); then the geometric means over the meshes
# and seeds of E_r curve / independent per count, of the time ratio, and of the independent
# fits below 64 over the fit at 64 (what fitting those counts costs), printed and written to
# curve_match_summary.txt beside it.
#   bash bench/curve_match.sh            SEEDS="1 2" bash bench/curve_match.sh
set -euo pipefail
args=("$@")
source "$(dirname "$0")/common.sh"
out=${OUT:-bench/results/curve_match.csv}
counts=${COUNTS:-8 16 32 64}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ ${#args[@]} -eq 0 ]; then
  skip_without_shared curve_match
  link_closed_meshes "$shared/meshes" "$tmp/closed"
  mapfile -t meshes < <(find "$tmp/closed" -type l | sort)
else
  meshes=("${args[@]}")
fi
exe=build/apps/sphereset
mkdir -p "$(dirname "$out")"
echo "mesh,seed,n,er_curve,er_fit,curve_s,fit_s" >"$out"
for seed in ${SEEDS:-1}; do
  for mesh in "${meshes[@]}"; do
    echo "curve_match: $mesh, seed $seed" >&2
    tc=$(wall_seconds /dev/null "$exe" curve "$mesh" --max-spheres 64 --seed "$seed" \
      -o "$tmp/curve.csv" -q)
    for n in $counts; do
      tf=$(wall_seconds "$tmp/fit.json" "$exe" fit "$mesh" -n "$n" --seed "$seed" -o "$tmp/f.json" \
        -q --json)
      f=$(/usr/bin/python3 -c "import json; print(json.load(open('$tmp/fit.json'))['er_sum'])")
      c=$(awk -F, -v n="$n" 'NR > 1 && $1 == n { print $2 }' "$tmp/curve.csv")
      [ -n "$c" ] || { echo "curve_match: the curve has no count $n (1 to 64)" >&2; exit 2; }
      echo "$(basename "$mesh"),$seed,$n,$c,$f,$tc,$tf" >>"$out"
    done
  done
done
/usr/bin/python3 - "$out" <<'PY' | tee "${out%.csv}_summary.txt"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
gm = lambda xs: math.exp(sum(math.log(x) for x in xs) / len(xs))
for n in sorted({int(r["n"]) for r in rows}):
    rs = [float(r["er_curve"]) / float(r["er_fit"]) for r in rows if int(r["n"]) == n]
    print(f"n = {n}: E_r curve / independent, geometric mean {gm(rs):.3f} "
          f"({min(rs):.3f} to {max(rs):.3f}, {len(rs)} fits)")
top = max(int(r["n"]) for r in rows)
ts = [float(r["curve_s"]) / float(r["fit_s"]) for r in rows if int(r["n"]) == top]
print(f"time: curve 1 ... 64 / fit at {top}, geometric mean {gm(ts):.3f} "
      f"({min(ts):.3f} to {max(ts):.3f})")
# What the counts below the top cost when each is fitted on its own: the independent fits'
# seconds summed over the top's (with the top itself, a floor for a curve that fits them).
fit_s = {}
for r in rows:
    fit_s.setdefault((r["mesh"], r["seed"]), {})[int(r["n"])] = float(r["fit_s"])
below = [sum(t for n, t in f.items() if n < top) / f[top] for f in fit_s.values()]
print(f"time: independent fits below {top} / fit at {top}, geometric mean {gm(below):.3f} "
      f"({min(below):.3f} to {max(below):.3f})")
PY

#!/usr/bin/env bash
# The envelope's volume over the walls' against the size of the openings it closes
# (`sphereset check MESH --fill-openings S --json`, S a fraction of the walls' bounding box's
# smallest extent), for the Kinova Gen3's links (../shared/robots/kinova_gen3, skipped when it
# is absent) and for prisms as tall as they are wide whose cross-section is a plus (arms 0.1,
# 0.2 and 0.3 of the width wide), which enclose no hollow. Into
# bench/results/envelope_sizes.csv (shape, fraction, size, ratio), with a table on stdout.
#   bash bench/envelope_sizes.sh        FRACTIONS="0.5 1" bash bench/envelope_sizes.sh
set -euo pipefail
args=()
source "$(dirname "$0")/common.sh"
fractions=(${FRACTIONS:-0.15 0.3 0.5 0.7 0.8 1})
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
shapes=()
meshes=../shared/robots/kinova_gen3/kortex_description/arms/gen3/7dof/meshes
if [ -d "$meshes" ]; then
  for link in base_link shoulder_link half_arm_1_link half_arm_2_link forearm_link \
    spherical_wrist_1_link spherical_wrist_2_link bracelet_with_vision_link; do
    shapes+=("$meshes/$link.STL")
  done
else
  echo "envelope_sizes: the Kinova Gen3 skipped, $meshes is absent" >&2
fi
for arm in 0.1 0.2 0.3; do
  python3 - "$arm" "$tmp/plus_$arm.obj" <<'PY'
import sys
# A unit prism whose cross-section is a plus with arms `arm` wide: 12 outline vertices at
# z = -0.5 and 0.5, caps made of the centre square and the four arms' rectangles.
h, e, path = float(sys.argv[1]) / 2, 0.5, sys.argv[2]
outline = [(h, -e), (h, -h), (e, -h), (e, h), (h, h), (h, e), (-h, e), (-h, h), (-e, h),
           (-e, -h), (-h, -h), (-h, -e)]
n = len(outline)
quads = [[1, 4, 7, 10], [11, 0, 1, 10], [1, 2, 3, 4], [4, 5, 6, 7], [7, 8, 9, 10]]
faces = []
for q in quads:
    for a, b, c in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
        faces += [(a + n, b + n, c + n), (c, b, a)]
for i in range(n):
    j = (i + 1) % n
    faces += [(i, j, j + n), (i, j + n, i + n)]
with open(path, "w") as f:
    for z in (-0.5, 0.5):
        for x, y in outline:
            f.write("v %g %g %g\n" % (x, y, z))
    for t in faces:
        f.write("f %d %d %d\n" % tuple(k + 1 for k in t))
PY
  shapes+=("$tmp/plus_$arm.obj")
done
out=bench/results/envelope_sizes.csv
echo "shape,fraction,size,ratio" >"$out.tmp"
for shape in "${shapes[@]}"; do
  extent=$(build/apps/sphereset check "$shape" --json | python3 -c \
    "import json, sys; d = json.load(sys.stdin); \
print(min(a - b for a, b in zip(d['bbox_max'], d['bbox_min'])))")
  for f in "${fractions[@]}"; do
    size=$(python3 -c "print($extent * $f)")
    build/apps/sphereset check "$shape" --fill-openings "$size" --json | python3 -c "
import json, sys
d = json.load(sys.stdin)
r = d['repair']
print('%s,%s,%.6g,%.4f' % (sys.argv[1], sys.argv[2], r['fill_openings'],
                           r['volume'] / r['walls_volume']))" "$(basename "$shape")" "$f" \
      >>"$out.tmp"
  done
done
mv "$out.tmp" "$out"
python3 - "$out" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
fractions = list(dict.fromkeys(r["fraction"] for r in rows))
print("envelope volume / walls volume, by size as a fraction of the smallest extent")
print("%-32s" % "shape" + "".join(" %6s" % f for f in fractions))
for shape in dict.fromkeys(r["shape"] for r in rows):
    print("%-32s" % shape + "".join(" %6.2f" % float(r["ratio"]) for r in rows
                                     if r["shape"] == shape))
PY

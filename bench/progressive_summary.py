"""Summary of bench/progressive_table.sh's CSV: per count and over all, the geometric mean of
progressive E_r over independent E_r; per mesh, the seconds of the progressive run through every
count over the seconds of one independent fit at the largest count, and their geometric mean.

    python3 bench/progressive_summary.py bench/results/progressive.csv
"""
import collections
import csv
import math
import sys


def geomean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values))


def main(path):
    rows = list(csv.DictReader(open(path)))
    fit = {(r["mesh"], r["method"], int(r["n"])): r for r in rows}
    meshes = sorted({r["mesh"] for r in rows})
    per_n = collections.defaultdict(list)
    time_ratio = {}
    for mesh in meshes:
        counts = sorted(n for (m, meth, n) in fit if m == mesh and meth == "independent")
        for n in counts:
            p = fit.get((mesh, "progressive", n))
            if p:
                per_n[n].append(float(p["er_sum"]) / float(fit[(mesh, "independent", n)]["er_sum"]))
        top = counts[-1]
        p = fit.get((mesh, "progressive", top))
        if p:
            time_ratio[mesh] = float(p["run_s"]) / float(fit[(mesh, "independent", top)]["fit_s"])
    every = [v for vs in per_n.values() for v in vs]
    print(f"meshes {len(meshes)}, cells {len(every)}")
    print("E_r progressive / independent, geometric mean: %.4f" % geomean(every))
    for n, vs in sorted(per_n.items()):
        print("  n = %d: %.4f (min %.3f, max %.3f)" % (n, geomean(vs), min(vs), max(vs)))
    print("time of the progressive run / one independent fit at the largest count:")
    for mesh, t in time_ratio.items():
        print("  %s: %.2f" % (mesh, t))
    print("  geometric mean %.2f, max %.2f" % (geomean(list(time_ratio.values())),
                                                max(time_ratio.values())))


if __name__ == "__main__":
    main(sys.argv[1])

"""Summary of bench/progressive_table.sh's CSV: per count and over all, the geometric mean of
progressive E_r over independent E_r (over every mesh and seed; per seed too); with several
seeds, how far independent fits of one mesh are from each other (the geometric mean over meshes
of the largest over the smallest E_r among the seeds, per count): the noise a ratio of single
fits carries; per mesh and seed, the seconds of the progressive run through every count over the
seconds of one independent fit at the largest count, and their geometric mean. Where the CSV
has the er_clustering column, the same ratio per count before the bound (the clustering's
outside volume over its sample points) and each method's growth through the bound (final E_r
over the clustering's): which of the two the gap at a count comes from.

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
    for r in rows:
        r.setdefault("seed", "1")
    fit = {(r["mesh"], r["seed"], r["method"], int(r["n"])): r for r in rows}
    runs = sorted({(r["mesh"], r["seed"]) for r in rows})
    seeds = sorted({r["seed"] for r in rows}, key=int)
    per_n = collections.defaultdict(list)
    per_seed_n = collections.defaultdict(list)
    clustering = collections.defaultdict(list)  # n -> progressive / independent, before bound
    growth = collections.defaultdict(list)  # (method, n) -> final E_r / clustering E_r
    time_ratio = {}
    for mesh, seed in runs:
        counts = sorted(n for (m, s, meth, n) in fit
                        if m == mesh and s == seed and meth == "independent")
        for n in counts:
            p = fit.get((mesh, seed, "progressive", n))
            if p:
                ratio = float(p["er_sum"]) / float(fit[(mesh, seed, "independent", n)]["er_sum"])
                per_n[n].append(ratio)
                per_seed_n[(seed, n)].append(ratio)
                i = fit[(mesh, seed, "independent", n)]
                if p.get("er_clustering") and i.get("er_clustering"):
                    clustering[n].append(float(p["er_clustering"]) / float(i["er_clustering"]))
                    for method, r in (("independent", i), ("progressive", p)):
                        growth[(method, n)].append(float(r["er_sum"]) /
                                                   float(r["er_clustering"]))
        top = counts[-1]
        p = fit.get((mesh, seed, "progressive", top))
        if p:
            time_ratio[(mesh, seed)] = (float(p["run_s"]) /
                                        float(fit[(mesh, seed, "independent", top)]["fit_s"]))
    every = [v for vs in per_n.values() for v in vs]
    meshes = sorted({m for m, _ in runs})
    print(f"meshes {len(meshes)}, seeds {' '.join(seeds)}, cells {len(every)}")
    print("E_r progressive / independent, geometric mean: %.4f" % geomean(every))
    for n, vs in sorted(per_n.items()):
        by_seed = ", ".join("seed %s %.4f" % (s, geomean(per_seed_n[(s, n)])) for s in seeds
                            if per_seed_n[(s, n)])
        print("  n = %d: %.4f (min %.3f, max %.3f; %s)" % (n, geomean(vs), min(vs), max(vs),
                                                           by_seed))
    if clustering:
        print("before the bound (clustering E_r), progressive / independent; growth through the "
              "bound (E_r / clustering E_r), independent and progressive:")
        for n, vs in sorted(clustering.items()):
            gi, gp = growth[("independent", n)], growth[("progressive", n)]
            print("  n = %d: %.4f (min %.3f, max %.3f); growth %.3f (%.3f to %.3f) and %.3f "
                  "(%.3f to %.3f)" % (n, geomean(vs), min(vs), max(vs), geomean(gi), min(gi),
                                      max(gi), geomean(gp), min(gp), max(gp)))
    if len(seeds) > 1:
        print("independent fits, largest / smallest E_r among the seeds, geometric mean over "
              "meshes:")
        for n in sorted(per_n):
            spread = []
            for mesh in meshes:
                ers = [float(fit[(mesh, s, "independent", n)]["er_sum"]) for s in seeds
                       if (mesh, s, "independent", n) in fit]
                if len(ers) > 1:
                    spread.append(max(ers) / min(ers))
            if spread:
                print("  n = %d: %.4f" % (n, geomean(spread)))
    print("time of the progressive run / one independent fit at the largest count:")
    for mesh in meshes:
        ts = [time_ratio[(mesh, s)] for s in seeds if (mesh, s) in time_ratio]
        print("  %s: %s" % (mesh, " ".join("%.2f" % t for t in ts)))
    print("  geometric mean %.2f, max %.2f" % (geomean(list(time_ratio.values())),
                                                max(time_ratio.values())))


if __name__ == "__main__":
    main(sys.argv[1])

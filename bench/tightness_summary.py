"""Summary of bench/tightness.sh's CSV: for each variant against `base:default` (the baseline's
default quality), per mesh and over everything, the geometric means of the E_r ratio and of the
wall-time ratio over the cells (n, seed) both ran, and each variant's bound overhead (E_r after
the bound over the clustering's own E_r; geometric mean and largest per mesh), and whether
every fit's certificates held.

    /usr/bin/python3 bench/tightness_summary.py bench/results/tightness.csv
"""
import collections
import csv
import math
import sys

BASELINE = "base:default"


def geomean(values):
    values = list(values)
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def ratios(cell, variant, keep):
    """E_r and wall-time ratios of `variant` to the baseline over the cells (mesh, n, seed)
    both ran and keep(mesh, n) accepts."""
    er, t = [], []
    for (m, n, seed, var), r in cell.items():
        b = cell.get((m, n, seed, BASELINE))
        if var != variant or b is None or not keep(m, n):
            continue
        er.append(float(r["er_sum"]) / float(b["er_sum"]))
        t.append(max(float(r["wall_s"]), 0.01) / max(float(b["wall_s"]), 0.01))
    return er, t


def main(path):
    rows = list(csv.DictReader(open(path)))
    cell = {(r["mesh"], r["n"], r["seed"], r["variant"]): r for r in rows}
    variants = list(dict.fromkeys(r["variant"] for r in rows))
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))
    others = [v for v in variants if v != BASELINE]
    print("E_r and time ratios against %s (geometric means over n and seeds); bound overhead "
          "= E_r after the bound / E_r of the clustering (geometric mean, largest)" % BASELINE)
    header = "%-28s" % "mesh" + "".join("%26s" % (v + " er/time") for v in others)
    header += "".join("%22s" % (v + " overhead") for v in variants)
    print(header)
    everything = collections.defaultdict(lambda: ([], []))
    for mesh in meshes:
        line = "%-28s" % mesh
        for v in others:
            er, t = ratios(cell, v, lambda m, n: m == mesh)
            everything[v][0].extend(er)
            everything[v][1].extend(t)
            line += "%26s" % ("%.3f / %.3f" % (geomean(er), geomean(t)))
        for v in variants:
            over = [float(r["er_sum"]) / float(r["er_before_bounding"])
                    for (m, _, _, var), r in cell.items()
                    if m == mesh and var == v and float(r["er_before_bounding"]) > 0]
            line += "%22s" % ("%.3f, %.3f" % (geomean(over), max(over, default=float("nan"))))
        print(line)
    line = "%-28s" % "all"
    for v in others:
        er, t = everything[v]
        line += "%26s" % ("%.3f / %.3f" % (geomean(er), geomean(t)))
    print(line)
    # Per n, over every mesh and seed.
    for n in sorted({r["n"] for r in rows}, key=int):
        line = "%-28s" % ("n = " + n)
        for v in others:
            er, t = ratios(cell, v, lambda m, n_, n=n: n_ == n)
            line += "%26s" % ("%.3f / %.3f" % (geomean(er), geomean(t)))
        print(line)
    # Absolute wall times of the cells with a target of their own (mean over seeds).
    for stem, n in (("armadillo", "64"), ("dragon", "128")):
        parts = []
        for v in variants:
            runs = [r for r in rows if stem in r["mesh"] and r["n"] == n and r["variant"] == v]
            if runs:
                parts.append("%s %.2f s (E_r %.3f)" % (
                    v, sum(float(r["wall_s"]) for r in runs) / len(runs),
                    sum(float(r["er_sum"]) for r in runs) / len(runs)))
        if parts:
            print("%s n = %s, mean wall time: %s" % (stem, n, "; ".join(parts)))
    # The bounding step's share of the wall time and the peak memory, per variant: the largest
    # over the fits (and where), for the targets (share <= 25 %, peak < 150 MB).
    for v in variants:
        fits = [r for r in rows if r["variant"] == v and r.get("bounding_s")]
        if not fits:
            continue
        share = max(fits, key=lambda r: float(r["bounding_s"]) / max(float(r["wall_s"]), 0.01))
        peak = max(fits, key=lambda r: int(r["peak_kb"]))
        print("%s: bounding share of wall time: geomean %.2f, largest %.2f (%s n=%s); peak memory "
              "largest %.0f MB (%s n=%s)" % (
                  v, geomean(max(float(r["bounding_s"]), 1e-3) / max(float(r["wall_s"]), 0.01)
                             for r in fits),
                  float(share["bounding_s"]) / max(float(share["wall_s"]), 0.01), share["mesh"],
                  share["n"], int(peak["peak_kb"]) / 1024.0, peak["mesh"], peak["n"]))
    for v in variants:
        fits = [r for r in rows if r["variant"] == v]
        uncovered = [r for r in fits if r.get("covered", "True") != "True"]
        print("%s: %d fits, %s" % (v, len(fits), "every one covered" if not uncovered else
                                   "NOT covered: " + ", ".join("%s n=%s seed %s" % (
                                       r["mesh"], r["n"], r["seed"]) for r in uncovered)))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "bench/results/tightness.csv")

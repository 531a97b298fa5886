"""Plots of bench/progressive_curves.sh's CSV: per group (the shared meshes, the Kinova links),
E_r and the certified protrusion (a fraction of the bounding-box diagonal) against the sphere
count, one line per mesh, log-log, into PREFIX_meshes.png and PREFIX_kinova.png beside the CSV.

    python3 bench/progressive_plot.py bench/results/progressive_curves.csv
"""
import collections
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path):
    rows = list(csv.DictReader(open(path)))
    groups = collections.defaultdict(lambda: collections.defaultdict(list))
    for r in rows:
        groups[r["group"]][r["mesh"]].append((int(r["n"]), float(r["er_sum"]),
                                              float(r["protrusion_of_diagonal"])))
    base = os.path.splitext(path)[0]
    for group, meshes in groups.items():
        fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
        for mesh, pts in sorted(meshes.items()):
            pts.sort()
            n = [p[0] for p in pts]
            a.plot(n, [p[1] for p in pts], marker="o", ms=3, label=mesh)
            b.plot(n, [p[2] for p in pts], marker="o", ms=3, label=mesh)
        for ax, label in ((a, "E_r (outside volume / volume)"),
                          (b, "certified protrusion / diagonal")):
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.set_xlabel("spheres")
            ax.set_ylabel(label)
            ax.grid(True, which="both", alpha=0.3)
        a.legend(fontsize=7)
        fig.suptitle(f"One progressive run per mesh ({group})")
        fig.tight_layout()
        out = f"{base}_{group}.png"
        fig.savefig(out, dpi=110)
        print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1])

"""The paper's evaluation (Sec. 7) for every fitting method: E_r, time, proximity and shadow
error against the number of spheres, over a set of closed meshes. Writes suite.csv and four
PNG plots (the paper's Figs. 17, 9, 13 and 11) into the output directory.

    bash bench/suite.sh [--quick] [--out DIR] [--n 8,16,...] [--methods ...] [MESH ...]

Default meshes: every closed solid in ../shared/meshes (found with `sphereset check`);
--quick: the two small meshes bundled with the project, n = 8 and 16 (for CI).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLI = os.path.join(ROOT, "build", "apps", "sphereset")
FIELDS = ["mesh", "triangles", "method", "n", "er_sum", "er_union", "surface_covered",
          "interior_covered", "proximity_error", "shadow_error_sky", "shadow_error_lights",
          "wall_s", "peak_mb", "sov_queries"]


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def up_axis(path):
    # Robot links are modelled z-up (ROS); the other meshes y-up.
    return "z" if "/robot/" in path or path.endswith(".stl") else "y"


def closed_meshes(root):
    found = []
    for dirpath, _, files in os.walk(root):
        for f in sorted(files):
            if f.endswith((".tsv", ".md", ".txt", ".json")):
                continue
            path = os.path.join(dirpath, f)
            r = subprocess.run([CLI, "check", path, "--json"], capture_output=True, text=True)
            if r.returncode == 0 and json.loads(r.stdout).get("solid"):
                found.append(path)
    return sorted(found)


def fit_and_eval(mesh, method, n, seed, tmp):
    out = os.path.join(tmp, "spheres.json")
    timing = os.path.join(tmp, "time")
    summary = run(["/usr/bin/time", "-f", "%e %M", "-o", timing, CLI, "fit", mesh, "-n", str(n),
                   "--method", method, "--seed", str(seed), "-o", out, "-q", "--json"])
    s = json.loads(summary)
    wall, peak_kb = open(timing).read().split()[-2:]
    e = json.loads(run([CLI, "eval", mesh, out, "--json", "--seed", str(seed), "--samples", "0",
                        "--segments", "1000", "--up", up_axis(mesh)]))
    return {"er_sum": s["er_sum"], "er_union": s["er_union"],
            "surface_covered": s["surface_covered"], "interior_covered": s["interior_covered"],
            "proximity_error": e["proximity_error"], "shadow_error_sky": e["shadow_error_sky"],
            "shadow_error_lights": e["shadow_error_lights"], "wall_s": float(wall),
            "peak_mb": int(peak_kb) / 1024.0, "sov_queries": s["sov_queries"]}


def plot(rows, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    meshes = sorted({r["mesh"] for r in rows})
    methods = sorted({r["method"] for r in rows}, key=["variational", "kmeans", "octree"].index)
    figures = [("er_sum", "E_r (summed)", "er.png", True),
               ("wall_s", "wall time (s)", "time.png", True),
               ("proximity_error", "proximity error / diagonal", "proximity.png", True),
               ("shadow_error_sky", "shadow RMS error (sky light)", "shadow.png", False)]
    cols = min(4, len(meshes))
    rows_n = (len(meshes) + cols - 1) // cols
    for key, label, name, logy in figures:
        fig, axes = plt.subplots(rows_n, cols, figsize=(4 * cols, 3.2 * rows_n), squeeze=False)
        for ax, mesh in zip(axes.flat, meshes):
            for method in methods:
                pts = sorted((int(r["n"]), float(r[key])) for r in rows
                             if r["mesh"] == mesh and r["method"] == method)
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", label=method)
            ax.set_title(mesh, fontsize=9)
            ax.set_xscale("log", base=2)
            if logy:
                ax.set_yscale("log")
            ax.set_xlabel("spheres")
            ax.set_ylabel(label, fontsize=8)
            ax.grid(True, alpha=0.3)
        for ax in list(axes.flat)[len(meshes):]:
            ax.axis("off")
        axes.flat[0].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, name), dpi=90)
        plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("meshes", nargs="*")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "suite"))
    ap.add_argument("--n", default="8,16,32,64,128,256")
    ap.add_argument("--methods", default="variational,kmeans,octree")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--mesh-dir", default=os.path.join(ROOT, "..", "shared", "meshes"))
    a = ap.parse_args()
    ns = [int(x) for x in a.n.split(",")]
    meshes = a.meshes
    if a.quick:
        meshes = meshes or [os.path.join(ROOT, "tests", "data", "fr3_link1_collision.stl"),
                            os.path.join(ROOT, "examples", "spot.obj")]
        if a.n == ap.get_default("n"):
            ns = [8, 16]
    elif not meshes:
        meshes = closed_meshes(a.mesh_dir)
        if not meshes:
            sys.exit("suite: no meshes found in %s (give paths, or --quick)" % a.mesh_dir)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    start = time.time()
    csv_path = os.path.join(a.out, "suite.csv")
    with open(csv_path, "w", newline="") as f, tempfile.TemporaryDirectory() as tmp:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        for mesh in meshes:
            tris = json.loads(run([CLI, "check", mesh, "--json"]))["triangles"]
            for method in a.methods.split(","):
                for n in ns:
                    r = {"mesh": os.path.basename(mesh), "triangles": tris, "method": method, "n": n}
                    r.update(fit_and_eval(mesh, method, n, a.seed, tmp))
                    w.writerow(r)
                    f.flush()
                    rows.append({k: str(v) for k, v in r.items()})
                    print("%-28s %-11s n=%-4d E_r %.4f  covered %s/%s  %.1f s  [%.0f s]" %
                          (r["mesh"], method, n, r["er_sum"], r["surface_covered"],
                           r["interior_covered"], r["wall_s"], time.time() - start), flush=True)
    plot(rows, a.out)
    print("wrote %s and er.png, time.png, proximity.png, shadow.png in %s (%.0f s)" %
          (csv_path, a.out, time.time() - start))
    if not all(r["surface_covered"] == "True" and r["interior_covered"] == "True" for r in rows):
        sys.exit("suite: some sphere sets do not cover their mesh")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Overhead of the Python module against the command line on one mesh: the same work
(load, repair, fit, write the spheres, the fit's coverage check) through `sphereset fit` and
through sphereset.fit + sphereset.evaluate, alternated, several repeats; into
bench/results/python_overhead.csv.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [MESH] [-n N] [-r REPEATS]

Default mesh: spot from ../shared/meshes (organic/spot.obj), else examples/spot.obj.
Columns: run, cli_wall_s, py_wall_s (in process), py_process_wall_s (a fresh interpreter:
start, import, the same work), cli_fit_s, py_fit_s (the fit's own seconds.total), cli_cpu_s,
py_cpu_s (user + system CPU time of the CLI process and of the in-process Python work: less
sensitive than wall time to other load on the machine), same_file (identical sphere files).
"""

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "build", "python"))
import sphereset as ss  # noqa: E402

CLI = os.path.join(ROOT, "build", "apps", "sphereset")
SHARED_SPOT = os.path.join(ROOT, "..", "shared", "meshes", "organic", "spot.obj")

PY_JOB = """
import sys, sphereset as ss
mesh, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
s = ss.solid(mesh)
r = ss.fit(s, n=n)
ss.write_spheres(out, r.spheres, source_mesh=mesh)
e = ss.evaluate(s, r.spheres, samples=100000, segments=0, shadow_resolution=0)
print(r.seconds["total"])
"""


def python_work(mesh, n, out):
    s = ss.solid(mesh)
    r = ss.fit(s, n=n)
    ss.write_spheres(out, r.spheres, source_mesh=mesh)
    ss.evaluate(s, r.spheres, samples=100000, segments=0, shadow_resolution=0)
    return r


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mesh", nargs="?", default=SHARED_SPOT if os.path.exists(SHARED_SPOT)
                   else os.path.join(ROOT, "examples", "spot.obj"))
    p.add_argument("-n", type=int, default=32)
    p.add_argument("-r", "--repeats", type=int, default=5)
    p.add_argument("-o", "--out", default=os.path.join(ROOT, "bench", "results",
                                                       "python_overhead.csv"))
    a = p.parse_args()
    os.makedirs(os.path.dirname(a.out), exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        cli_out, py_out = os.path.join(tmp, "cli.json"), os.path.join(tmp, "py.json")
        env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "build", "python"))
        python_work(a.mesh, a.n, py_out)  # warm the file cache and the module
        for i in range(a.repeats):
            c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            t = time.perf_counter()
            res = subprocess.run([CLI, "fit", a.mesh, "-n", str(a.n), "-o", cli_out, "-q",
                                  "--json"], check=False, capture_output=True, text=True)
            cli_wall = time.perf_counter() - t
            c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            cli_cpu = c1.ru_utime + c1.ru_stime - c0.ru_utime - c0.ru_stime
            s0 = resource.getrusage(resource.RUSAGE_SELF)
            cli_fit = json.loads(res.stdout)["seconds"]["total"]
            t = time.perf_counter()
            r = python_work(a.mesh, a.n, py_out)
            py_wall = time.perf_counter() - t
            s1 = resource.getrusage(resource.RUSAGE_SELF)
            py_cpu = s1.ru_utime + s1.ru_stime - s0.ru_utime - s0.ru_stime
            t = time.perf_counter()
            subprocess.run([sys.executable, "-c", PY_JOB, a.mesh, str(a.n), py_out], check=True,
                           env=env, capture_output=True)
            proc_wall = time.perf_counter() - t
            same = open(cli_out).read() == open(py_out).read()
            rows.append((i, cli_wall, py_wall, proc_wall, cli_fit, r.seconds["total"], cli_cpu,
                         py_cpu, same))
    with open(a.out, "w") as f:
        f.write("run,cli_wall_s,py_wall_s,py_process_wall_s,cli_fit_s,py_fit_s,cli_cpu_s,py_cpu_s,"
                "same_file\n")
        for row in rows:
            f.write(",".join([str(row[0])] + ["%.3f" % x for x in row[1:8]] + [str(row[8])])
                    + "\n")
    med = [statistics.median(r[k] for r in rows) for k in range(1, 8)]
    print(open(a.out).read(), end="")
    print(f"mesh {os.path.basename(a.mesh)}, n {a.n}, {a.repeats} repeats (medians): "
          f"CLI {med[0]:.3f} s, Python in process {med[1]:.3f} s "
          f"({100 * (med[1] / med[0] - 1):+.1f} %), Python process {med[2]:.3f} s "
          f"({100 * (med[2] / med[0] - 1):+.1f} %); fit alone CLI {med[3]:.3f} s, "
          f"Python {med[4]:.3f} s ({100 * (med[4] / med[3] - 1):+.1f} %); CPU time CLI "
          f"{med[5]:.2f} s, Python in process {med[6]:.2f} s ({100 * (med[6] / med[5] - 1):+.1f} %)"
          f"; same sphere file every run: {all(r[8] for r in rows)}")


if __name__ == "__main__":
    main()

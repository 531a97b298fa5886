"""Meshes, fit and evaluation through the module: the same spheres as the command line for the
same seed, array shapes and dtypes, meshes given as arrays, errors as exceptions, cancellation."""

import json
import os
import re
import signal

import numpy as np
import pytest

import sphereset as ss
from conftest import DATA, LINK, cube_arrays


def test_load_mesh_arrays():
    m = ss.load_mesh(LINK)
    assert m.vertices.dtype == np.float64 and m.vertices.ndim == 2 and m.vertices.shape[1] == 3
    assert np.issubdtype(m.faces.dtype, np.integer) and m.faces.shape == (300, 3)
    assert m.faces.min() >= 0 and m.faces.max() < len(m.vertices)
    assert m.volume > 0 and m.load_report["file_triangles"] == 300
    d = ss.diagnose(m)
    assert d["solid"] and d["closed"] and d["triangles"] == 300 and d["vertices"] == 152


@pytest.mark.parametrize("args", [
    dict(n=6, seed=3, quality="fast"),
    dict(n=4, seed=1, quality="default", padding=0.001, optimizer="gradient"),
    dict(n=5, seed=2, quality="fast", method="kmeans", init="random"),
])
def test_same_spheres_as_cli(cli, tmp_path, args):
    out = tmp_path / "cli.json"
    cmd = ["fit", LINK, "-n", args["n"], "--seed", args["seed"], "--quality", args["quality"],
           "-o", out, "-q", "--json"]
    for k in ("padding", "optimizer", "method", "init"):
        if k in args:
            cmd += [f"--{k}", args[k]]
    summary = json.loads(cli(*cmd).stdout)
    r = ss.fit(ss.load_mesh(LINK), **args)
    # JSON and text files hold shortest round-trip decimals: the same doubles.
    assert np.array_equal(r.spheres, ss.read_spheres(out))
    assert r.spheres.shape == (args["n"], 4) and r.spheres.dtype == np.float64
    assert r.rounds == summary["rounds"] and r.points == summary["points"]
    assert r.er_sum == pytest.approx(summary["er_sum"], rel=1e-12)
    assert r.teleports == summary["teleports"] and r.restart == summary["restart"]
    # One field list (result_fields.hpp) behind both: every field, same name and value.
    for row in ss._core._result_schema("fit"):
        name = row["name"].split(".")[0]
        if name == "seconds":
            assert set(summary[name]) == set(r.seconds)
            continue
        mine = getattr(r, name)
        if isinstance(mine, np.ndarray):
            assert np.array_equal(mine, np.array(summary[name])), name
        else:
            assert mine == pytest.approx(summary[name], rel=1e-12), name


def test_same_spheres_as_cli_after_repair(cli, tmp_path):
    # The open box is capped by the repair, and its input triangles are bounded too.
    out = tmp_path / "box.txt"
    cli("fit", DATA / "open_box.off", "-n", 3, "--quality", "fast", "-o", out, "-q")
    r = ss.fit(DATA / "open_box.off", n=3, quality="fast")
    assert r.repair["kind"] == "capped"
    assert np.array_equal(r.spheres, ss.read_spheres(out))


def test_fit_diagnostics_and_options():
    r = ss.fit(ss.load_mesh(LINK), n=4, quality="fast", iterations=5, restarts=2)
    assert r.options["iterations"] == 5 and r.options["restarts"] == 2
    assert r.options["points"] == int(0.25 * 5000)
    assert r.outside_volume.shape == (4,) and np.all(r.outside_volume >= 0)
    assert r.energy == pytest.approx(r.outside_volume.sum(), rel=1e-9)
    assert r.er_sum == pytest.approx(r.energy / r.mesh_volume)
    assert set(r.seconds) >= {"total", "sampling", "assignment", "update", "bounding"}
    assert np.all(r.spheres[:, 3] > 0)
    json.dumps(r.to_dict())


def test_mesh_from_arrays_fitted_and_evaluated():
    v, f = cube_arrays(2.0, (1.0, -1.0, 0.5))
    m = ss.Mesh(v, f)
    assert m.vertices.shape == (8, 3) and m.faces.shape == (12, 3)
    assert m.volume == pytest.approx(8.0)
    r = ss.fit(m, n=4, seed=5, quality="fast")
    assert r.spheres.shape == (4, 4)
    e = ss.evaluate(m, r.spheres, samples=20000, segments=100, shadow_resolution=16)
    assert e.surface_covered and e.interior_covered and e.covered
    assert e.er_sum == pytest.approx(r.er_sum, rel=1e-9)
    assert e.outside_volume.shape == (4,)
    # Every vertex of the cube is inside some sphere (the bound is guaranteed).
    assert ss.contains(r.spheres, v).all()
    # The protrusion: a certified bound, its witness in a ball at the distance it says from the
    # cube (closed form: the excess over the box, per axis), and the bound no nearer than the
    # sphere that sticks out most along an axis.
    p = e.protrusion
    lo, hi = np.array([1.0, -1.0, 0.5]), np.array([3.0, 1.0, 2.5])
    w = np.array(p["witness"])
    assert np.linalg.norm(np.maximum(np.maximum(lo - w, w - hi), 0)) == pytest.approx(
        p["witness_distance"], abs=1e-12)
    assert p["witness_distance"] <= p["bound"] <= p["witness_distance"] + 1e-3 * e.bbox_diagonal
    c, rad = r.spheres[:, :3], r.spheres[:, 3]
    axis_out = np.max(np.maximum(np.maximum(lo - (c.T - rad).T, (c.T + rad).T - hi), 0))
    assert p["bound"] >= axis_out - 1e-12
    assert len(p["per_sphere"]) == 4 and max(p["per_sphere"]) == p["bound"]
    quick = ss.evaluate(m, r.spheres, samples=1000, segments=0, shadow_resolution=0,
                        protrusion_tolerance=0)
    assert quick.protrusion["sphere"] == -1


def test_arrays_and_file_give_the_same_fit(tmp_path):
    v, f = cube_arrays()
    off = tmp_path / "cube.off"
    off.write_text("OFF\n8 12 0\n" + "".join(f"{a:.17g} {b:.17g} {c:.17g}\n" for a, b, c in v)
                   + "".join(f"3 {a} {b} {c}\n" for a, b, c in f))
    a = ss.fit(ss.Mesh(v, f), n=3, quality="fast")
    b = ss.fit(off, n=3, quality="fast")
    assert np.array_equal(a.spheres, b.spheres)


def test_solid_reused_and_queries():
    s = ss.solid(LINK)
    assert s.repair["kind"] == "none" and s.original is None
    r1 = ss.fit(s, n=3, quality="fast")
    r2 = ss.fit(s, n=3, quality="fast")
    assert np.array_equal(r1.spheres, r2.spheres)
    assert np.allclose(s.outside_volume(r1.spheres), r1.outside_volume, rtol=1e-9, atol=1e-15)
    centre = ss.load_mesh(LINK).vertices.mean(axis=0)
    far = centre + 10.0
    assert s.distance([far])[0] > 1.0 and not s.contains([far])[0]


def test_check_reports_repair():
    c = ss.check(DATA / "open_box.off")
    assert not c.diagnosis["closed"] and c.diagnosis["boundary_edges"] == 4
    assert c.fit_accepts and c.repair["kind"] == "capped"
    off = ss.check(DATA / "open_box.off", repair="off")
    assert not off.fit_accepts and "not a closed solid" in off.error
    x = ss.check(DATA / "overlapping_cubes.off")
    assert x.shells["intersecting_shell_pairs"] == 1 and x.shells["shells"] == 2


def test_errors_are_exceptions(tmp_path):
    with pytest.raises(ss.UnreadableError, match="missing.obj"):
        ss.load_mesh(tmp_path / "missing.obj")
    with pytest.raises(OSError):
        ss.load_mesh(tmp_path / "missing.obj")
    bad = tmp_path / "garbage.stl"
    bad.write_text("not a mesh at all")
    with pytest.raises(ss.Error):
        ss.load_mesh(bad)
    nan = tmp_path / "nan.off"
    nan.write_text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    with pytest.raises(ss.InvalidDataError, match="vertex 1 has a NaN"):
        ss.load_mesh(nan)
    v, f = cube_arrays()
    v_nan = v.copy()
    v_nan[3, 1] = np.nan
    with pytest.raises(ss.InvalidDataError, match="vertex 3 has a NaN"):
        ss.Mesh(v_nan, f)
    with pytest.raises(ss.InvalidDataError, match="vertex 3 has a NaN"):
        ss.Mesh(v_nan, f, clean=False)
    with pytest.raises(ValueError, match="references vertex 8 of 8"):
        ss.Mesh(v, np.where(f == 7, 8, f))
    with pytest.raises(ss.InvalidDataError):
        ss.Mesh(v, -f - 1)
    # Unsigned indices are named as they are (2^64 - 1 was shown as vertex -1).
    huge = f.astype(np.uint64)
    huge[2, 1] = 2**64 - 1
    with pytest.raises(ss.InvalidDataError, match="triangle 2 references vertex 18446744073709551615 of 8"):
        ss.Mesh(v, huge)
    assert ss.Mesh(v, f.astype(np.uint16)).faces.shape == (12, 3)
    with pytest.raises(ss.InvalidArgumentError, match="integer"):
        ss.Mesh(v, f.astype(float))
    with pytest.raises(ss.InvalidArgumentError):
        ss.Mesh(v[:, :2], f)
    with pytest.raises(ss.InvalidArgumentError,
                       match="n '0': expected an integer from 1 to 1000000"):
        ss.fit(ss.Mesh(v, f), n=0)
    # The command line's upper limits, before any work (n = 10**8 used to run for minutes).
    with pytest.raises(ss.InvalidArgumentError, match="n '100000000': expected an integer"):
        ss.fit(ss.Mesh(v, f), n=10**8)
    for seed in (-1, 2**64, 1e23):
        with pytest.raises(ss.InvalidArgumentError, match="seed '.*': expected an integer"):
            ss.fit(ss.Mesh(v, f), n=2, seed=seed)
    with pytest.raises(ss.InvalidArgumentError, match="decimation 'nan'"):
        ss.fit(ss.Mesh(v, f), n=2, decimation=float("nan"))
    # The wrap's limits: this used to kill the interpreter with a signal inside GMP.
    with pytest.raises(ss.InvalidArgumentError, match="wrap_alpha '1e.200': expected a number"):
        ss.fit(DATA / "bow_tie.off", 4, wrap_alpha=1e200)
    with pytest.raises(ss.InvalidArgumentError, match="wrap_alpha 1e.03 is more than 100 times"):
        ss.fit(DATA / "bow_tie.off", 4, wrap_alpha=1e3)
    with pytest.raises(ss.InvalidArgumentError, match="^weld_tolerance 'nan': expected a number"):
        ss.solid(DATA / "bow_tie.off", weld_tolerance=float("nan"))
    with pytest.raises(ss.InvalidArgumentError, match="quality"):
        ss.fit(ss.Mesh(v, f), n=2, quality="perfect")
    with pytest.raises(ss.NotSolidError, match="not a closed solid"):
        ss.fit(DATA / "open_box.off", n=2, repair="off")
    with pytest.raises(ss.InvalidDataError, match="negative radius"):
        ss.evaluate(ss.Mesh(v, f), [[0, 0, 0, -1]])
    with pytest.raises(ss.InvalidArgumentError, match=r"\(N, 4\)"):
        ss.evaluate(ss.Mesh(v, f), [[0, 0, 0]])
    assert issubclass(ss.UnreadableError, OSError) and issubclass(ss.NotSolidError, ValueError)


def test_progress_and_cancel():
    m = ss.load_mesh(LINK)
    seen = []
    r = ss.fit(m, n=4, quality="fast", progress=seen.append)
    assert seen and seen[0]["phase"] == "sampling" and r.spheres.shape == (4, 4)
    assert {p["phase"] for p in seen} >= {"sampling", "clustering", "bounding"}

    class Stop(Exception):
        pass

    def stop(p):
        if p["phase"] == "clustering":
            raise Stop()

    with pytest.raises(Stop):
        ss.fit(m, n=4, quality="fast", progress=stop)

    # Ctrl-C: SIGINT during the fit raises KeyboardInterrupt at the next progress report.
    def interrupt(p):
        if p["phase"] == "clustering":
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        ss.fit(m, n=4, quality="fast", progress=interrupt)

    # A signal that arrives while the library runs (no Python callback at all) is handled at the
    # next progress report, inside the fit.
    def alarm(*_):
        raise KeyboardInterrupt()

    s = ss.solid(m)
    old = signal.signal(signal.SIGALRM, alarm)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.05)  # the fit takes much longer
        with pytest.raises(KeyboardInterrupt) as info:
            ss.fit(s, n=8, quality="default")
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    # Raised inside the fit: the handler's frame sits on fit's, not on the test's.
    assert [e.name for e in info.traceback][-2:] == ["fit", "alarm"]
    # The module is usable afterwards and gives the same result.
    assert np.array_equal(ss.fit(m, n=4, quality="fast").spheres, r.spheres)


def test_interrupt_anywhere_in_the_fit_leaves_it():
    """Ctrl-C at any moment of a fit raises KeyboardInterrupt: inside the optimisers too, where
    NLopt's wrapper used to swallow it (the refinement ran on and the fit returned)."""
    import time

    s = ss.solid(ss.load_mesh(LINK))
    t0 = time.perf_counter()
    ss.fit(s, n=8, quality="default")
    took = time.perf_counter() - t0

    def alarm(*_):
        raise KeyboardInterrupt()

    old = signal.signal(signal.SIGALRM, alarm)
    try:
        for frac in (0.2, 0.4, 0.55, 0.7, 0.8, 0.9, 0.95):
            signal.setitimer(signal.ITIMER_REAL, frac * took)
            with pytest.raises(KeyboardInterrupt):
                ss.fit(s, n=8, quality="default")
                time.sleep(2 * took)  # an alarm after the fit still ends up here
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def test_evaluate_options_are_checked_by_the_library_table():
    # Python had lower bounds only: shadow_resolution=100000 ended in MemoryError.
    box = ss.Mesh(*cube_arrays())
    one = np.array([[0.5, 0.5, 0.5, 1.0]])
    with pytest.raises(ss.InvalidArgumentError,
                       match="shadow_resolution '100000': expected an integer from 0 to 4096"):
        ss.evaluate(box, one, shadow_resolution=100000)
    with pytest.raises(ss.InvalidArgumentError, match="up 'w': expected x, y or z"):
        ss.evaluate(box, one, up="w")
    names = [row["name"] for row in ss.eval_option_table()]
    assert names[:3] == ["seed", "samples", "segments"]
    r = ss.evaluate(box, one, samples=0, segments=0, shadow_resolution=0)
    assert r.surface_covered and r.interior_covered



def test_file_names_that_are_not_utf8(tmp_path, cli):
    # File names are bytes: "l\xff.stl" used to end in "internal error: [json.exception...]"
    # after the fit, write invalid UTF-8 into YAML, and make repr(Mesh) raise.
    name = os.fsdecode(b"l\xff.stl")
    mesh = tmp_path / name
    mesh.write_bytes(LINK.read_bytes())
    assert "l\udcff.stl" in repr(ss.load_mesh(mesh))
    with pytest.raises(ss.UnreadableError, match="n\udcffo.stl: no such file"):
        ss.load_mesh(tmp_path / os.fsdecode(b"n\xffo.stl"))
    out = tmp_path / os.fsdecode(b"o\xff.yaml")
    r = cli("fit", mesh, "-n", "3", "--quality", "fast", "-o", out, "-q", "--json")
    assert json.loads(r.stdout)["spheres"] == 3
    out.read_bytes().decode("utf-8")  # valid UTF-8
    assert ss.read_spheres(out).shape == (3, 4)
    tree = tmp_path / "t.json"
    cli("tree", mesh, "--branch", "2", "--depth", "1", "--quality", "fast", "-o", tree, "-q")
    assert "\ufffd" in tree.read_text(encoding="utf-8")


def test_check_refuses_repair_options_outside_the_table():
    # check() reports a mesh the fit refuses, but options outside the library's repair table
    # raise, as `sphereset check` exits 2, before anything is loaded.
    for kw, words in ((dict(weld_tolerance=float("inf")), "weld_tolerance 'inf'"),
                      (dict(weld_tolerance=1e31), "weld_tolerance '1e+31'"),
                      (dict(wrap_alpha=1.0000004e30), "wrap_alpha '1.0000004e+30'"),
                      (dict(repair="maybe"), "repair 'maybe': expected auto or off")):
        with pytest.raises(ss.InvalidArgumentError, match=re.escape(words)):
            ss.check(DATA / "bow_tie.off", **kw)
    assert ss.check(DATA / "bow_tie.off", weld_tolerance=-1.0).diagnosis["triangles"] == 12


@pytest.mark.parametrize("mesh", ["open_box.off", "overlapping_cubes.off"])
def test_check_fields_are_the_command_lines(cli, mesh):
    # One field list per result (result_fields.hpp) behind `sphereset check --json` and
    # ss.check: the diagnosis, the load report and the repair, field by field.
    path = DATA / mesh
    ref = json.loads(cli("check", path, "--json").stdout)
    r = ss.check(path)

    def same(mine, theirs, name):
        if isinstance(mine, np.ndarray):
            mine = mine.tolist()
        if isinstance(mine, float) and np.isnan(mine):
            assert theirs is None, name  # NaN is written as null
        else:
            assert mine == theirs, name

    for name, value in r.diagnosis.items():
        same(value, ref[name], name)
    for name, value in r.load.items():
        if name not in ("path", "format"):
            same(value, ref["load"][name], name)
    for row in ss._core._result_schema("shells"):
        same(r.shells[row["name"]], ref["self_intersections"][row["name"]], row["name"])
    assert r.repair is not None and set(r.repair) == set(ref["repair"])
    for name, value in r.repair.items():
        if name != "seconds":
            same(value, ref["repair"][name], name)


def test_a_number_option_is_read_by_one_rule():
    """n='4' was accepted while n=4.0 was refused: a float is written as the library writes a
    number (4.0 is "4"), text is parsed as on the command line, a bool is refused."""
    m = ss.load_mesh(LINK)
    a = ss.fit(m, 4.0, quality="fast")
    b = ss.fit(m, "4", quality="fast")
    c = ss.fit(m, 4, quality="fast")
    assert np.array_equal(a.spheres, c.spheres) and np.array_equal(b.spheres, c.spheres)
    with pytest.raises(ss.InvalidArgumentError, match="padding 'True': expected a number"):
        ss.fit(m, 4, padding=True)
    with pytest.raises(ss.InvalidArgumentError, match="n '4.5'"):
        ss.fit(m, 4.5)


def test_fit_to_tolerance_same_as_the_command(cli, tmp_path):
    """fit_to_tolerance finds the count `sphereset fit --max-protrusion` finds, with the same
    spheres and curve; a tolerance no count meets is met=False with the best count tried."""
    out = tmp_path / "tol.json"
    r = cli("fit", LINK, "--max-protrusion", "12%", "--quality", "fast", "-o", out, "--json", "-q")
    ref = json.loads(r.stdout)
    t = ss.fit_to_tolerance(LINK, max_protrusion="12%", quality="fast")
    assert t["met"] and t["n"] == ref["tolerance"]["n"] == len(t["fit"].spheres)
    assert [c["n"] for c in t["curve"]] == [c["n"] for c in ref["tolerance"]["curve"]]
    np.testing.assert_array_equal(t["fit"].spheres, ss.read_spheres(out))
    assert t["eval"]["protrusion"]["bound"] <= t["protrusion_limit"]
    none = ss.fit_to_tolerance(LINK, max_protrusion=1e-7, max_spheres=2, quality="fast")
    assert not none["met"] and [c["n"] for c in none["curve"]] == [1, 2]
    with pytest.raises(ss.InvalidArgumentError, match="max_er 'nan'"):
        ss.fit_to_tolerance(LINK, max_er=float("nan"))


def test_fit_to_tolerance_takes_the_fit_keywords(tmp_path):
    """fit_to_tolerance takes fit's keywords (the result's options are them), calls progress
    after each count tried, ends the search when progress raises, and refuses a bad tolerance or
    option before it reads the mesh (a missing file is not what it reports)."""
    seen = []
    t = ss.fit_to_tolerance(LINK, max_protrusion="12%", quality="fast", iterations=5,
                            points=800, progress=seen.append)
    assert t["fit"].options["iterations"] == 5 and t["fit"].options["points"] == 800
    assert seen == t["curve"] and t["met"] and seen[-1]["n"] > 0
    missing = str(tmp_path / "missing.stl")
    with pytest.raises(ss.InvalidArgumentError, match="max_protrusion '-1'"):
        ss.fit_to_tolerance(missing, max_protrusion=-1)
    with pytest.raises(ss.InvalidArgumentError, match="needs max_protrusion or max_er"):
        ss.fit_to_tolerance(missing, max_spheres=8)
    with pytest.raises(ss.InvalidArgumentError, match="restarts '0'"):
        ss.fit_to_tolerance(missing, max_er=1.0, restarts=0)

    class Stop(Exception):
        pass

    calls = []

    def stop(point):
        calls.append(point["n"])
        raise Stop(point["n"])
    with pytest.raises(Stop):
        ss.fit_to_tolerance(LINK, max_protrusion="12%", quality="fast", progress=stop)
    assert calls == [1]

    # A signal while a count is being fitted is handled inside that fit: progress reports every
    # count finished, and the count running when the signal came never finishes.
    def alarm(*_):
        raise KeyboardInterrupt()

    s = ss.solid(LINK)
    counts = []

    def arm(point):
        counts.append(point["n"])
        if point["n"] == 1:
            signal.setitimer(signal.ITIMER_REAL, 0.02)  # the next count's fit takes much longer

    old = signal.signal(signal.SIGALRM, alarm)
    try:
        with pytest.raises(KeyboardInterrupt) as info:
            ss.fit_to_tolerance(s, max_protrusion="0.1%", quality="best", progress=arm)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    assert counts == [1]
    assert [e.name for e in info.traceback][-2:] == ["fit_to_tolerance", "alarm"]


def test_fit_curve_is_the_commands_curve(cli, tmp_path):
    """fit_curve gives every count's point and set, the same figures as `sphereset curve` (the
    same library call), each point the check of its set, the last set `fit`'s at that count; bad
    counts are refused before the mesh is read."""
    seen = []
    c = ss.fit_curve(LINK, max_spheres=4, quality="fast", progress=seen.append)
    assert [p["n"] for p in c["curve"]] == [1, 2, 3, 4] and seen == c["curve"]
    assert c["progressive"] and [len(s) for s in c["spheres"]] == [1, 2, 3, 4]
    out = tmp_path / "curve.csv"
    cli("curve", str(LINK), "--max-spheres", "4", "--quality", "fast", "-o", str(out), "-q")
    rows = out.read_text().splitlines()
    assert rows[0] == "n,er_sum,protrusion,covered,meets,seconds"
    for row, p in zip(rows[1:], c["curve"]):
        n, er, prot, covered = row.split(",")[:4]
        assert (int(n), float(er), float(prot), covered) == (p["n"], p["er_sum"],
                                                             p["protrusion"], "1")
    # Without max_spheres, the library's default cap: every count from 1 to 64.
    assert [p["n"] for p in ss.fit_curve(LINK, quality="fast")["curve"]] == list(range(1, 65))
    # The last count's set is the fit `fit` gives at that count.
    np.testing.assert_array_equal(c["spheres"][-1], ss.fit(LINK, n=4, quality="fast").spheres)
    # Each point is the check of its set: the protrusion bounds the same union, within the
    # bound's tolerance (0.001 of the diagonal) of the full check's.
    ev = ss.evaluate(LINK, c["spheres"][2])
    assert ev.er_sum == pytest.approx(c["curve"][2]["er_sum"], rel=1e-12)
    tolerance = 1e-3 * ev.bbox_diagonal
    assert ev.protrusion["witness_distance"] <= c["curve"][2]["protrusion"]
    assert c["curve"][2]["protrusion"] <= ev.protrusion["bound"] + tolerance
    missing = str(tmp_path / "missing.stl")
    with pytest.raises(ss.InvalidArgumentError, match="expected increasing counts"):
        ss.fit_curve(missing, counts=[4, 2])
    with pytest.raises(ss.InvalidArgumentError, match="max_spheres 0"):
        ss.fit_curve(missing, max_spheres=0)
    with pytest.raises(ss.InvalidArgumentError, match="max_spheres 2000: expected an integer "
                                                      "from 1 to 1024"):
        ss.fit_curve(missing, max_spheres=2000)
    with pytest.raises(ss.InvalidArgumentError, match="counts \\[\\]"):
        ss.fit_curve(missing, counts=[])
    with pytest.raises(TypeError):
        ss.fit_curve(missing, counts=[1.5, 2])

"""The batch on a Dask cluster (sphereset.batch) against `sphereset batch`: a local cluster of two
worker processes writes the same sphere files and the same report (timings aside)."""

import json
import os
import shutil

import pytest

from conftest import DATA

distributed = pytest.importorskip("distributed")

import sphereset as ss  # noqa: E402
from sphereset import batch  # noqa: E402


def meshes(tmp_path):
    src = tmp_path / "meshes"
    (src / "sub").mkdir(parents=True)
    shutil.copy(DATA / "fr3_link1_collision.stl", src / "link1.stl")
    shutil.copy(DATA / "open_box.off", src / "sub" / "open_box.off")
    shutil.copy(DATA / "overlapping_cubes.off", src / "sub" / "cubes.off")
    shutil.copy(DATA / "robot" / "three_link_description" / "meshes" / "link.stl",
                src / "sub" / "link.stl")
    (src / "broken.off").write_text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    return src


def report(path):
    lines = [json.loads(x) for x in path.read_text().splitlines()]
    for d in lines:
        d.pop("seconds")
    return lines


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=":0")
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_dask_batch_equals_cli_batch(cli, tmp_path, client):
    src = meshes(tmp_path)
    cli_out, dask_out = tmp_path / "cli", tmp_path / "dask"
    r = cli("batch", src, "-o", cli_out, "-n", 3, "--quality", "fast", "-q", check=False)
    assert (cli_out / "report.jsonl").exists(), r.stderr
    opts = batch.batch_options(3, quality="fast", threads=1)
    lines = batch.run_batch(str(src), str(dask_out), opts, client, quiet=True)
    assert len(lines) == 5
    want = report(cli_out / "report.jsonl")
    got = report(dask_out / "report.jsonl")
    assert [d["mesh"] for d in got] == [d["mesh"] for d in want]
    assert got == want
    statuses = [d["status"] for d in got]
    assert statuses.count("error") == 1 and statuses.count("ok") == 4
    for d in want:
        if d["status"] == "ok":
            a = (cli_out / d["output"]).read_bytes()
            b = (dask_out / d["output"]).read_bytes()
            assert a == b, d["output"]
            assert ss.read_spheres(dask_out / d["output"]).shape == (3, 4)

    # Resuming: nothing is fitted again, every fitted item is reported as skipped.
    again = batch.run_batch(str(src), str(dask_out), opts, client, quiet=True)
    st = [json.loads(x)["status"] for x in again]
    assert st.count("skipped") == 4 and st.count("error") == 1


def test_batch_items_and_bad_input(tmp_path):
    src = meshes(tmp_path)
    items = batch.list_items(str(src), batch.batch_options(5))
    assert [i["output"] for i in items] == sorted(i["output"] for i in items)
    assert all(i["fit"]["n"] == 5 for i in items) and len(items) == 5
    with pytest.raises(ss.UnreadableError):
        batch.list_items(str(tmp_path / "nothing"), batch.batch_options())


def test_tolerance_crosses_to_the_workers(tmp_path):
    # A batch-wide tolerance and a manifest line's own reach the item dicts the workers get; the
    # report gives the count the tolerance chose and its certified protrusion.
    src = tmp_path / "m"
    src.mkdir()
    shutil.copy(DATA / "fr3_link1_collision.stl", src / "a.stl")
    shutil.copy(DATA / "fr3_link1_collision.stl", src / "b.stl")
    (src / "list.csv").write_text("mesh,max_protrusion\na.stl,15%\nb.stl,\n")
    opts = batch.batch_options(quality="fast", max_er=3.0, max_spheres=32)
    items = batch.list_items(str(src / "list.csv"), opts)
    assert items[0]["tolerance"] == {"max_protrusion": "15%", "max_er": "3", "max_spheres": "32"}
    assert items[1]["tolerance"]["max_protrusion"] is None
    out = tmp_path / "out"
    for item in items:
        line = json.loads(batch.process_item(item, str(out), opts))
        assert line["status"] == "ok" and line["n"] == 0 and line["tolerance_met"]
        assert line["spheres"] >= 1 and line["protrusion"] > 0 and line["covered"]
    # A tolerance no count up to the cap meets: an error item, or with best_effort the best count
    # written with tolerance_met false.
    for best_effort in (False, True):
        strict = batch.batch_options(quality="fast", max_protrusion=1e-7, max_spheres=2,
                                     best_effort=best_effort)
        item = batch.list_items(str(src / "list.csv"), strict)[1]
        line = json.loads(batch.process_item(item, str(tmp_path / f"unmet{best_effort}"), strict))
        assert not line["tolerance_met"]
        assert line["status"] == ("ok" if best_effort else "error")
        assert (line["spheres"] >= 1) == best_effort
    with pytest.raises(ss.InvalidArgumentError, match="max_er 'nan'"):
        batch.list_items(str(src / "list.csv"), batch.batch_options(max_er=float("nan")))
    with pytest.raises(ss.InvalidArgumentError, match="max_er '0': expected a number above 0"):
        batch.list_items(str(src / "list.csv"), batch.batch_options(max_er=0))
    # A batch's cap binds the lines with a limit (a.stl's) and reaches the workers; with a limit
    # on no line, or for a folder with no limit, it would cap nothing: refused.
    capped = batch.list_items(str(src / "list.csv"), batch.batch_options(max_spheres=8))
    assert capped[0]["tolerance"]["max_spheres"] == "8"
    with pytest.raises(ss.InvalidArgumentError, match="max_spheres goes with a tolerance"):
        batch.list_items(str(src), batch.batch_options(max_spheres=8))
    (src / "fixed.csv").write_text("mesh,n\na.stl,4\n")
    with pytest.raises(ss.InvalidArgumentError, match=r"fixed.csv: max_spheres goes .*no line"):
        batch.list_items(str(src / "fixed.csv"), batch.batch_options(max_spheres=8))
    items = batch.list_items(str(src / "list.csv"), batch.batch_options(max_er=3.0))
    assert items[1]["tolerance"]["max_spheres"] is None  # not given: the library's cap


def test_command_line_local_workers(tmp_path):
    src = tmp_path / "one"
    src.mkdir()
    shutil.copy(DATA / "fr3_link1_collision.stl", src / "link1.stl")
    out = tmp_path / "out"
    code = batch.main([str(src), "-o", str(out), "--local-workers", "1", "-n", "2",
                       "--quality", "fast", "-q", "--format", "txt"])
    assert code == 0
    assert ss.read_spheres(out / "link1.txt").shape == (2, 4)
    assert json.loads((out / "report.jsonl").read_text())["status"] == "ok"


def test_one_run_per_output_folder(tmp_path, capsys):
    # Two runs on one folder used to interleave report.jsonl and fit every item twice; the second
    # now stops at once with the library's message (exit 6), naming the run that holds it.
    src = tmp_path / "one"
    src.mkdir()
    shutil.copy(DATA / "open_box.off", src / "a.off")
    out = tmp_path / "out"
    held = ss._core._BatchReport(str(out))
    code = batch.main([str(src), "-o", str(out), "--local-workers", "1", "-n", "2", "-q"])
    assert code == 6
    assert f"another batch run (pid {os.getpid()}" in capsys.readouterr().err
    assert not (out / "a.json").exists()
    held.finish()
    assert batch.main([str(src), "-o", str(src), "--local-workers", "1", "-q"]) == 2
    assert "is the input" in capsys.readouterr().err


def test_fit_options_are_checked_by_the_library_table(tmp_path):
    # The batch's fit options go through the library's fit table: the command line's messages,
    # InvalidArgumentError (exit 2 from the command), never a traceback or a wrapped seed.
    shutil.copy(DATA / "open_box.off", tmp_path / "a.off")
    for kw, words in ((dict(seed=-1), "seed '-1': expected an integer from 0 to"),
                      (dict(n=0), "n '0': expected an integer from 1 to 1000000"),
                      (dict(quality="great"), "quality 'great': expected fast, default or best"),
                      (dict(decimation=17), "decimation '17': expected a number from 0 to 16")):
        with pytest.raises(ss.InvalidArgumentError, match=words):
            batch.list_items(str(tmp_path), batch.batch_options(**kw))
    assert batch._exit_code(ss.InvalidArgumentError("x")) == 2


def test_repair_options_are_checked_by_the_library_table(tmp_path, capsys):
    # The command's repair flags come from the library's repair table, and their text is parsed
    # by it before any cluster starts: the messages of `sphereset batch`, exit 2.
    shutil.copy(DATA / "open_box.off", tmp_path / "a.off")
    out = tmp_path / "out"
    for flags, words in ((["--weld-tolerance", "nan"], "weld_tolerance 'nan': expected a number"),
                         (["--wrap-alpha", "-1"], "wrap_alpha '-1': expected a number"),
                         (["--repair", "maybe"], "repair 'maybe': expected auto or off")):
        assert batch.main([str(tmp_path), "-o", str(out), "--local-workers", "1", *flags]) == 2
        assert words in capsys.readouterr().err
    assert not out.exists()
    flags = {row["flag"] for row in ss._core._repair_option_table()}
    assert flags == {"--repair", "--weld-tolerance", "--wrap-alpha", "--wrap-offset",
                     "--fill-openings"}
    # The library's values, defaults for the rows not given.
    assert ss._core._repair_option_values({"wrap_alpha": "0.5"}) == {
        "repair": "auto", "weld_tolerance": -1.0, "wrap_alpha": 0.5, "wrap_offset": 0.0,
        "fill_cavities": True, "fill_openings": 0.0}
    assert ss._core._repair_option_values({"fill_openings": "auto"})["fill_openings"] == "auto"


def test_an_unreachable_scheduler_is_one_line(tmp_path, capsys):
    """An address nobody answers used to print a traceback."""
    src = tmp_path / "in"
    src.mkdir()
    shutil.copy(DATA / "fr3_link1_collision.stl", src / "link1.stl")
    code = batch.main([str(src), "-o", str(tmp_path / "out"), "--scheduler", "tcp://127.0.0.1:9",
                       "-q"])
    err = capsys.readouterr().err
    assert code == 2
    assert "Traceback" not in err
    assert err.startswith("sphereset: --scheduler tcp://127.0.0.1:9: cannot reach the scheduler")
    assert len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


def test_local_workers_beyond_the_cores_are_refused_before_any_start(tmp_path, capsys):
    # --local-workers 100000 used to start that many worker processes before the first item.
    shutil.copy(DATA / "open_box.off", tmp_path / "a.off")
    out = tmp_path / "out"
    cores = len(os.sched_getaffinity(0))
    for k in (0, cores + 1, 100000):
        assert batch.main([str(tmp_path), "-o", str(out), "--local-workers", str(k), "-q"]) == 2
        assert (f"--local-workers {k}: expected an integer from 1 to {cores}"
                in capsys.readouterr().err)
    assert not out.exists()


def test_exit_codes_and_summary_come_from_the_library(tmp_path):
    # One table for every door (exit_codes.hpp, batch.hpp: batchEnd): the exception classes
    # carry the command's codes, and the end of a run is the command's.
    assert [c.exit_code for c in (ss.Error, ss.InvalidArgumentError, ss.UnreadableError,
                                  ss.InvalidDataError, ss.NotSolidError, ss.WriteError)] == [
        1, 2, 3, 4, 5, 6]
    ok = ('{"mesh":"a.off","output":"a.json","status":"ok","n":2,"spheres":2,"er_sum":0.5,'
          '"er_union":0.4,"covered":true,"protrusion":0.1,"tolerance_met":true,"repair":"none",'
          '"seconds":1.0,"error":"",'
          '"fingerprint":"0123456789abcdef"}')
    bare = ss._core._batch_end([ok], "in", str(tmp_path))
    assert bare == {"summary": "1 items: 1 fitted, 0 skipped, 0 failed", "exit_code": 0,
                    "message": ""}
    uncovered = ok.replace('"covered":true', '"covered":false')
    end = ss._core._batch_end([ok, uncovered], "in", str(tmp_path))
    assert end["exit_code"] == 7
    assert end["message"].startswith("in: 1 of 2 items failed the coverage check")
    failed = ('{"mesh":"b.off","output":"b.json","status":"error","n":2,"spheres":0,'
              '"er_sum":null,"er_union":null,"covered":false,"protrusion":null,'
              '"tolerance_met":true,"repair":"","seconds":0.1,'
              '"error":"b.off: no such file","fingerprint":""}')
    end = ss._core._batch_end([ok, uncovered, failed], "in", str(tmp_path))
    assert (end["summary"], end["exit_code"]) == ("3 items: 2 fitted, 0 skipped, 1 failed", 8)
    assert end["message"] == f"in: 1 of 3 items failed (see {tmp_path / 'report.jsonl'})"


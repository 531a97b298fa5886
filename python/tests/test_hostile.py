"""The hostile-input table (tests/hostile/cases.json) through the command line and the Python
module: the same status (exit code, exception class) and the same message from both, matching
the table, and nothing written. tests/hostile/test_hostile.cpp runs it through the C++ API."""

import json
import pathlib
import re
import subprocess

import pytest

import sphereset as ss
from sphereset import batch
from conftest import SOURCE_DIR, cli_path

HOSTILE = SOURCE_DIR / "tests" / "hostile"
CASES = json.loads((HOSTILE / "cases.json").read_text())

# Status -> (exit code of the command line, exception class of the Python module).
STATUS = {"invalid_argument": (2, ss.InvalidArgumentError), "unreadable": (3, ss.UnreadableError),
          "invalid_data": (4, ss.InvalidDataError), "not_solid": (5, ss.NotSolidError),
          "write_failed": (6, ss.WriteError)}
TABLES = (ss._core._fit_option_table() + ss.eval_option_table()
          + ss._core._repair_option_table() + ss._core._tree_option_table()
          + ss._core._robot_option_table() + ss._core._animate_option_table()
          + ss._core._skinned_load_option_table())
ROWS = {row["name"]: row for row in TABLES}


def flag(name):
    return ROWS[name]["flag"].split(",")[-1]


def command(case, files, out):
    op, opts = case["op"], case.get("options", {})
    flags = [x for name, value in opts.items() for x in (flag(name), value)]
    if op == "fit":
        return ["fit", files[0], "-o", out / "x.json", "-q", *flags]
    if op == "repair":
        return ["check", files[0], *flags]
    if op == "batch":
        return ["batch", files[0], "-o", out / "b", "-q", *flags]
    if op == "tree":
        return ["tree", files[0], "-o", out / "t.sph", "-q", *flags]
    if op == "eval":
        return ["eval", files[0], files[1], *flags]
    if op == "query":
        return ["query", files[0], "--point", ",".join(str(v) for v in case["point"])]
    if op == "robot":
        package = str(pathlib.Path(files[0]).parent)
        return ["robot", files[0], "--package-path", package, "-o", out / "r.yml", "-q", *flags]
    if op == "animate":
        return ["animate", files[0], files[1], "--animation", files[0], "-o", out / "anim", "-q",
                *flags]
    if op == "links":  # a planner's sphere file (cuRobo, Lula) read for a link of a robot
        robot = HOSTILE.parent / "data" / "robot"
        return ["eval", robot / "three_link.urdf", files[0], "--link", "link1",
                "--package-path", robot]
    raise AssertionError(op)


def python_value(name, text):
    """The keyword's value a Python user would pass for the typed text: a number of the row's
    type, a name, or {link: value} for a keyed row."""
    row = ROWS[name]
    if row["key"] is not None:
        key, value = text.rsplit("=", 1)
        if row["type"] == "choice":
            return {key: value}
        return {key: float(value) if row["type"] == "real" else int(value)}
    if row["type"] == "choice":
        return text
    return float(text) if row["type"] == "real" else int(text)


def python_call(case, files):
    opts = {name: python_value(name, v) for name, v in case.get("options", {}).items()}
    op = case["op"]
    if op == "fit":
        return lambda: ss.fit(files[0], **opts)
    if op == "repair":
        return lambda: ss.solid(files[0], **opts)
    if op == "batch":
        return lambda: batch.list_items(files[0], batch.batch_options(**opts))
    if op == "tree":
        return lambda: ss.tree(files[0], **opts)
    if op == "eval":
        return lambda: ss.evaluate(files[0], ss.read_spheres(files[1]), **opts)
    if op == "query":
        point = [[float(v) for v in case["point"]]]
        return lambda: ss.point_distance(ss.read_sphere_tree(files[0]), point)
    if op == "robot":
        package = str(pathlib.Path(files[0]).parent)
        return lambda: ss.fit_robot(files[0], package_paths=[package], quality="fast", **opts)
    if op == "animate":
        load = {k: v for k, v in opts.items() if k == "fps"}
        move = {k: v for k, v in opts.items() if k != "fps"}
        return lambda: ss.animate(None, ss.read_spheres(files[1]),
                                  ss.load_animation(files[0], **load), **move)
    if op == "links":
        return lambda: ss.read_link_spheres(files[0])
    raise AssertionError(op)


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_every_door_gives_the_same_status_and_message(case, tmp_path):
    exe = cli_path()
    if exe is None:
        pytest.skip("the sphereset command-line tool is not available (set SPHERESET_CLI)")
    if case.get("mujoco") and not ss.mujoco_available():
        pytest.skip("built without MuJoCo")
    files = [str((HOSTILE / f).resolve()) for f in case["inputs"]]
    code, error_class = STATUS[case["code"]]
    out = tmp_path / "out"
    out.mkdir()
    r = subprocess.run([exe, *map(str, command(case, files, out))], capture_output=True,
                       timeout=60)
    stderr = r.stderr.decode()
    if r.returncode == 5 and case.get("repair"):
        pytest.skip("built without the repair library")
    assert r.returncode == code, stderr
    assert stderr.startswith("sphereset: ") and stderr.count("\n") == 1, stderr
    message = stderr[len("sphereset: "):].rstrip("\n")
    assert re.search(case["message"], message), message
    with pytest.raises(ss.Error) as e:
        python_call(case, files)()
    assert type(e.value) is error_class
    assert str(e.value) == message
    assert not any(out.iterdir())  # nothing written

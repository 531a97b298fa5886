"""Shared fixtures: the repository's test data and the command-line tool built beside the
module (SPHERESET_CLI, set by CTest; the tests that compare with it are skipped without it)."""

import os
import pathlib
import shutil
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(
    os.environ.get("SPHERESET_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DATA = SOURCE_DIR / "tests" / "data"
LINK = DATA / "fr3_link1_collision.stl"  # 300 triangles, a closed solid
SPOT = SOURCE_DIR / "examples" / "spot.obj"


def cli_path():
    p = os.environ.get("SPHERESET_CLI") or shutil.which("sphereset")
    return p if p and os.path.exists(p) else None


@pytest.fixture
def cli():
    p = cli_path()
    if p is None:
        pytest.skip("the sphereset command-line tool is not available (set SPHERESET_CLI)")

    def run(*args, check=True):
        r = subprocess.run([p, *map(str, args)], capture_output=True, text=True)
        if check and r.returncode != 0:
            raise AssertionError(f"sphereset {' '.join(map(str, args))}: exit {r.returncode}: "
                                 f"{r.stderr}")
        return r

    return run


def cube_arrays(size=1.0, offset=(0.0, 0.0, 0.0)):
    """The cube [0, size]^3 + offset, outward-oriented, as (vertices, faces)."""
    import numpy as np
    v = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float) * size
    v += np.asarray(offset, float)
    f = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                  [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]], np.int64)
    return v, f

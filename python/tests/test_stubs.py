"""The extension's stubs are stubgen's, from the module as built: a binding changed without
`bash scripts/update_stubs.sh` fails here."""

import os
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR


def test_stubs_are_stubgens_output(tmp_path):
    stubgen = shutil.which("stubgen")
    if stubgen is None:
        pytest.skip("mypy's stubgen is not installed (scripts/setup.sh installs it)")
    import sphereset
    package_parent = os.path.dirname(os.path.dirname(sphereset.__file__))
    env = dict(os.environ, PYTHONPATH=package_parent)
    subprocess.run([sys.executable, stubgen, "-p", "sphereset._sphereset", "-o", str(tmp_path)],
                   check=True, env=env, capture_output=True)
    generated = (tmp_path / "sphereset" / "_sphereset.pyi").read_text()
    checked_in = (SOURCE_DIR / "python" / "sphereset" / "_sphereset.pyi").read_text()
    assert generated == checked_in, "the bindings changed: run bash scripts/update_stubs.sh"

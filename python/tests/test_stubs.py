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


def test_result_classes_are_made_from_the_library_fields(tmp_path):
    import sphereset
    package_parent = os.path.dirname(os.path.dirname(sphereset.__file__))
    env = dict(os.environ, PYTHONPATH=package_parent)
    out = tmp_path / "_results.py"
    subprocess.run([sys.executable, str(SOURCE_DIR / "scripts" / "gen_results.py"), str(out)],
                   check=True, env=env, capture_output=True)
    checked_in = (SOURCE_DIR / "python" / "sphereset" / "_results.py").read_text()
    assert out.read_text() == checked_in, "the result fields changed: run scripts/update_stubs.sh"
    # And the classes hold exactly the library's fields (plus the door's own).
    names = {f.name for f in sphereset.FitResult.__dataclass_fields__.values()}
    schema = {row["name"].split(".")[0] for row in sphereset._core._result_schema("fit")}
    assert schema <= names and names - schema == {"spheres", "options", "repair"}

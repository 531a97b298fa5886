"""Writes python/sphereset/_results.py, the Python classes of the library's results, from the
field lists the extension module reports (result_fields.hpp through _result_schema): one
definition of each field's name, type and meaning. Run by scripts/update_stubs.sh; the tests
check that the file equals this script's output (python/tests/test_stubs.py).

    PYTHONPATH=build/python /usr/bin/python3 scripts/gen_results.py OUT.py
"""

import glob
import importlib.util
import os
import sys


def _extension():
    """The extension module alone, without the package's __init__ (which imports the file this
    script writes)."""
    package = importlib.util.find_spec("sphereset").submodule_search_locations[0]
    path = glob.glob(os.path.join(package, "_sphereset*.so"))[0]
    spec = importlib.util.spec_from_file_location("sphereset._sphereset", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


core = _extension()

TYPES = {"bool": "bool", "int": "int", "float": "float", "str": "str", "array": "np.ndarray",
         "int_array": "np.ndarray", "str_list": "List[str]"}

# Per class: its docstring, the fields the front door adds before and after the library's, and
# methods.
CLASSES = {
    "fit": dict(
        name="FitResult",
        doc='''A fitted sphere set and the fit's diagnostics (fit.hpp's FitResult).

    ``spheres`` is (n, 4) float64 rows x, y, z, r; ``er_sum`` the paper's E_r (Σ outside volume
    / mesh volume, of the repaired solid's volume when the mesh was repaired); ``seconds`` the
    timings by phase; ``options`` the options the fit ran with (after the quality preset);
    ``repair`` what the repair did. The other fields are the library's (result_fields.hpp).''',
        before=[("spheres", "np.ndarray", "(n, 4) rows x, y, z, r")],
        after=[("options", "Dict[str, Any]", "the options the fit ran with"),
               ("repair", "Dict[str, Any]", "what the repair did")],
        methods=""),
    "eval": dict(
        name="EvalResult",
        doc='''How tightly a sphere set bounds a solid (evaluate.hpp's EvalResult, as
    ``sphereset eval --json`` reports it): E_r summed (exact) and of the union (Monte Carlo,
    with its standard error), certified surface/interior/original coverage with the largest gaps
    (fractions of the bounding-box diagonal), proximity and shadow errors.''',
        before=[("spheres", "int", "spheres measured")],
        after=[("repair", "Dict[str, Any]", "what the repair did")],
        methods='''
    @property
    def covered(self) -> bool:
        """Surface, interior and original triangles all certified covered."""
        return self.surface_covered and self.interior_covered and self.original_covered
'''),
    "animate": dict(
        name="AnimateResult",
        columns="animate_frame",
        doc='''A sphere set moved through the frames of a deforming mesh (animate.hpp's AnimateResult,
    with the per-frame fields of AnimateFrameResult as arrays over the F frames).

    ``spheres`` (F, N, 4): the moved sets (grown, with ``rebound``); ``times`` the frames'
    times. ``er``, ``surface_covered``, ``interior_covered``, ``max_gap`` certify the moved set
    with the rest radii; ``crossings`` counts crossing triangle pairs of the deformed mesh (a
    frame that passes through itself is no solid: its figures are not meaningful). The rebound
    and fresh-fit fields are 0 unless asked for.''',
        before=[("spheres", "np.ndarray", "(F, N, 4) the set in each frame"),
                ("times", "np.ndarray", "(F,) the frames' times")],
        after=[("rebound", "bool", "whether radii were grown per frame")],
        methods='''
    @property
    def covered(self) -> np.ndarray:
        """Per frame, whether the set in ``spheres`` is certified to cover the deformed surface
        and interior: ``rebound_covered`` with rebound, else surface and interior covered."""
        if self.rebound:
            return self.rebound_covered.copy()
        return self.surface_covered & self.interior_covered

    def __len__(self) -> int:
        return int(self.spheres.shape[0])
'''),
    "robot_link": dict(
        name="RobotLinkFit",
        doc='''One link of a robot fit (robot_fit.hpp's RobotLinkFit): ``spheres`` (N, 4), its sphere
    primitives first then the fitted spheres, padded; when fitted, ``repair`` and ``eval`` (the
    fitted spheres' evaluation before padding, as :class:`EvalResult`'s fields).''',
        before=[("spheres", "np.ndarray", "(N, 4) rows x, y, z, r")],
        after=[("repair", "Optional[Dict[str, Any]]", "when fitted: what the repair did"),
               ("eval", "Optional[Dict[str, Any]]", "when fitted: the fitted spheres' evaluation")],
        methods=""),
    "robot": dict(
        name="RobotFitResult",
        doc='''A whole robot fitted (robot_fit.hpp's RobotFitResult): ``links`` in the robot's order
    (the links with geometry); with a budget, the total outside volume as chosen and for the
    curve split alone.''',
        before=[("robot", "str", "the robot's name"), ("urdf", "str", "the URDF read"),
                ("links", "List[RobotLinkFit]", "the links with geometry, in order")],
        after=[],
        methods='''
    @property
    def spheres(self) -> Dict[str, np.ndarray]:
        """{link: (N, 4) spheres} of the links not skipped, in order: what
        :func:`write_robot_spheres` and :func:`write_sphere_urdf` take."""
        return {lf.link: lf.spheres for lf in self.links if not lf.skipped}

    @property
    def covered(self) -> bool:
        """Every link's spheres certified to cover it."""
        return all(lf.covered for lf in self.links)
'''),
}

# The numpy type of each per-frame column.
DTYPES = {"bool": "bool", "int": "np.int64", "float": "np.float64"}

HEADER = '''"""The result classes of the fit and the evaluation, written by scripts/gen_results.py from the
library's field lists (result_fields.hpp): do not edit; the tests check this file against the
script's output."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Dict, List, Optional

import numpy as np


def _plain(value: Any) -> Any:
    """Arrays as lists, through dicts and lists: what JSON takes."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value
'''


def fields(kind):
    """(name, annotation, help) of a result, dotted groups as one Dict field."""
    out, groups = [], {}
    for row in core._result_schema(kind):
        name, typ, help_ = row["name"], TYPES[row["type"]], row["help"]
        if "." in name:
            group, member = name.split(".", 1)
            if group not in groups:
                groups[group] = []
                out.append((group, None, None))
            groups[group].append((member, typ, help_))
            continue
        out.append((name, typ, help_))
    result = []
    for name, typ, help_ in out:
        if typ is None:
            members = groups[name]
            types = {t for _, t, _ in members}
            help_ = "; ".join(f"{m}: {h}" for m, _, h in members)
            typ = f"Dict[str, {types.pop() if len(types) == 1 else 'Any'}]"
        result.append((name, typ, help_))
    return result


def render():
    parts = [HEADER]
    for kind, c in CLASSES.items():
        lines = ["", "", "@dataclass", f"class {c['name']}:", f'    """{c["doc"]}"""', ""]
        columns = []
        if "columns" in c:  # one array over the frames per field of the frame's list
            columns = [(name, "np.ndarray", "per frame: " + help_)
                       for name, _, help_ in fields(c["columns"])]
        for name, typ, help_ in c["before"] + columns + fields(kind) + c["after"]:
            lines.append(f"    {name}: {typ}")
            lines.append(f'    """{help_}"""')
        lines.append(c["methods"].rstrip("\n") if c["methods"] else "")
        lines += ["", "    def to_dict(self) -> Dict[str, Any]:",
                  '        """The fields as a dict (arrays as lists), e.g. for JSON."""',
                  "        return {k: _plain(v) for k, v in dataclasses.asdict(self).items()}"]
        parts.append("\n".join(lines))
    frame = "".join(f'\n    "{r["name"]}": {DTYPES[r["type"]]},'
                    for r in core._result_schema("animate_frame"))
    parts.append("\n\n\n# AnimateResult's per-frame columns and their types.\n"
                 f"FRAME_COLUMNS: Dict[str, Any] = {{{frame}\n}}")
    return "".join(parts) + "\n"


if __name__ == "__main__":
    with open(sys.argv[1], "w", encoding="utf-8") as f:
        f.write(render())

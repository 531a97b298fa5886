"""Writes python/sphereset/_results.py, the Python classes of the library's results, from the
field lists the extension module reports (result_fields.hpp through _result_schema): one
definition of each field's name, type and meaning. Run by scripts/update_stubs.sh; the tests
check that the file equals this script's output (python/tests/test_stubs.py).

    PYTHONPATH=build/python /usr/bin/python3 scripts/gen_results.py OUT.py
"""

import sys

from sphereset import _sphereset as core

TYPES = {"bool": "bool", "int": "int", "float": "float", "array": "np.ndarray"}

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
}

HEADER = '''"""The result classes of the fit and the evaluation, written by scripts/gen_results.py from the
library's field lists (result_fields.hpp): do not edit; the tests check this file against the
script's output."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Dict

import numpy as np


def _plain(value: Any) -> Any:
    return value.tolist() if isinstance(value, np.ndarray) else value
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
        for name, typ, help_ in c["before"] + fields(kind) + c["after"]:
            lines.append(f"    {name}: {typ}")
            lines.append(f'    """{help_}"""')
        lines.append(c["methods"].rstrip("\n") if c["methods"] else "")
        lines += ["", "    def to_dict(self) -> Dict[str, Any]:",
                  '        """The fields as a dict (arrays as lists), e.g. for JSON."""',
                  "        return {k: _plain(v) for k, v in dataclasses.asdict(self).items()}"]
        parts.append("\n".join(lines))
    return "".join(parts) + "\n"


if __name__ == "__main__":
    with open(sys.argv[1], "w", encoding="utf-8") as f:
        f.write(render())

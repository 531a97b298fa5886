"""What every function of the package shares: the path and mesh types, the repair keywords (defined
once, from the library's repair table) and reading a mesh."""

from __future__ import annotations

import functools
import inspect
import os
from typing import Any, Callable, Dict, TypeVar, Union, cast

from . import _sphereset as _core
from ._sphereset import Mesh, Solid

PathLike = Union[str, "os.PathLike[str]"]
MeshLike = Union[Mesh, Solid, PathLike]
ProgressCallback = Callable[[Dict[str, Any]], None]


def _size_text(value: Union[float, str]) -> str:
    """A length keyword as the text the library's table parses ("auto" stays a word)."""
    return value if isinstance(value, str) else repr(float(value))


def _repair_keyword_values(texts: Dict[str, str]) -> Dict[str, Any]:
    """The repair keywords of every function that makes a solid, from the texts a user typed
    ({} for the defaults), parsed and checked by the library's repair table: repair,
    weld_tolerance (None: automatic), fill_cavities, wrap_alpha, wrap_offset, fill_openings."""
    d = _core._repair_option_values(texts)
    d["weld_tolerance"] = None if d["weld_tolerance"] < 0 else d["weld_tolerance"]
    return {k: d[k] for k in ("repair", "weld_tolerance", "fill_cavities", "wrap_alpha",
                              "wrap_offset", "fill_openings")}


# Defined once, here: the functions below get them from `_repair_keywords`.
REPAIR_KEYWORDS: Dict[str, Any] = _repair_keyword_values({})

_F = TypeVar("_F", bound=Callable[..., Any])


def _repair_keywords(fn: _F) -> _F:
    """Gives ``fn`` the repair keywords (REPAIR_KEYWORDS, keyword-only, shown in its signature)
    and passes them to it as one dict, ``repair_options``."""
    sig = inspect.signature(fn)
    own = [p for name, p in sig.parameters.items() if name != "repair_options"]
    extra = [inspect.Parameter(k, inspect.Parameter.KEYWORD_ONLY, default=v)
             for k, v in REPAIR_KEYWORDS.items()]

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        repair = {k: kwargs.pop(k, v) for k, v in REPAIR_KEYWORDS.items()}
        return fn(*args, repair_options=repair, **kwargs)

    wrapper.__signature__ = sig.replace(parameters=own + extra)  # type: ignore[attr-defined]
    return cast(_F, wrapper)


def _repair_args(ro: Dict[str, Any]) -> Dict[str, Any]:
    """The repair keywords as the extension takes them, in its order: repair "auto"/"off"
    (True/False too), weld_tolerance (-1: automatic), fill_cavities, wrap_alpha, wrap_offset,
    fill_openings as text."""
    repair = ro["repair"]
    if repair is True:
        repair = "auto"
    elif repair is False:
        repair = "off"
    return {"repair": repair,
            "weld_tolerance": -1.0 if ro["weld_tolerance"] is None else float(ro["weld_tolerance"]),
            "fill_cavities": bool(ro["fill_cavities"]), "wrap_alpha": float(ro["wrap_alpha"]),
            "wrap_offset": float(ro["wrap_offset"]),
            "fill_openings": _size_text(ro["fill_openings"])}


def load_mesh(path: PathLike, *, weld_tolerance: float = 0.0) -> Mesh:
    """Reads a mesh file (OBJ, PLY, STL, OFF, DAE, glTF/GLB, ... anything assimp reads).

    Vertices closer than ``weld_tolerance`` are merged (0: exact duplicates only), degenerate
    and duplicate triangles dropped, the orientation made outward. Raises UnreadableError
    (missing file, unknown format) or InvalidDataError (NaN, bad index, no triangles).
    """
    return _core._load_mesh(os.fspath(path), weld_tolerance)

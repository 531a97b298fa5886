"""Every front door's keywords are the rows of the library's option tables: each row of a table
is a keyword of the Python function that takes it, with the row's default (None where the row's
default comes from elsewhere, e.g. a quality preset)."""

import inspect

import pytest

import sphereset as ss
from sphereset import _sphereset as core

DOORS = [
    (ss.fit, core._fit_option_table, ()),
    (ss.tree, core._fit_option_table, ("n",)),
    (ss.evaluate, core._eval_option_table, ()),
    (ss.solid, core._repair_option_table, ()),
    (ss.fit_robot, core._robot_option_table, ()),
    (ss.fit_robot, core._fit_option_table,
     ("n", "points", "iterations", "restarts", "decimation", "padding", "optimizer", "init",
      "method")),
    (ss.sample_self_collisions, core._collision_option_table, ()),
    (ss.animate, core._animate_option_table, ()),
    (ss.load_animation, core._skinned_load_option_table, ()),
]


def default_of(row):
    """The row's default as a Python value, or None when it is not a literal."""
    text = row["default"]
    if row["key"] is not None:
        return {}
    if row["type"] == "choice":
        return text
    try:
        return float(text) if row["type"] == "real" else int(text)
    except ValueError:
        return None


@pytest.mark.parametrize("function,table,skip", DOORS,
                         ids=[f"{d[0].__name__}-{d[1].__name__}" for d in DOORS])
def test_keywords_are_the_rows(function, table, skip):
    params = inspect.signature(function).parameters
    for row in table():
        if row["name"] in skip:
            continue
        assert row["name"] in params, f"{function.__name__} lacks the keyword {row['name']}"
        given = params[row["name"]].default
        want = default_of(row)
        if given is None or want is None:
            continue  # the library's default (None keeps it) or a default that is not a literal
        if isinstance(want, dict):
            assert given is None or given == {}, row["name"]
        else:
            assert given == want, (row["name"], given, want)


def test_repair_keywords_have_one_home():
    # Every function that makes a solid takes the same repair keywords, with the library's
    # defaults (REPAIR_KEYWORDS, from its repair table), and refuses others as Python does.
    from sphereset import batch
    assert ss.REPAIR_KEYWORDS == {"repair": "auto", "weld_tolerance": None,
                                  "fill_cavities": True, "wrap_alpha": 0.0, "wrap_offset": 0.0,
                                  "fill_openings": 0.0}
    for function in (ss.solid, ss.check, ss.fit, ss.evaluate, ss.tree, ss.fit_robot,
                     batch.batch_options):
        params = inspect.signature(function).parameters
        assert "repair_options" not in params, function.__name__
        for name, default in ss.REPAIR_KEYWORDS.items():
            assert params[name].kind == inspect.Parameter.KEYWORD_ONLY, (function.__name__, name)
            assert params[name].default == default, (function.__name__, name)
    with pytest.raises(TypeError, match="wrap_alfa"):
        ss.fit(object(), 4, wrap_alfa=0.5)
    opts = batch.batch_options(4, wrap_alpha=0.25, weld_tolerance=None, fill_cavities=False)
    assert (opts["wrap_alpha"], opts["weld_tolerance"], opts["fill_cavities"]) == (0.25, -1.0, False)


def test_percent_rows_are_marked():
    # A row that takes a trailing '%' says so: the protrusion limits, fit's (of the diagonal)
    # and the robot's (of each link's diagonal).
    tables = [getattr(core, name) for name in dir(core) if name.endswith("_option_table")]
    assert len(tables) >= 9
    marked = {(t.__name__, row["name"]) for t in tables for row in t() if row["percent"]}
    assert marked == {("_tolerance_option_table", "max_protrusion"),
                      ("_robot_option_table", "max_protrusion"),
                      ("_robot_option_table", "link_max_protrusion")}

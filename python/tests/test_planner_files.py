"""The planner files of `sphereset robot` read back by readers other than the ones the library
uses: MoveIt's SRDF by Python's xml.etree, cuRobo's YAML and Lula's robot description by PyYAML.
Each must say what the command's JSON report says: the same disabled pairs with their reasons,
the same spheres per link, the robot's movable joints."""

import json
import xml.etree.ElementTree as ElementTree

import pytest

from conftest import DATA

yaml = pytest.importorskip("yaml")


def test_srdf_lula_and_curobo_read_back_independently(cli, tmp_path):
    robot = DATA / "robot"
    outs = {ext: tmp_path / f"three{ext}" for ext in (".srdf", ".lula.yml", ".yml", ".json")}
    args = ["robot", robot / "three_link.urdf", "--package-path", robot, "--budget", "8",
            "--quality", "fast", "-q"]
    for path in outs.values():
        args += ["-o", path]
    cli(*args)
    report = json.loads(outs[".json"].read_text())
    disabled = {(p["link1"], p["link2"], p["reason"])
                for p in report["self_collision"]["disabled"]}
    assert disabled, "the test robot has adjacent links at least"
    assert {r for _, _, r in disabled} <= {"Adjacent", "Default", "Always", "Never"}
    spheres = {link["link"]: link["spheres"] for link in report["links"] if link["spheres"]}
    assert spheres

    # SRDF: the robot's name, a chain group from the root, every disabled pair with its reason.
    srdf = ElementTree.parse(outs[".srdf"]).getroot()
    assert srdf.tag == "robot" and srdf.get("name") == report["robot"]
    chains = srdf.findall("group/chain")
    assert len(chains) == 1 and chains[0].get("base_link") == "base_link"
    assert {(d.get("link1"), d.get("link2"), d.get("reason"))
            for d in srdf.findall("disable_collisions")} == disabled

    # cuRobo: the spheres per link, and the ignore list holds exactly the disabled pairs.
    curobo = yaml.safe_load(outs[".yml"].read_text())
    got = {link: [[*s["center"], s["radius"]] for s in ss]
           for link, ss in curobo["collision_spheres"].items()}
    assert got.keys() == spheres.keys()
    for link, ss in spheres.items():
        assert sum(got[link], []) == pytest.approx(sum(ss, []), rel=1e-12, abs=1e-15)
    ignored = {tuple(sorted((a, b))) for a, bs in curobo["self_collision_ignore"].items()
               for b in bs}
    assert ignored == {tuple(sorted((a, b))) for a, b, _ in disabled}

    # Lula: the movable joints as the c-space, a default configuration for each, and the same
    # spheres as a list of one-link maps.
    lula = yaml.safe_load(outs[".lula.yml"].read_text())
    assert lula["cspace"] == ["joint1", "joint2"]
    assert lula["default_q"] == [0.0, 0.0]
    got = {}
    for entry in lula["collision_spheres"]:
        ((link, ss),) = entry.items()
        got[link] = [[*s["center"], s["radius"]] for s in ss]
    assert got.keys() == spheres.keys()
    for link, ss in spheres.items():
        assert sum(got[link], []) == pytest.approx(sum(ss, []), rel=1e-12, abs=1e-15)

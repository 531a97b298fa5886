"""Sphere files, trees, queries and robots through the module, against brute-force numpy."""

import json

import numpy as np
import pytest

import sphereset as ss
from conftest import DATA, LINK

RNG = np.random.default_rng(7)
SPHERES = np.column_stack([RNG.normal(size=(20, 3)), RNG.uniform(0.1, 0.6, 20)])


@pytest.mark.parametrize("ext", ["txt", "json", "sph", "yaml"])
def test_sphere_io_round_trip(tmp_path, ext):
    p = tmp_path / f"s.{ext}"
    ss.write_spheres(p, SPHERES, name="link_a", source_mesh="m.obj")
    assert ss.sphere_format(p) == ext
    back = ss.read_spheres(p)
    assert back.shape == SPHERES.shape and back.dtype == np.float64
    assert np.array_equal(back, SPHERES)
    assert p.read_text() == ss.format_spheres(ext, SPHERES, name="link_a", source_mesh="m.obj")


def test_sphere_io_errors(tmp_path):
    with pytest.raises(ss.InvalidArgumentError):
        ss.sphere_format("a.xyz")
    with pytest.raises(ss.UnreadableError):
        ss.read_spheres(tmp_path / "none.txt")
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0 0\n")
    with pytest.raises(ss.InvalidDataError, match="bad.txt:1"):
        ss.read_spheres(bad)
    with pytest.raises(ss.WriteError):
        ss.write_spheres(tmp_path / "no" / "dir" / "s.txt", SPHERES)


def test_link_spheres_round_trip(tmp_path):
    links = {"base": SPHERES[:3], "arm": SPHERES[3:8], "empty": np.zeros((0, 4))}
    p = tmp_path / "robot.yml"
    ss.write_link_spheres(p, links)
    back = ss.read_link_spheres(p)
    assert list(back) == ["base", "arm", "empty"]
    for k in links:
        assert np.array_equal(back[k].reshape(-1, 4), links[k])
    two = ss.read_link_spheres(DATA / "curobo_two_links.yml")
    assert len(two) == 2


def test_tree_fit_build_and_files(tmp_path):
    t = ss.tree(LINK, branching=4, depth=2, quality="fast")
    assert t.tree.branching == 4 and t.tree.depth == 2 and t.tree.leaves().shape == (16, 4)
    assert [lv["level"] for lv in t.levels] == [0, 1, 2]
    t.tree.check()
    for ext in ("sph", "json"):
        p = tmp_path / f"t.{ext}"
        ss.write_sphere_tree(p, t.tree)
        back = ss.read_sphere_tree(p)
        assert np.array_equal(back.nodes, t.tree.nodes) and back.depth == 2
        assert p.read_text() == ss.format_sphere_tree(ext, t.tree)
    b = ss.build_tree(SPHERES, branching=3, depth=3)
    b.tree.check()
    leaves = b.tree.leaves()
    assert sorted(map(tuple, leaves)) == sorted(map(tuple, SPHERES))
    # Every parent encloses its children.
    root = b.tree.level(0)[0]
    assert np.all(np.linalg.norm(SPHERES[:, :3] - root[:3], axis=1) + SPHERES[:, 3]
                  <= root[3] * (1 + 1e-12))


def test_queries_against_brute_force():
    pts = RNG.normal(scale=2.0, size=(200, 3))
    d_all = np.linalg.norm(pts[:, None, :] - SPHERES[None, :, :3], axis=2) - SPHERES[None, :, 3]
    q = ss.point_distance(SPHERES, pts)
    assert np.allclose(q.distance, d_all.min(axis=1), rtol=0, atol=1e-12)
    assert np.allclose(d_all[np.arange(len(pts)), q.sphere], q.distance, atol=1e-12)
    assert np.array_equal(q.inside, d_all.min(axis=1) <= 0)
    assert np.array_equal(ss.contains(ss.query_tree(SPHERES), pts), q.inside)
    # A segment far from every sphere is outside over its whole length.
    a = np.array([[50.0, 0, 0]])
    b = np.array([[60.0, 0, 0]])
    assert ss.segment_outside_length(SPHERES, a, b)[0] == pytest.approx(10.0)
    # Through one sphere alone: outside length = length - chord.
    one = np.array([[0.0, 0, 0, 1.0]])
    assert ss.segment_outside_length(one, [[-3.0, 0, 0]], [[3.0, 0, 0]])[0] == pytest.approx(4.0)
    # Separation of two sets under poses, against all pairs.
    other = SPHERES[:5].copy()
    pose = np.eye(4)
    pose[:3, 3] = [4.0, 0.5, 0.0]
    moved = other[:, :3] + pose[:3, 3]
    pair = (np.linalg.norm(SPHERES[:, None, :3] - moved[None], axis=2)
            - SPHERES[:, None, 3] - other[None, :, 3])
    s = ss.separation(SPHERES, other, pose_b=pose)
    assert s.distance == pytest.approx(pair.min(), abs=1e-12)
    assert pair[s.sphere_a, s.sphere_b] == pytest.approx(s.distance, abs=1e-12)
    assert ss.overlaps(SPHERES, other, pose_b=pose).overlap == (pair.min() < 0)
    assert ss.overlaps(SPHERES, SPHERES).overlap


def test_queries_refuse_non_finite_inputs():
    # The library refuses what it cannot answer in finite numbers (it used to say "outside, inf").
    with pytest.raises(ss.InvalidArgumentError, match=r"^point \(nan 0 0\): coordinates must"):
        ss.point_distance(SPHERES, [[0.0, 0, 0], [np.nan, 0, 0]])
    with pytest.raises(ss.InvalidArgumentError, match=r"^point \(1e\+31 0 0\)"):
        ss.point_distance(SPHERES, [[0.0, 0, 0], [1e31, 0, 0]])
    with pytest.raises(ss.InvalidArgumentError, match="segment end"):
        ss.segment_outside_length(SPHERES, [[0.0, 0, 0]], [[1e154, 1e154, 1e154]])
    pose = np.eye(4)
    pose[0, 3] = 1e31
    with pytest.raises(ss.InvalidArgumentError, match="pose_b translation"):
        ss.separation(SPHERES, SPHERES, pose_b=pose)


def test_unbalanced_tree_keeps_its_leaves():
    # A root over two children, only the first with children: the second is a leaf.
    none = [0.0, 0, 0, -1]
    t = ss.SphereTree([[0, 0, 0, 10], [-3, 0, 0, 4], [5, 0, 0, 2], [-4, 0, 0, 1], [-2, 0, 0, 1],
                       none, none], 2, 2)
    assert len(t.leaves()) == 3
    q = ss.point_distance(t, [[5.0, 0, 0]])
    assert q.inside[0] and q.distance[0] == pytest.approx(-2.0)
    with pytest.raises(ss.InvalidDataError, match="node 2"):
        ss.SphereTree([[0, 0, 0, 10], [-3, 0, 0, 4], [np.nan, 0, 0, 2], [-4, 0, 0, 1],
                       [-2, 0, 0, 1], none, none], 2, 2)


def test_a_tree_whose_parent_lost_its_leaves_is_queried_by_its_leaves(tmp_path):
    # A parent edited (in the page) so that it no longer holds its two leaves, saved and read
    # back: contains used to miss both leaves' centres while `sphereset query` found them.
    path = tmp_path / "edited.sph"
    path.write_text("3 2\n0 0 0 10 0\n-3 0 0 0.1 0\n5 0 0 2 0\n-4 0 0 1 0\n-2 0 0 1 0\n"
                    "4 0 0 1 0\n6 0 0 1 0\n")
    back = ss.read_sphere_tree(path)
    assert len(back.leaves()) == 4
    centres = [[-4.0, 0, 0], [-2, 0, 0], [4, 0, 0], [6, 0, 0]]
    assert ss.contains(back, centres).all()
    q = ss.point_distance(back, centres)
    assert np.allclose(q.distance, -1.0)


def test_robot(tmp_path):
    urdf = DATA / "robot" / "three_link.urdf"
    r = ss.load_robot(urdf, package_paths=[str(DATA / "robot")])
    assert r.root in r.links and len(r.joints) == 3
    poses = r.link_poses()
    assert np.allclose(poses[r.root], np.eye(4))
    moved = r.link_poses({r.joints[0]["name"]: 0.5})
    assert set(moved) == set(poses)
    # NaN used to give NaN matrices; a clamp was silent.
    with pytest.raises(ss.InvalidArgumentError, match="joint 'joint1': nan is not a finite"):
        r.link_poses({"joint1": float("nan")})
    with pytest.raises(ss.InvalidArgumentError, match="no joint 'elbow'"):
        r.link_poses({"elbow": 0.1})
    with pytest.warns(UserWarning, match="joint 'joint1': 100 is beyond its upper limit 1.5"):
        r.link_poses({"joint1": 100.0})
    assert r.joints[0]["mimic"] is None
    links = {}
    for name in r.links:
        geo = r.link_geometry(name)
        if not geo or all(g["kind"] == "sphere" for g in geo):
            continue
        m = r.link_mesh(name)
        assert m.faces.shape[1] == 3
        fit = ss.fit(ss.Mesh(m.vertices, m.faces, name=name), n=2, quality="fast")
        links[name] = np.vstack([r.link_spheres(name), fit.spheres])
    pairs = r.self_collision_pairs(links)
    assert len(pairs["adjacent"]) >= 2
    out = tmp_path / "robot.yml"
    ss.write_robot_spheres(out, links, robot=r)
    assert "self_collision_ignore" in out.read_text()
    assert list(ss.read_link_spheres(out)) == list(links)
    u = tmp_path / "spheres.urdf"
    ss.write_sphere_urdf(urdf, u, links)
    assert u.read_text().count("<sphere") >= sum(len(s) for s in links.values())
    with pytest.raises(ss.InvalidArgumentError, match="no link"):
        r.link_mesh("nope")
    with pytest.raises(ss.UnreadableError):
        ss.load_robot(tmp_path / "none.urdf")
    counts = ss.split_budget([([1, 2, 4], [8.0, 3.0, 1.0]), ([1, 2, 4], [1.0, 0.9, 0.8])],
                             [-1, -1], 6)
    assert sum(counts) == 6 and counts[0] > counts[1]


def test_sample_self_collisions_same_pairs_as_cli(cli, tmp_path):
    urdf = DATA / "robot" / "three_link.urdf"
    out = tmp_path / "robot.json"
    cli("robot", urdf, "--package-path", DATA / "robot", "--quality", "fast",
        "--collision-samples", 500, "--collision-seed", 4, "-o", out, "-q")
    ref = json.loads(out.read_text())
    r = ss.load_robot(urdf, package_paths=[str(DATA / "robot")])
    links = {lf["link"]: np.array(lf["spheres"]) for lf in ref["links"]}
    got = ss.sample_self_collisions(r, links, collision_samples=500, collision_seed=4)
    want = ref["self_collision"]
    for key in ("samples", "check", "pairs", "enabled", "adjacent", "default", "always", "never"):
        assert got[key] == want[key], key
    assert got["disabled"] == [(p["link1"], p["link2"], p["reason"], p["collisions"])
                               for p in want["disabled"]]
    assert got["adjacent"] == 3 and got["samples"] == 500
    meshes = ss.sample_self_collisions(r, links, collision_samples=500, collision_check="meshes")
    assert meshes["check"] == "meshes" and meshes["adjacent"] == 3
    with pytest.raises(ss.InvalidArgumentError, match="always_fraction '0.1'"):
        ss.sample_self_collisions(r, links, always_fraction=0.1)
    with pytest.raises(ss.InvalidArgumentError, match="default_pose: no joint 'elbow'"):
        ss.sample_self_collisions(r, links, default_pose={"elbow": 0.1})


def test_fit_robot_same_spheres_as_cli(cli, tmp_path):
    urdf = DATA / "robot" / "three_link.urdf"
    out = tmp_path / "robot.json"
    cli("robot", urdf, "--package-path", DATA / "robot", "--quality", "fast", "--seed", 3,
        "--budget", 12, "--link-spheres", "base_link=2", "--padding", 0.01, "--link-padding",
        "link1=0.02", "-o", out, "-q")
    r = ss.fit_robot(urdf, budget=12, link_spheres={"base_link": 2}, padding=0.01,
                     link_padding={"link1": 0.02}, package_paths=[DATA / "robot"], seed=3,
                     quality="fast")
    ref = json.loads(out.read_text())
    assert r.robot == ref["robot"]
    assert [lf.link for lf in r.links] == [lf["link"] for lf in ref["links"]]
    for lf, rl in zip(r.links, ref["links"]):
        assert lf.spheres.shape == (rl["count"], 4) and lf.spheres.dtype == np.float64
        np.testing.assert_array_equal(lf.spheres, np.array(rl["spheres"]).reshape(-1, 4))
        assert (lf.primitives, lf.skipped, lf.covered, lf.padding) == (
            rl["primitives"], rl["skipped"], rl["covered"], rl["padding"])
        if lf.fitted:
            assert lf.er_sum == rl["er_sum"] and lf.eval["er_sum"] == rl["er_sum"]
            assert lf.repair["kind"] == rl["repair"]["kind"]
        # One field list (robot_fit.hpp) behind both: every field, same name and value.
        for row in ss._core._result_schema("robot_link"):
            name = row["name"].split(".")[0]
            if name == "seconds":
                continue
            mine = getattr(lf, name)
            if isinstance(mine, dict):
                assert {k: list(v) for k, v in mine.items()} == rl[name], name
            elif isinstance(mine, np.ndarray):
                assert mine.tolist() == rl[name], name
            else:
                assert mine == rl[name], name
    assert r.budget_split and r.outside_volume == ref["outside_volume"] and ref["budget"] == 12
    spheres = r.spheres
    assert len(spheres["base_link"]) == 2
    assert sum(len(s) for s in spheres.values()) <= 12
    assert r.covered
    with pytest.raises(ss.InvalidArgumentError, match="no_such_link"):
        ss.fit_robot(urdf, link_spheres={"no_such_link": 2}, package_paths=[DATA / "robot"],
                     quality="fast")


def test_fit_robot_protrusion_limits():
    # Each fitted link within its limit (the padded set's certified protrusion); a limit no
    # count meets under a budget is reported per link, not raised.
    urdf = DATA / "robot" / "three_link.urdf"
    r = ss.fit_robot(urdf, package_paths=[DATA / "robot"], quality="fast",
                     max_protrusion=0.05, link_max_protrusion={"link2": 0.06})
    assert r.tolerance and r.tolerance_met
    for lf in r.links:
        if lf.fitted:
            assert lf.protrusion_limit == (0.06 if lf.link == "link2" else 0.05)
            assert lf.limit_met and lf.protrusion <= lf.protrusion_limit
    tight = ss.fit_robot(urdf, package_paths=[DATA / "robot"], quality="fast", budget=6,
                         max_protrusion=1e-9)
    assert tight.tolerance and not tight.tolerance_met
    assert sum(len(s) for s in tight.spheres.values()) <= 6
    with pytest.raises(ss.InvalidArgumentError,
                       match="link_max_protrusion 'link2=0': expected LINK=VALUE, VALUE a number "
                             "above 0"):
        ss.fit_robot(urdf, package_paths=[DATA / "robot"], link_max_protrusion={"link2": 0})
    # "P%": a percentage of each link's own diagonal, so the links' limits differ; the length
    # given for link2 is its own.
    pct = ss.fit_robot(urdf, package_paths=[DATA / "robot"], quality="fast",
                       max_protrusion="30%", link_max_protrusion={"link2": 0.06})
    limits = {lf.link: lf.protrusion_limit for lf in pct.links if lf.fitted}
    assert limits["link2"] == 0.06
    assert all(0 < v for v in limits.values()) and len(set(limits.values())) == len(limits)
    assert pct.tolerance_met


def test_fit_robot_link_solid_for():
    # link2's envelope at the size given, the other links' walls.
    urdf = DATA / "robot" / "three_link.urdf"
    counts = {"base_link": 1, "link1": 1, "link2": 2}
    r = ss.fit_robot(urdf, link_spheres=counts, package_paths=[DATA / "robot"], quality="fast",
                     link_solid="walls", fill_openings=0.05, link_solid_for={"link2": "envelope"})
    solids = {lf.link: (lf.solid, lf.fill_openings) for lf in r.links if lf.fitted}
    assert solids == {"base_link": ("walls", 0.0), "link1": ("walls", 0.0),
                      "link2": ("envelope", 0.05)}
    assert r.covered
    with pytest.raises(ss.InvalidArgumentError, match="link_solid_for names 'elbow'"):
        ss.fit_robot(urdf, link_spheres=counts, package_paths=[DATA / "robot"], quality="fast",
                     link_solid_for={"elbow": "walls"})
    with pytest.raises(ss.InvalidArgumentError,
                       match="link_solid_for 'link2=hollow': expected LINK=VALUE"):
        ss.fit_robot(urdf, package_paths=[DATA / "robot"], link_solid_for={"link2": "hollow"})


def test_fit_robot_honours_ctrl_c():
    # A signal while the links are fitted is handled at the next progress report of a fit on
    # the calling thread, inside fit_robot; the module is usable afterwards.
    import signal

    urdf = DATA / "robot" / "three_link.urdf"

    def alarm(*_):
        raise KeyboardInterrupt()

    old = signal.signal(signal.SIGALRM, alarm)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.05)  # the fit takes much longer
        with pytest.raises(KeyboardInterrupt) as info:
            ss.fit_robot(urdf, budget=40, package_paths=[DATA / "robot"], quality="default")
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    assert [e.name for e in info.traceback][-2:] == ["fit_robot", "alarm"]
    r = ss.fit_robot(urdf, link_spheres={"base_link": 1, "link1": 1, "link2": 1},
                     package_paths=[DATA / "robot"], quality="fast")
    assert r.covered


@pytest.mark.skipif(not ss.mujoco_available(), reason="built without MuJoCo")
def test_mjcf_robot_fit_and_written_back(cli, tmp_path):
    """An MJCF robot (read by MuJoCo): load_robot and fit_robot take it as the command does, and
    write_sphere_mjcf writes a model whose sphere geoms load_robot reads back as the spheres."""
    xml = DATA / "robot" / "mjcf" / "arm.xml"
    r = ss.load_robot(xml)
    assert "wrist/wx" in r.links and ("finger_left", "finger_right") in r.excluded_pairs
    j2 = next(j for j in r.joints if j["name"] == "j2")
    assert j2["reference"] == pytest.approx(np.radians(10.0))
    assert [g["kind"] for g in r.link_geometry("wrist")] == ["ellipsoid", "cylinder"]
    out = tmp_path / "arm.json"
    cli("robot", xml, "--quality", "fast", "--default-link-spheres", 3, "--collision-samples",
        100, "-o", out, "-q")
    fit = ss.fit_robot(xml, default_link_spheres=3, quality="fast", link_solid="walls")
    ref = json.loads(out.read_text())
    assert [lf.link for lf in fit.links] == [lf["link"] for lf in ref["links"]]
    assert fit.covered
    model = tmp_path / "arm_spheres.xml"
    ss.write_sphere_mjcf(xml, model, fit.spheres)
    back = ss.load_robot(model)
    for link, spheres in fit.spheres.items():
        kinds = [g["kind"] for g in back.link_geometry(link)]
        assert kinds == ["sphere"] * len(spheres), link
    with pytest.raises(ss.InvalidArgumentError, match="no body named 'elbow'"):
        ss.write_sphere_mjcf(xml, tmp_path / "never.xml", {"elbow": np.zeros((1, 4))})
    assert not (tmp_path / "never.xml").exists()
    with pytest.raises(ss.InvalidDataError, match="composites are not read"):
        ss.load_robot(DATA.parent / "hostile" / "mjcf_composite.xml")

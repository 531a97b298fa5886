"""The posed-robot queries from Python: the same answer as brute force over every pair of a link
sphere and an obstacle, the first colliding waypoint, and the library's messages for bad input."""

import warnings

import numpy as np
import pytest

import sphereset as ss
from conftest import DATA


def robot():
    return ss.load_robot(DATA / "robot" / "three_link.urdf",
                         package_paths=[str(DATA / "robot")], use_ros_package_path=False)


# link2's sphere (0.45, 0, 0) r 0.05 is at (0.45 cos q, 0, 0.5 - 0.45 sin q) at joint2 = q.
SPHERES = {"base_link": np.array([[0.0, 0.0, 0.05, 0.1]]),
           "link2": np.array([[0.45, 0.0, 0.0, 0.05]])}


def brute(r, spheres, obstacles, joints):
    poses = r.link_poses(joints)
    best = np.inf
    for link, s in spheres.items():
        c = s[:, :3] @ poses[link][:3, :3].T + poses[link][:3, 3]
        o = obstacles if obstacles.shape[1] == 4 else np.c_[obstacles, np.zeros(len(obstacles))]
        d = np.linalg.norm(c[:, None, :] - o[None, :, :3], axis=2) - s[:, 3:4] - o[None, :, 3]
        best = min(best, d.min())
    return best


def test_robot_contacts_match_brute_force():
    r = robot()
    rng = np.random.default_rng(3)
    cloud = rng.uniform([-0.8, -0.8, 0.0], [0.8, 0.8, 1.0], size=(5000, 3))
    balls = np.c_[rng.uniform(-0.8, 0.8, size=(200, 3)), rng.uniform(0.0, 0.05, size=200)]
    for obstacles in (cloud, balls):
        for q in (-1.0, 0.0, 0.7):
            got = ss.robot_contacts(r, SPHERES, obstacles, {"joint2": q})
            want = brute(r, SPHERES, obstacles, {"joint2": q})
            assert got["distance"] == pytest.approx(want, abs=1e-12)
            assert got["collides"] == (want < 0)
            assert [c["link"] for c in got["links"]] == list(SPHERES)


def test_trajectory_first_collision():
    r = robot()
    q = 0.4
    obstacles = np.array([[0.45 * np.cos(q), 0.0, 0.5 - 0.45 * np.sin(q), 0.02], [5, 5, 5, 0.1]])
    t = ss.trajectory_contacts(r, SPHERES, obstacles, [{"joint2": 0.2 * i} for i in range(5)])
    assert t["first_collision"] == 2
    assert [w["collides"] for w in t["waypoints"]] == [False, False, True, False, False]
    assert t["waypoints"][2]["link"] == "link2"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ss.trajectory_contacts(r, SPHERES, obstacles, [{"joint1": 100.0}])
    assert any("waypoint 0: joint 'joint1': 100 is beyond" in str(w.message) for w in caught)


def test_bad_inputs_name_them():
    r = robot()
    with pytest.raises(ss.InvalidDataError, match="obstacles: point 1 .* finite"):
        ss.robot_contacts(r, SPHERES, np.array([[0, 0, 0], [np.nan, 0, 0]]))
    with pytest.raises(ss.InvalidDataError, match="link 'elbow' is not a link of robot"):
        ss.robot_contacts(r, {"elbow": np.array([[0, 0, 0, 0.1]])}, np.zeros((1, 3)))
    with pytest.raises(ss.InvalidArgumentError, match="no joint 'joint9'"):
        ss.robot_contacts(r, SPHERES, np.zeros((1, 3)), {"joint9": 1.0})

"""Sphere sets that follow a deforming mesh: mean value coordinates (partition of unity, linear
precision), animate under an affine frame, rebound coverage, bad input, skinned assets, and the
same spheres as ``sphereset animate``."""

import json

import numpy as np
import pytest

import sphereset as ss

from conftest import cube_arrays


def box_mesh(size=(2.0, 1.0, 1.5)):
    """An axis-aligned box [0, size] with a vertex at the centre of each face (so that not every
    vertex is a corner), outward-oriented."""
    v, f = cube_arrays()
    v = v * np.asarray(size)
    verts = list(v)
    faces = []
    # Each quad of the cube (two triangles in cube_arrays) becomes four triangles around its
    # centre.
    for a, b in zip(f[0::2], f[1::2]):
        quad = [a[0], a[1], a[2], b[2]]
        c = len(verts)
        verts.append(v[quad].mean(axis=0))
        for i in range(4):
            faces.append([quad[i], quad[(i + 1) % 4], c])
    return ss.Mesh(np.array(verts), np.array(faces, np.int64), clean=False)


SHEAR = np.array([[1.0, 0.4, 0.0], [0.0, 1.1, 0.2], [0.1, 0.0, 0.9]])
SHIFT = np.array([0.3, -0.2, 0.5])


def sheared(vertices):
    return vertices @ SHEAR.T + SHIFT


def test_box_mesh_is_a_solid():
    m = box_mesh()
    assert len(m.vertices) == 14
    assert m.volume == pytest.approx(3.0)
    assert ss.diagnose(m)["solid"]


@pytest.mark.parametrize("point", [[0.7, 0.3, 0.9], [1.9, 0.95, 0.05], [3.0, -1.0, 2.5],
                                   [-0.5, 0.5, 0.75]])
def test_mean_value_coordinates_partition_of_unity_and_linear_precision(point):
    m = box_mesh()
    w = ss.mean_value_coordinates(m, point)
    assert w.shape == (len(m.vertices),) and w.dtype == np.float64
    assert w.sum() == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(w @ m.vertices, point, atol=1e-10)
    inside = bool(ss.solid(m, repair="off").contains(np.array([point]))[0])
    if inside:
        # The box is convex: inside it every mean value coordinate is positive.
        assert (w > 0).all()
    else:
        assert (w < 0).any()


def test_mean_value_weights_rows_are_the_coordinates():
    m = box_mesh()
    pts = np.array([[0.7, 0.3, 0.9], [3.0, -1.0, 2.5], [1.0, 0.5, 0.75]])
    w = ss.mean_value_weights(m, pts)
    assert w.shape == (3, len(m.vertices)) and w.dtype == np.float64
    np.testing.assert_allclose(w.sum(axis=1), 1.0, atol=1e-12)
    np.testing.assert_allclose(w @ m.vertices, pts, atol=1e-10)
    for i, p in enumerate(pts):
        np.testing.assert_allclose(w[i], ss.mean_value_coordinates(m, p), atol=1e-14)
    # Any affine map of the mesh moves the points by the same map.
    np.testing.assert_allclose(w @ sheared(m.vertices), sheared(pts), atol=1e-10)


SPHERES = np.array([[0.5, 0.5, 0.75, 1.1], [1.5, 0.5, 0.75, 1.1], [1.0, 0.5, 0.75, 0.3]])


def test_animate_moves_centres_by_the_affine_map():
    m = box_mesh()
    frames = [m.vertices, sheared(m.vertices)]
    r = ss.animate(m, SPHERES, frames)
    assert r.weighting == "mvc" and not r.rebound
    assert r.spheres.shape == (2, 3, 4) and r.spheres.dtype == np.float64
    assert len(r) == 2
    np.testing.assert_allclose(r.spheres[0], SPHERES, atol=1e-12)  # the rest pose: unchanged
    np.testing.assert_allclose(r.spheres[1, :, :3], sheared(SPHERES[:, :3]), atol=1e-6)
    np.testing.assert_array_equal(r.spheres[1, :, 3], SPHERES[:, 3])  # radii kept
    for k in ("er", "surface_covered", "interior_covered", "max_gap", "crossings",
              "radius_growth", "update_seconds"):
        assert getattr(r, k).shape == (2,), k
    assert r.surface_covered.dtype == bool
    np.testing.assert_array_equal(r.times, [0.0, 1.0])
    assert r.covered[0] and r.max_gap[0] == 0.0
    assert (r.crossings == 0).all() and r.frames_crossing == 0
    assert r.frames_covered == int(r.covered.sum())
    # E_r of the rest frame: the exact outside volume over the box's volume.
    assert r.er[0] == pytest.approx(
        ss.solid(m, repair="off").outside_volume(SPHERES).sum() / m.volume, rel=1e-9)


def test_rebound_covers_every_frame():
    m = box_mesh()
    v = m.vertices
    # Stretched along x: the fixed radii no longer reach the far corners.
    stretch = v * np.array([1.6, 1.0, 1.0])
    frames = [v, sheared(v), stretch, v + [5.0, 0.0, 0.0]]
    fixed = ss.animate(m, SPHERES, frames)
    assert not fixed.covered.all()
    r = ss.animate(m, SPHERES, frames, rebound=True)
    assert r.rebound and r.covered.all() and r.rebound_covered.all()
    # The moved set with the rest radii is certified as before; only the growth differs.
    np.testing.assert_array_equal(r.surface_covered, fixed.surface_covered)
    assert (r.spheres[:, :, 3] >= SPHERES[:, 3] - 1e-12).all()
    grown = ~fixed.covered
    assert (r.radius_growth[grown] > 0).all() and (r.grown[grown] > 0).all()
    assert r.radius_growth[0] == 0.0 and r.grown[0] == 0
    # An independent check of the grown sets: every deformed vertex inside the union.
    for f, sp in zip(frames, r.spheres):
        assert ss.contains(sp, f).all()


def test_frames_as_meshes_and_one_array():
    m = box_mesh()
    a = ss.animate(m, SPHERES, np.stack([m.vertices, sheared(m.vertices)]))
    f = ss.Mesh(sheared(m.vertices), m.faces, clean=False)
    b = ss.animate(m, SPHERES, [m, f])
    np.testing.assert_array_equal(a.spheres, b.spheres)


def test_progress_and_cancel():
    m = box_mesh()
    seen = []
    ss.animate(m, SPHERES, [m.vertices] * 3, progress=lambda f, n: seen.append((f, n)))
    assert seen == [(0, 3), (1, 3), (2, 3)]

    def stop(f, n):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        ss.animate(m, SPHERES, [m.vertices] * 3, progress=stop)


def test_bad_input_raises():
    m = box_mesh()
    with pytest.raises(ss.InvalidDataError, match="frame 1 has 13 vertices, the rest mesh 14"):
        ss.animate(m, SPHERES, [m.vertices, m.vertices[:-1]])
    # A Mesh frame is checked for the rest mesh's triangles too.
    swapped = ss.Mesh(m.vertices, m.faces[::-1].copy())
    with pytest.raises(ss.InvalidDataError, match="its triangles differ from the rest mesh's"):
        ss.animate(m, SPHERES, [m, swapped])
    with pytest.raises(ss.InvalidArgumentError, match="bones"):
        ss.animate(m, SPHERES, [m.vertices], weighting="bones")
    with pytest.raises(ss.InvalidArgumentError, match="weighting"):
        ss.animate(m, SPHERES, [m.vertices], weighting="nearest")
    with pytest.raises(ss.InvalidDataError):
        ss.animate(m, np.zeros((0, 4)), [m.vertices])
    with pytest.raises(ss.InvalidArgumentError):
        ss.animate(m, SPHERES[:, :3], [m.vertices])
    v, f = cube_arrays()
    open_box = ss.Mesh(v, f[:-2])
    with pytest.raises(ss.NotSolidError):
        ss.animate(open_box, SPHERES, [open_box.vertices])


def write_skinned_box(path):
    """A skinned asset (Valve SMD): a 1 x 1 x 2 box whose bottom follows bone "root" and whose
    top follows bone "tip" (at z = 1), turned about x by 0, 0.3 and 0.6 radians in 3 frames."""
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    out = ["version 1", "nodes", '0 "root" -1', '1 "tip" 0', "end", "skeleton"]
    for t, angle in enumerate([0.0, 0.3, 0.6]):
        out += [f"time {t}", "0 0 0 0 0 0 0", f"1 0 0 1 {angle} 0 0"]
    out += ["end", "triangles"]
    for q in quads:
        for tri in ([q[0], q[1], q[2]], [q[0], q[2], q[3]]):
            out.append("skin")
            for i in tri:
                x, y, z = i & 1, (i >> 1) & 1, (i >> 2) & 1
                out.append(f"{z} {x} {y} {2 * z} 0 0 1 0 0 1 {z} 1")
    out.append("end")
    path.write_text("\n".join(out) + "\n")
    return path


def test_load_animation_and_bone_weighting(tmp_path):
    a = ss.load_animation(write_skinned_box(tmp_path / "box.smd"))
    assert len(a) == 3 and len(a.times) == 3 and a.clips == [a.clip]
    assert len(a.rest.vertices) == 8 and a.rest.volume == pytest.approx(2.0, rel=1e-6)
    assert a.bone_weights.shape == (8, len(a.bone_names))
    np.testing.assert_allclose(a.bone_weights.sum(axis=1), 1.0)
    assert all(t.shape == (len(a.bone_names), 4, 4) for t in a.bone_transforms)
    # Linear blend skinning of the rest vertices with the transforms gives the frames.
    for f, t in zip(a.frames, a.bone_transforms):
        assert f.shape == (8, 3)
        np.testing.assert_allclose(ss.skin_points(a.rest.vertices, a.bone_weights, t), f,
                                   atol=1e-9)
    sp = np.array([[0.5, 0.5, 0.5, 0.9], [0.5, 0.5, 1.5, 0.9]])
    r = ss.animate(None, sp, a)
    assert r.weighting == "bones" and r.spheres.shape == (3, 2, 4)
    np.testing.assert_allclose(r.times, a.times)
    w = ss.point_bone_weights(a.rest, a.bone_weights, sp[:, :3])
    for f in range(3):
        np.testing.assert_allclose(
            r.spheres[f, :, :3], ss.skin_points(sp[:, :3], w, a.bone_transforms[f]), atol=1e-9)
    assert ss.animate(a.rest, sp, a, weighting="mvc").weighting == "mvc"
    # Sampled at a rate instead of the keyframes.
    assert len(ss.load_animation(tmp_path / "box.smd", fps=2.0 / a.duration)) == 3
    with pytest.raises(ss.InvalidArgumentError, match="no clip 'walk'"):
        ss.load_animation(tmp_path / "box.smd", clip="walk")
    with pytest.raises(ss.InvalidArgumentError):
        ss.load_animation(tmp_path / "box.smd", fps=-1.0)
    with pytest.raises(ss.InvalidDataError, match="vertices"):
        ss.animate(box_mesh(), sp, a)
    # The bind pose scaled by 3 and shifted: same vertices and triangles, not the bind pose.
    moved = ss.Mesh(a.rest.vertices * 3.0 + np.array([1.0, 2.0, 0.0]), a.rest.faces)
    for weighting in ("bones", "mvc"):
        with pytest.raises(ss.InvalidDataError, match="not the skin's bind pose"):
            ss.animate(moved, sp, a, weighting=weighting)


def test_asset_without_animation_raises(tmp_path):
    off = tmp_path / "tet.off"
    off.write_text("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
    with pytest.raises(ss.InvalidDataError, match="no animation"):
        ss.load_animation(off)
    with pytest.raises(ss.UnreadableError):
        ss.load_animation(tmp_path / "missing.fbx")


def write_off(path, vertices, faces):
    lines = ["OFF", f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(repr(float(x)) for x in v) for v in vertices]
    lines += ["3 " + " ".join(str(int(i)) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("rebound", [False, True])
def test_same_spheres_as_cli(cli, tmp_path, rebound):
    m = box_mesh()
    rest = write_off(tmp_path / "rest.off", m.vertices, m.faces)
    frames = [m.vertices, sheared(m.vertices), m.vertices * np.array([1.6, 1.0, 1.0])]
    paths = [write_off(tmp_path / f"f{i}.off", v, m.faces) for i, v in enumerate(frames)]
    spheres = tmp_path / "rest.json"
    ss.write_spheres(spheres, SPHERES)
    out = tmp_path / "out"
    cli("animate", rest, spheres, "-o", out, "--frames", *paths, "-q",
        *(["--rebound"] if rebound else []))
    r = ss.animate(ss.load_mesh(rest), ss.read_spheres(spheres), frames, rebound=rebound)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["weighting"] == "mvc" and r.weighting == "mvc"
    assert summary["frames_covered"] == r.frames_covered
    # One field list (animate.hpp) behind both: every frame field, same name and value.
    for row in ss._core._result_schema("animate_frame"):
        name = row["name"]
        if name.endswith("seconds"):
            continue
        assert getattr(r, name).tolist() == [f[name] for f in summary["frames"]], name
    for i, fr in enumerate(summary["frames"]):
        np.testing.assert_array_equal(ss.read_spheres(out / fr["file"]), r.spheres[i])
        assert fr["er"] == pytest.approx(r.er[i], rel=1e-12)
        assert fr["surface_covered"] == r.surface_covered[i]
        assert fr["interior_covered"] == r.interior_covered[i]
        assert fr["max_gap"] == pytest.approx(r.max_gap[i], rel=1e-12, abs=1e-15)
        if rebound:
            assert fr["rebound_covered"] == r.rebound_covered[i]
            assert fr["radius_growth"] == pytest.approx(r.radius_growth[i], rel=1e-12, abs=1e-15)
    assert (out / "frame_0000.json").exists()

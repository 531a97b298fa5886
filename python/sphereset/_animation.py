"""Moving a sphere set with its mesh (paper Sec. 6): mean value coordinates, bone weights,
skinning, animated assets and the certified animation of a set."""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _sphereset as _core
from ._common import PathLike, load_mesh
from ._results import FRAME_COLUMNS, AnimateResult
from ._sphereset import InvalidArgumentError, Mesh


def mean_value_coordinates(mesh: Union[Mesh, PathLike], point: Any) -> np.ndarray:
    """Mean value coordinates of one (3,) ``point`` over the vertices of a closed,
    outward-oriented triangle mesh (Ju, Schaefer and Warren 2005): a (V,) float64 array ``w``
    with ``w.sum() == 1`` and ``w @ mesh.vertices == point``, for points inside and outside the
    solid (outside, some weights are negative). A point on a triangle gets its barycentric
    coordinates."""
    if not isinstance(mesh, Mesh):
        mesh = load_mesh(mesh)
    return _core._mean_value_coordinates(mesh, point)


def mean_value_weights(mesh: Union[Mesh, PathLike], points: Any) -> np.ndarray:
    """Mean value coordinates of each of (N, 3) ``points``: an (N, V) float64 array whose row i
    holds the coordinates of point i, so that ``weights @ deformed_vertices`` moves the points
    with the mesh. Computed in parallel, rows independent (deterministic)."""
    if not isinstance(mesh, Mesh):
        mesh = load_mesh(mesh)
    return _core._mean_value_weights(mesh, points)[0]


def point_bone_weights(mesh: Mesh, bone_weights: Any, points: Any, *,
                       neighbours: int = 8) -> np.ndarray:
    """Bone weights of (N, 3) ``points`` from the (V, B) ``bone_weights`` of the mesh's
    vertices: the inverse-distance average over the ``neighbours`` nearest vertices, (N, B) rows
    summing to 1 (0 where no nearby vertex has a bone)."""
    return _core._point_bone_weights(mesh, bone_weights, points, int(neighbours))


def skin_points(points: Any, weights: Any, bones: Any) -> np.ndarray:
    """Linear blend skinning of (N, 3) ``points`` with (N, B) ``weights`` and (B, 4, 4) bone
    transforms (rest pose to the frame): p' = Σ_b w_b T_b p; points without weight stay put."""
    return _core._skin_points(points, weights, bones)


@dataclass
class Animation:
    """A skinned, animated asset's clip (``load_animation``): the bind pose ``rest`` (welded as
    ``load_mesh`` welds), one (V, 3) float64 vertex array per frame in ``frames`` (the rest's
    vertices, same order) at ``times`` (seconds), the skin (``bone_weights`` (V, B) rows summing
    to 1, or 0 for vertices no bone moves; None without bones) and each frame's (B, 4, 4) bone
    transforms from the rest pose (``bone_transforms``)."""

    path: str
    rest: Mesh
    frames: List[np.ndarray]
    times: np.ndarray
    bone_weights: Optional[np.ndarray]
    bone_transforms: List[np.ndarray]
    bone_names: List[str]
    clip: str
    clips: List[str]
    duration: float

    def __len__(self) -> int:
        return len(self.frames)


def load_animation(path: PathLike, clip: Optional[str] = None,
                   fps: Optional[float] = None) -> Animation:
    """Reads a skinned, animated asset through assimp (FBX, glTF 2.0, COLLADA, DirectX .x,
    SMD, ...) and evaluates a clip (``clip`` None: the first) at its keyframe times, or every
    1/``fps`` seconds. Raises UnreadableError (not readable), InvalidDataError (no triangles,
    no animation) or InvalidArgumentError (no clip of that name: the message lists the clips;
    ``fps`` outside the library's row: a finite number >= 0, 0 or None the keyframe times)."""
    d = _core._load_animation(os.fspath(path), clip or "", dict(fps=fps))
    if d["bone_weights"].shape[1] == 0:
        d["bone_weights"] = None
    return Animation(**d)


def animate(rest_mesh: Union[Mesh, PathLike, None], spheres: Any,
            frames: Union[Animation, Sequence[Any], np.ndarray], *, rebound: bool = False,
            weighting: str = "auto", bone_neighbours: int = 8, fresh_fit: bool = False,
            max_crossings: int = 1000, times: Any = None,
            progress: Optional[Callable[[int, int], None]] = None) -> AnimateResult:
    """Moves (N, 4) ``spheres`` fitted to ``rest_mesh`` through ``frames`` (paper Sec. 6), like
    ``sphereset animate``: centres move, radii stay, and every frame is certified.

    ``frames`` is a list of (V, 3) vertex arrays (or Meshes, or one (F, V, 3) array) with the
    rest mesh's vertices in its order, or an :class:`Animation` (``rest_mesh`` may then be None:
    its bind pose). ``weighting`` "mvc" moves the centres by mean value coordinates of the rest
    mesh, "bones" by the bone weights of the ``bone_neighbours`` nearest rest vertices (needs an
    Animation with a skin), "auto" bones for a skinned Animation, else mvc. ``rebound`` grows
    radii minimally per frame to restore exact coverage; ``fresh_fit`` also fits a fresh set to
    every frame to compare E_r (slow). ``max_crossings`` caps the crossing pairs counted per
    frame (0 skips the check). ``progress(frame, frames)`` is called after each frame; an
    exception it raises, or Ctrl-C, abandons the call. Raises InvalidDataError (a frame whose
    vertex count, or a Mesh frame whose triangles, differ from the rest mesh's; a rest mesh
    that is not the Animation's bind pose; no spheres), InvalidArgumentError (bones without a
    skin, options out of range), NotSolidError (the rest mesh or a frame has no positive
    volume).
    """
    bone_weights = None
    bone_transforms = None
    bind_pose = None
    if isinstance(frames, Animation):
        anim = frames
        if rest_mesh is None:
            rest_mesh = anim.rest
        frames = anim.frames
        if times is None:
            times = anim.times
        bone_weights = anim.bone_weights
        bone_transforms = anim.bone_transforms
        bind_pose = anim.rest
    if rest_mesh is None:
        raise InvalidArgumentError("rest_mesh is needed unless frames is an Animation")
    if not isinstance(rest_mesh, Mesh):
        rest_mesh = load_mesh(rest_mesh)
    # The keywords of the library's animation table (animate.hpp), checked there.
    options = dict(weighting=weighting, bone_neighbours=bone_neighbours,
                   max_crossings=max_crossings)
    d = _core._animate(rest_mesh, spheres, list(frames), times, bone_weights, bone_transforms,
                       bind_pose, options, bool(rebound), bool(fresh_fit), progress)
    fr = d.pop("frames")
    out: Dict[str, Any] = {
        "spheres": (np.stack([f["spheres"] for f in fr]) if fr
                    else np.zeros((0, 0, 4), dtype=np.float64)),
        "times": np.array([f["time"] for f in fr], dtype=np.float64),
    }
    for k, t in FRAME_COLUMNS.items():
        out[k] = np.array([f[k] for f in fr], dtype=t)
    out.update(d)
    return AnimateResult(**out)

"""sphereset: bounding sphere sets for solid triangle meshes, from Python.

Variational sphere-set approximation (Wang et al. 2006) with a guaranteed bound of the surface,
sphere trees, queries, robots and sphere files, on numpy arrays::

    import sphereset as ss
    m = ss.load_mesh("spot.obj")           # ss.Mesh: .vertices (V, 3) float64, .faces (F, 3)
    m = ss.Mesh(vertices, faces)           # from arrays, no file
    r = ss.fit(m, n=32, seed=1)            # r.spheres: (32, 4) float64 rows x, y, z, r
    e = ss.evaluate(m, r.spheres)          # E_r, coverage certificates, proximity, shadows

`fit` takes the options of ``sphereset fit`` with the same defaults and gives the same spheres
for the same seed. Meshes that are not clean solids are repaired as the command line does
(``repair="off"`` refuses them). Errors raise subclasses of :class:`Error` (also ValueError or
OSError) carrying the library's one-line message. Long calls release the GIL; Ctrl-C cancels a
fit (KeyboardInterrupt) at its next progress report.
"""

from __future__ import annotations

import operator
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _sphereset as _core
from ._animation import (Animation, animate, load_animation,  # noqa: F401  (re-exported)
                         mean_value_coordinates, mean_value_weights, point_bone_weights,
                         skin_points)
from ._common import (REPAIR_KEYWORDS, MeshLike, PathLike,  # noqa: F401  (re-exported)
                      ProgressCallback, _repair_args, _repair_keywords, load_mesh)
from ._results import (FRAME_COLUMNS, AnimateResult, EvalResult,  # noqa: F401  (re-exported)
                       FitResult, RobotFitResult, RobotLinkFit)
from ._sphereset import (  # noqa: F401  (re-exported)
    Error,
    InvalidArgumentError,
    InvalidDataError,
    Mesh,
    NotSolidError,
    Robot,
    Solid,
    SphereTree,
    UnreadableError,
    WriteError,
    curve_volume,
    format_sphere_tree,
    format_sphere_urdf,
    format_spheres,
    load_robot,
    mujoco_available,
    read_link_spheres,
    read_sphere_tree,
    read_spheres,
    robot_contacts,
    sphere_format,
    split_budget,
    trajectory_contacts,
    write_link_spheres,
    write_robot_spheres,
    write_sphere_mesh,
    write_sphere_tree,
    write_sphere_mjcf,
    write_sphere_urdf,
    write_spheres,
)

__version__ = "0.1.0"

__all__ = [
    "Error", "InvalidArgumentError", "InvalidDataError", "NotSolidError", "UnreadableError",
    "WriteError", "Mesh", "Solid", "SphereTree", "Robot", "FitResult", "EvalResult",
    "CheckResult", "TreeResult", "PointQueryResult", "PairQueryResult", "load_mesh", "solid",
    "check", "diagnose", "fit", "evaluate", "eval_option_table", "tree", "build_tree", "query_tree", "point_distance",
    "contains", "segment_outside_length", "separation", "overlaps", "read_spheres",
    "write_spheres", "format_spheres", "sphere_format", "read_link_spheres", "write_link_spheres",
    "read_sphere_tree", "write_sphere_tree", "format_sphere_tree", "write_sphere_mesh",
    "load_robot", "write_robot_spheres", "write_sphere_urdf", "format_sphere_urdf",
    "write_sphere_mjcf", "mujoco_available",
    "split_budget", "curve_volume", "Animation", "AnimateResult", "mean_value_coordinates",
    "mean_value_weights", "point_bone_weights", "skin_points", "load_animation", "animate",
    "RobotLinkFit", "RobotFitResult", "fit_robot", "robot_contacts", "trajectory_contacts",
    "sample_self_collisions", "fit_to_tolerance", "fit_curve",
]

@_repair_keywords
def solid(mesh: MeshLike, *, repair_options: Dict[str, Any]) -> Solid:
    """The solid the fit runs on: ``mesh`` repaired as ``sphereset fit`` does and indexed.

    ``mesh`` is a Mesh, a path, or already a Solid (returned as it is). ``repair`` is "auto"
    (weld, re-orient, cap holes, unite crossing shells, wrap) or "off" (a mesh that is not a clean
    closed solid raises NotSolidError). ``weld_tolerance`` None welds automatically (exact, then
    up to 1e-6 of the diagonal if that closes the mesh). ``fill_cavities`` fills inner cavities;
    ``wrap_alpha``/``wrap_offset`` (absolute, 0: from the mesh) tune the wrapping.
    ``fill_openings`` (absolute, "auto": the smallest extent of the bounding box, 0: off) makes
    the solid the walls' envelope: openings narrower than it closed, the hollow behind them
    inside (E_r is then reported against the walls too, ``er_walls``).
    """
    if isinstance(mesh, Solid):
        return mesh
    if not isinstance(mesh, Mesh):
        mesh = load_mesh(mesh)
    return Solid(mesh, **_repair_args(repair_options))


@dataclass
class CheckResult:
    """What ``sphereset check`` reports about a mesh: its diagnosis as loaded (topology,
    volume, bounds), its shells and crossing triangles, and what the fit's repair does with it
    (``repair`` is None and ``error`` says why when the fit refuses it)."""

    name: str
    diagnosis: Dict[str, Any]
    load: Dict[str, Any]
    shells: Dict[str, Any]
    repair: Optional[Dict[str, Any]]
    error: Optional[str]

    @property
    def fit_accepts(self) -> bool:
        """Whether ``fit`` accepts the mesh with these repair options."""
        return self.error is None


def diagnose(mesh: Union[Mesh, PathLike]) -> Dict[str, Any]:
    """Topological and geometric facts of a mesh (vertices, triangles, edges, boundary and
    non-manifold edges, orientation, components, closed/manifold/oriented/solid, volume, area,
    bounding box, edge lengths), as ``sphereset check --json`` reports them."""
    if not isinstance(mesh, Mesh):
        mesh = load_mesh(mesh)
    return _core._diagnose(mesh)


@_repair_keywords
def check(mesh: Union[Mesh, PathLike], *, repair_options: Dict[str, Any]) -> CheckResult:
    """Diagnoses a mesh as a solid and says what the fit does about its problems, like
    ``sphereset check`` (same options as :func:`solid`). Never raises for a mesh the fit
    refuses: ``result.error`` holds the reason; a file that cannot be read and options outside
    the library's repair table raise."""
    args = _repair_args(repair_options)
    _core._check_repair_options(*args.values())
    if not isinstance(mesh, Mesh):
        mesh = load_mesh(mesh, weld_tolerance=max(0.0, args["weld_tolerance"]))
    rep: Optional[Dict[str, Any]] = None
    err: Optional[str] = None
    try:
        rep = solid(mesh, **repair_options).repair
    except Error as e:
        err = str(e)
    return CheckResult(name=mesh.name, diagnosis=_core._diagnose(mesh), load=mesh.load_report,
                       shells=_core._shells(mesh), repair=rep, error=err)


@_repair_keywords
def fit(mesh: MeshLike, n: int = 32, *, seed: int = 1, quality: str = "default",
        padding: float = 0.0, points: int = 0, iterations: Optional[int] = None,
        restarts: Optional[int] = None, decimation: Optional[float] = None,
        optimizer: str = "powell", init: str = "fps", method: str = "variational",
        progress: Optional[ProgressCallback] = None,
        repair_options: Dict[str, Any]) -> FitResult:
    """Fits ``n`` spheres that bound the solid: the options and defaults of ``sphereset fit``.

    ``quality`` "fast", "default" or "best" sets the points, rounds, optimiser effort, restarts
    and decimation; ``points`` (0: max(5000, 100 n) times the preset's factor), ``iterations``,
    ``restarts`` and ``decimation`` override it when given. ``padding`` is added to every radius.
    ``optimizer`` "powell" or "gradient"; ``init`` "fps" or "random"; ``method`` "variational",
    "kmeans" or "octree". The repair keywords are those of :func:`solid`. ``progress`` is called
    with {"phase", "iteration", "energy", "spheres", "seconds"} at each round; an exception it
    raises cancels the fit and propagates, and so does Ctrl-C (KeyboardInterrupt).

    The spheres equal those of ``sphereset fit MESH -n N --seed S`` with the same options.
    """
    # Checked by the library's fit table (the command line's messages) before any repair.
    options = dict(n=n, quality=quality, seed=seed, padding=padding, points=points,
                   iterations=iterations, restarts=restarts, decimation=decimation,
                   optimizer=optimizer, init=init, method=method)
    _core._check_fit_options(options)
    s = solid(mesh, **repair_options)
    d = _core._fit(s, options, progress)
    return FitResult(**d)


@_repair_keywords
def fit_to_tolerance(mesh: MeshLike, *, max_protrusion: Union[float, str, None] = None,
                     max_er: Optional[float] = None, max_spheres: Optional[int] = None,
                     seed: int = 1, quality: str = "default", padding: float = 0.0,
                     points: int = 0, iterations: Optional[int] = None,
                     restarts: Optional[int] = None, decimation: Optional[float] = None,
                     optimizer: str = "powell", init: str = "fps", method: str = "variational",
                     progress: Optional[ProgressCallback] = None,
                     repair_options: Dict[str, Any]) -> Dict[str, Any]:
    """Of the counts tried, the fewest spheres that meet a tolerance, as ``sphereset fit
    --max-protrusion D --max-er X`` finds them (the same library call): ``max_protrusion`` a
    length, or "P%" of the bounding-box diagonal, bounding the certified protrusion; ``max_er``
    bounding E_r; ``max_spheres`` the cap (256). The fit keywords are :func:`fit`'s (without
    ``n``: the tolerance chooses it); the tolerance and the fit options are checked before the
    mesh is read or repaired. ``progress`` is called after each count tried with {"n", "er_sum",
    "protrusion", "covered", "meets", "seconds"}; an exception it raises ends the search and
    propagates, and Ctrl-C raises KeyboardInterrupt at the next progress report of the fit
    running (every round and every 0.25 s), ending the search.

    Returns {"met", "n", "protrusion_limit", "fit" (a FitResult), "eval" (the check's fields,
    ``protrusion`` included), "curve" (every count tried, as ``progress`` gets them),
    "seconds"}; when no count up to the cap meets it, "met" is False and "fit" is the best count
    tried (the command exits 10 instead).
    """
    tolerance = dict(max_protrusion=max_protrusion, max_er=max_er, max_spheres=max_spheres)
    options = dict(quality=quality, seed=seed, padding=padding, points=points,
                   iterations=iterations, restarts=restarts, decimation=decimation,
                   optimizer=optimizer, init=init, method=method)
    _core._check_tolerance(tolerance)  # in fitToTolerance's order: the tolerance, then the fit
    _core._check_fit_options(options)
    s = solid(mesh, **repair_options)
    d = _core._fit_to_tolerance(s, options, tolerance, progress)
    d["fit"] = FitResult(**d["fit"])
    return d


@_repair_keywords
def fit_curve(mesh: MeshLike, *, counts: Optional[Sequence[int]] = None,
              max_spheres: Optional[int] = None,
              seed: int = 1, quality: str = "default", padding: float = 0.0, points: int = 0,
              iterations: Optional[int] = None, restarts: Optional[int] = None,
              decimation: Optional[float] = None, optimizer: str = "powell", init: str = "fps",
              method: str = "variational", progress: Optional[ProgressCallback] = None,
              repair_options: Dict[str, Any]) -> Dict[str, Any]:
    """E_r and the certified protrusion at every count from 1 to ``max_spheres`` (None: the
    library's default, 64) or at ``counts`` (increasing), from one run, as ``sphereset curve``
    gives them (the same library call, fitCurve): the fits of one progressive run for the
    largest count, the counts between powers of two made by local steps (usually looser than
    fits at those counts), the counts 1, 2 and 8 and the last count clustered from seeds (the last
    is the set :func:`fit` gives at that count), or independent fits when the options do not
    allow a run; each checked as ``fit`` checks its result. The fit keywords are :func:`fit`'s
    (without ``n``); the counts and options are checked before the mesh is read. ``progress``
    gets each count's point
    ({"n", "er_sum", "protrusion", "covered", "meets", "seconds"}) when it is done; an exception
    it raises ends the run, and Ctrl-C raises KeyboardInterrupt within a count's fit.

    Returns {"curve": [point per count], "spheres": [(n, 4) array per count], "progressive",
    "seconds"}.
    """
    options = dict(quality=quality, seed=seed, padding=padding, points=points,
                   iterations=iterations, restarts=restarts, decimation=decimation,
                   optimizer=optimizer, init=init, method=method)
    wanted = [operator.index(n) for n in counts] if counts is not None else []
    if counts is not None and not wanted:
        raise InvalidArgumentError("counts []: expected at least one count")
    cap = None if max_spheres is None else operator.index(max_spheres)  # None: the library's 64
    _core._check_curve(options, wanted, cap)
    s = solid(mesh, **repair_options)
    return _core._fit_curve(s, options, wanted, cap, progress)


@_repair_keywords
def evaluate(mesh: MeshLike, spheres: Any, *, seed: Optional[int] = None,
             samples: Optional[int] = None, segments: Optional[int] = None,
             up: Optional[str] = None, shadow_resolution: Optional[int] = None,
             shadow_lights: Optional[int] = None, surface_max_depth: Optional[int] = None,
             interior_max_depth: Optional[int] = None,
             protrusion_tolerance: Optional[float] = None,
             repair_options: Dict[str, Any]) -> EvalResult:
    """Measures (N, 4) ``spheres`` against the solid with the options and defaults of
    ``sphereset eval`` (the library's evaluation table; None keeps a default, see
    :func:`eval_option_table`).

    ``samples`` Monte Carlo samples for the union's E_r, ``segments`` random segments for the
    proximity error, ``shadow_resolution`` (0 skips the shadows) and ``shadow_lights`` for the
    shadow errors on a ground plane under the object along ``up``. The coverage check
    ``sphereset fit`` runs is ``samples=100000, segments=0, shadow_resolution=0``. The result's
    ``protrusion`` (``bound``, ``witness``, ``witness_distance``, ``sphere``, ``per_sphere``) is
    certified to within ``protrusion_tolerance`` times the bounding-box diagonal (0 skips it).
    """
    # Checked by the library's table (the command line's messages) before any repair.
    options = dict(seed=seed, samples=samples, segments=segments, up=up,
                   shadow_resolution=shadow_resolution, shadow_lights=shadow_lights,
                   surface_max_depth=surface_max_depth, interior_max_depth=interior_max_depth,
                   protrusion_tolerance=protrusion_tolerance)
    _core._check_eval_options(options)
    s = solid(mesh, **repair_options)
    return EvalResult(**_core._evaluate(s, spheres, options))


def eval_option_table() -> List[Dict[str, Any]]:
    """The evaluation's options (name, flag, type, min, max, above_min, percent, choices, default,
    help, key, automatic): the keywords of :func:`evaluate` and the flags of ``sphereset eval``."""
    return _core._eval_option_table()


@dataclass
class TreeResult:
    """A sphere tree (``tree``) and its levels' statistics, root first: spheres, Lloyd rounds,
    convergence and outside volume (E_r when built against a solid); ``fit`` is the leaves' fit
    when the tree was fitted to a mesh."""

    tree: SphereTree
    levels: List[Dict[str, Any]]
    seconds: float
    fit: Optional[FitResult] = None
    repair: Optional[Dict[str, Any]] = None


@_repair_keywords
def tree(mesh: MeshLike, *, branching: int = 8, depth: int = 2, parents: str = "minimal",
         n: Optional[int] = None, seed: int = 1, quality: str = "default", padding: float = 0.0,
         points: int = 0, iterations: Optional[int] = None, restarts: Optional[int] = None,
         decimation: Optional[float] = None, optimizer: str = "powell", init: str = "fps",
         method: str = "variational", progress: Optional[ProgressCallback] = None,
         repair_options: Dict[str, Any]) -> TreeResult:
    """Fits leaves and builds a sphere tree over them, like ``sphereset tree``: ``n`` leaves
    (None: branching**depth), levels above by Lloyd clustering of the children, each parent the
    minimal ball enclosing its children (``parents="minimal"``) or the enclosing ball of least
    outside volume ("outside"). Fit options as :func:`fit`."""
    options = dict(n=n, quality=quality, seed=seed, padding=padding, points=points,
                   iterations=iterations, restarts=restarts, decimation=decimation,
                   optimizer=optimizer, init=init, method=method)
    _core._check_fit_options(options)
    s = solid(mesh, **repair_options)
    d = _core._fit_tree(s, int(branching), int(depth), parents, options, progress)
    d["fit"] = FitResult(**d["fit"], options={}, repair=d["repair"])
    return TreeResult(**d)


def build_tree(leaves: Any, *, branching: int = 8, depth: int = 2, parents: str = "minimal",
               iterations: int = 20, seed: int = 1,
               solid: Optional[Solid] = None) -> TreeResult:  # noqa: F811
    """Builds the levels above (N, 4) ``leaves`` (at most branching**depth). ``solid`` is needed
    for ``parents="outside"`` and gives each level's outside volume."""
    d = _core._build_tree(leaves, int(branching), int(depth), parents, int(iterations),
                          int(seed), solid)
    return TreeResult(**d)


def query_tree(spheres: Any, branching: int = 8) -> SphereTree:
    """A query tree over a plain (N, 4) set (minimal enclosing parents), to reuse across
    queries; sphere ids it reports are slots of the tree."""
    return _core._query_tree(spheres, int(branching))


@dataclass
class PointQueryResult:
    """Per point: the signed distance to the sphere set (min |p - c| - r: exact distance to the
    union when positive, the deepest penetration when <= 0), the sphere attaining it (its row in
    an (N, 4) set, its slot in a SphereTree), and whether the point is inside the union."""

    distance: np.ndarray
    sphere: np.ndarray
    inside: np.ndarray


def point_distance(spheres: Union[SphereTree, Any], points: Any) -> PointQueryResult:
    """Signed distance from each of (P, 3) ``points`` to a sphere set or tree."""
    d, i, c = _core._point_distance(spheres, points)
    return PointQueryResult(distance=d, sphere=i, inside=c)


def contains(spheres: Union[SphereTree, Any], points: Any) -> np.ndarray:
    """Whether each of (P, 3) ``points`` is inside the union of the spheres (bool array)."""
    return _core._point_distance(spheres, points)[2]


def segment_outside_length(spheres: Union[SphereTree, Any], a: Any, b: Any) -> np.ndarray:
    """Length of each segment a[i] -> b[i] ((P, 3) each) outside the union of the spheres."""
    return _core._segment_outside_length(spheres, a, b)


@dataclass
class PairQueryResult:
    """The closest pair of spheres of two sets under their poses: signed distance
    |c_a - c_b| - r_a - r_b (negative: overlap depth), the pair (rows of (N, 4) sets or slots of
    trees), pairs examined; ``overlap`` for :func:`overlaps`."""

    distance: float
    sphere_a: int
    sphere_b: int
    visited: int
    overlap: Optional[bool] = None


def separation(a: Union[SphereTree, Any], b: Union[SphereTree, Any], *,
               pose_a: Any = None, pose_b: Any = None) -> PairQueryResult:
    """Signed distance between two sphere sets (or trees), each placed by a 4x4 rigid pose
    (None: identity)."""
    return PairQueryResult(**_core._separation(a, b, pose_a, pose_b, False))


def overlaps(a: Union[SphereTree, Any], b: Union[SphereTree, Any], *, pose_a: Any = None,
             pose_b: Any = None) -> PairQueryResult:
    """Whether two sphere sets under their poses overlap; stops at the first overlapping pair
    (returned). ``result.overlap`` is the answer."""
    return PairQueryResult(**_core._separation(a, b, pose_a, pose_b, True))


@_repair_keywords
def fit_robot(urdf: PathLike, *, budget: int = 0, default_link_spheres: int = 8,
              link_spheres: Optional[Dict[str, int]] = None,
              padding: float = 0.0, link_padding: Optional[Dict[str, float]] = None,
              package_paths: Sequence[PathLike] = (), use_ros_package_path: bool = True,
              collision_group: int = -1,
              seed: int = 1, quality: str = "default", link_solid: str = "envelope",
              link_solid_for: Optional[Dict[str, str]] = None,
              max_protrusion: Union[float, str, None] = None,
              link_max_protrusion: Optional[Dict[str, Union[float, str]]] = None,
              repair_options: Dict[str, Any]) -> RobotFitResult:
    """Fits collision spheres to every link of a URDF or MJCF (.xml, read by MuJoCo) robot, like
    ``sphereset robot`` (the same library call, options and defaults, so the same spheres for
    the same seed). An MJCF's collision geoms are those MuJoCo collides, or those of
    ``collision_group`` (0-5).

    ``budget`` spheres over the whole robot, sphere primitives included (0:
    ``default_link_spheres`` per link not fixed by ``link_spheres``), split over the links by what lowers the total outside volume
    most; ``link_spheres`` {link: count} fixes a link's count (0 skips it); ``padding`` is added
    to every radius, ``link_padding`` {link: padding} instead for those links; mesh paths
    resolve through ``package_paths`` (package://), then ROS_PACKAGE_PATH. ``quality`` is the
    fit preset ("fast", "default", "best"); the repair keywords are those of :func:`solid`.
    ``link_solid`` "envelope" (the default) fits each link's envelope, its walls with the hollow
    behind openings up to ``fill_openings`` (0 or "auto": the link's smallest extent) inside;
    "walls" fits the walls alone; ``link_solid_for`` {link: "envelope" or "walls"} instead for
    those links (an envelope chosen so is kept even where it encloses no hollow).
    ``max_protrusion`` (a length above 0, or "P%" of each link's bounding-box diagonal; None:
    none) holds every fitted link's padded spheres within that certified protrusion,
    ``link_max_protrusion`` {link: length or "P%"} instead for those links: alone,
    each such link gets its fewest spheres that meet it; with ``budget``, every free link needs
    a limit and the budget goes where the worst link is furthest over its limit. A limit not
    met is not an error: see each link's ``limit_met`` and the result's ``tolerance_met``.
    Raises InvalidArgumentError (a link name the robot lacks, a budget too small), UnreadableError
    (the URDF or a mesh), NotSolidError (a link's geometry cannot be made a solid). The call
    releases the GIL; Ctrl-C raises KeyboardInterrupt at the next progress report of a link fit
    on the calling thread and cancels the whole call.
    """
    # The keywords of the library's robot table (robot_fit.hpp), checked there.
    options = dict(budget=budget, default_link_spheres=default_link_spheres,
                   link_spheres=dict(link_spheres or {}), padding=padding,
                   link_padding=dict(link_padding or {}), link_solid=link_solid,
                   link_solid_for=dict(link_solid_for or {}), max_protrusion=max_protrusion,
                   link_max_protrusion=dict(link_max_protrusion or {}))
    d = _core._fit_robot(os.fspath(urdf), options, dict(quality=quality, seed=seed),
                         [os.fspath(p) for p in package_paths], bool(use_ros_package_path),
                         int(collision_group), *_repair_args(repair_options).values())
    d["links"] = [RobotLinkFit(**lf) for lf in d["links"]]
    return RobotFitResult(**d)


def sample_self_collisions(robot: Robot, spheres: Any, *, collision_samples: int = 0,
                           collision_seed: int = 1, always_fraction: float = 0.95,
                           default_pose: Optional[Dict[str, float]] = None,
                           collision_check: str = "spheres") -> Dict[str, Any]:
    """The link pairs a planner may skip, found as MoveIt's setup assistant finds them and as
    ``sphereset robot`` does (the same library call, options and defaults): ``collision_samples``
    random configurations within the joint limits (0: 2000 per movable joint that is not a
    mimic, from 1000 to 100000) seeded by ``collision_seed``; a pair gets the first reason that
    applies: "Adjacent" (joined by a joint, or through links without spheres), "Default" (in
    collision at ``default_pose`` {joint: value}, joints not given at 0), "Always" (in collision
    in at least ``always_fraction`` of the samples), "Never" (in none). ``spheres`` is
    {link: (N, 4)} in the link frames; ``collision_check`` "meshes" measures on the link
    solids (each link's geometry made a solid as the robot command makes it) instead of the
    spheres. Returns {"disabled": [(link1, link2, reason, collisions), ...], "samples",
    "check", "pairs", "enabled", "adjacent", "default", "always", "never", "seconds"}.
    Raises InvalidArgumentError for an option outside its row or an unknown joint.
    """
    # The keywords of the library's sampling table (robot_collision.hpp), checked there.
    options = dict(collision_samples=collision_samples, collision_seed=collision_seed,
                   always_fraction=always_fraction, default_pose=dict(default_pose or {}),
                   collision_check=collision_check)
    return _core._sample_self_collisions(robot, spheres, options)


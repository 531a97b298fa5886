"""Type stubs of the sphereset package (see __init__.py for the documentation)."""

from __future__ import annotations
import dataclasses
import os
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union
import numpy as np
from . import _sphereset as _core
from ._sphereset import Error, InvalidArgumentError, InvalidDataError, Mesh, NotSolidError, Robot, Solid, SphereTree, UnreadableError, WriteError, curve_volume, format_sphere_tree, format_sphere_urdf, format_spheres, load_robot, read_link_spheres, read_sphere_tree, read_spheres, sphere_format, split_budget, write_link_spheres, write_robot_spheres, write_sphere_mesh, write_sphere_tree, write_sphere_urdf, write_spheres
__version__ = '0.1.0'
__all__ = ['Error', 'InvalidArgumentError', 'InvalidDataError', 'NotSolidError', 'UnreadableError', 'WriteError', 'Mesh', 'Solid', 'SphereTree', 'Robot', 'FitResult', 'EvalResult', 'CheckResult', 'TreeResult', 'PointQueryResult', 'PairQueryResult', 'load_mesh', 'solid', 'check', 'diagnose', 'fit', 'evaluate', 'eval_option_table', 'tree', 'build_tree', 'query_tree', 'point_distance', 'contains', 'segment_outside_length', 'separation', 'overlaps', 'read_spheres', 'write_spheres', 'format_spheres', 'sphere_format', 'read_link_spheres', 'write_link_spheres', 'read_sphere_tree', 'write_sphere_tree', 'format_sphere_tree', 'write_sphere_mesh', 'load_robot', 'write_robot_spheres', 'write_sphere_urdf', 'format_sphere_urdf', 'split_budget', 'curve_volume', 'Animation', 'AnimateResult', 'mean_value_coordinates', 'mean_value_weights', 'point_bone_weights', 'skin_points', 'load_animation', 'animate', 'RobotLinkFit', 'RobotFitResult', 'fit_robot']
PathLike = Union[str, 'os.PathLike[str]']
MeshLike = Union[Mesh, Solid, PathLike]
ProgressCallback = Callable[[Dict[str, Any]], None]
def load_mesh(path: PathLike, *, weld_tolerance: float=0.0) -> Mesh:
    ...
def solid(mesh: MeshLike, *, repair: Union[str, bool]='auto', weld_tolerance: Optional[float]=None, fill_cavities: bool=True, wrap_alpha: float=0.0, wrap_offset: float=0.0) -> Solid:
    ...
@dataclass
class CheckResult:
    name: str
    diagnosis: Dict[str, Any]
    load: Dict[str, Any]
    shells: Dict[str, Any]
    repair: Optional[Dict[str, Any]]
    error: Optional[str]

    @property
    def fit_accepts(self) -> bool:
        ...
def diagnose(mesh: Union[Mesh, PathLike]) -> Dict[str, Any]:
    ...
def check(mesh: Union[Mesh, PathLike], *, repair: Union[str, bool]='auto', weld_tolerance: Optional[float]=None, fill_cavities: bool=True, wrap_alpha: float=0.0, wrap_offset: float=0.0) -> CheckResult:
    ...
@dataclass
class FitResult:
    spheres: np.ndarray
    outside_volume: np.ndarray
    energy_history: np.ndarray
    energy: float
    energy_before_bounding: float
    mesh_volume: float
    er_sum: float
    er_sum_before_bounding: float
    rounds: int
    converged: bool
    teleports: int
    teleports_kept: int
    points: int
    interior_points: int
    sov_queries: int
    sov_queries_culled: int
    optimizer_queries: int
    bounding_enlarged: int
    bounding_pieces: int
    bounding_queries: int
    bounding_interior_cells: int
    shrink_passes: int
    decimated: int
    idle_teleports: int
    restart: int
    seconds: Dict[str, float]
    options: Dict[str, Any]
    repair: Dict[str, Any]

    def to_dict(self) -> Dict[str, Any]:
        ...
def fit(mesh: MeshLike, n: int=32, *, seed: int=1, quality: str='default', padding: float=0.0, points: int=0, iterations: Optional[int]=None, restarts: Optional[int]=None, decimation: Optional[float]=None, optimizer: str='powell', init: str='fps', method: str='variational', repair: Union[str, bool]='auto', weld_tolerance: Optional[float]=None, fill_cavities: bool=True, wrap_alpha: float=0.0, wrap_offset: float=0.0, progress: Optional[ProgressCallback]=None) -> FitResult:
    ...
@dataclass
class EvalResult:
    spheres: int
    mesh_volume: float
    bbox_diagonal: float
    er_sum: float
    er_union: float
    er_union_stderr: float
    outside_volume: np.ndarray
    surface_covered: bool
    max_surface_gap: float
    surface_uncertified_area: float
    uncovered_triangles: int
    original_covered: bool
    max_original_gap: float
    original_uncovered_triangles: int
    interior_covered: bool
    max_interior_gap: float
    interior_uncertified_cells: int
    proximity_error: float
    shadow_error_sky: float
    shadow_error_lights: float
    seconds: float
    repair: Dict[str, Any]

    @property
    def covered(self) -> bool:
        ...

    def to_dict(self) -> Dict[str, Any]:
        ...
def evaluate(mesh: MeshLike, spheres: Any, *, seed: Optional[int]=None, samples: Optional[int]=None, segments: Optional[int]=None, up: Optional[str]=None, shadow_resolution: Optional[int]=None, shadow_lights: Optional[int]=None, surface_max_depth: Optional[int]=None, interior_max_depth: Optional[int]=None, repair: Union[str, bool]='auto', weld_tolerance: Optional[float]=None, fill_cavities: bool=True, wrap_alpha: float=0.0, wrap_offset: float=0.0) -> EvalResult:
    ...
def eval_option_table() -> List[Dict[str, Any]]:
    ...
@dataclass
class TreeResult:
    tree: SphereTree
    levels: List[Dict[str, Any]]
    seconds: float
    fit: Optional[FitResult] = None
    repair: Optional[Dict[str, Any]] = None
def tree(mesh: MeshLike, *, branching: int=8, depth: int=2, parents: str='minimal', n: Optional[int]=None, seed: int=1, quality: str='default', padding: float=0.0, points: int=0, iterations: Optional[int]=None, restarts: Optional[int]=None, decimation: Optional[float]=None, optimizer: str='powell', init: str='fps', method: str='variational', repair: Union[str, bool]='auto', weld_tolerance: Optional[float]=None, fill_cavities: bool=True, wrap_alpha: float=0.0, wrap_offset: float=0.0, progress: Optional[ProgressCallback]=None) -> TreeResult:
    ...
def build_tree(leaves: Any, *, branching: int=8, depth: int=2, parents: str='minimal', iterations: int=20, seed: int=1, solid: Optional[Solid]=None) -> TreeResult:
    ...
def query_tree(spheres: Any, branching: int=8) -> SphereTree:
    ...
@dataclass
class PointQueryResult:
    distance: np.ndarray
    sphere: np.ndarray
    inside: np.ndarray
def point_distance(spheres: Union[SphereTree, Any], points: Any) -> PointQueryResult:
    ...
def contains(spheres: Union[SphereTree, Any], points: Any) -> np.ndarray:
    ...
def segment_outside_length(spheres: Union[SphereTree, Any], a: Any, b: Any) -> np.ndarray:
    ...
@dataclass
class PairQueryResult:
    distance: float
    sphere_a: int
    sphere_b: int
    visited: int
    overlap: Optional[bool] = None
def separation(a: Union[SphereTree, Any], b: Union[SphereTree, Any], *, pose_a: Any=None, pose_b: Any=None) -> PairQueryResult:
    ...
def overlaps(a: Union[SphereTree, Any], b: Union[SphereTree, Any], *, pose_a: Any=None, pose_b: Any=None) -> PairQueryResult:
    ...
def mean_value_coordinates(mesh: Union[Mesh, PathLike], point: Any) -> np.ndarray:
    ...
def mean_value_weights(mesh: Union[Mesh, PathLike], points: Any) -> np.ndarray:
    ...
def point_bone_weights(mesh: Mesh, bone_weights: Any, points: Any, *, neighbours: int=8) -> np.ndarray:
    ...
def skin_points(points: Any, weights: Any, bones: Any) -> np.ndarray:
    ...
@dataclass
class Animation:
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
        ...
def load_animation(path: PathLike, clip: Optional[str]=None, fps: Optional[float]=None) -> Animation:
    ...
@dataclass
class AnimateResult:
    spheres: np.ndarray
    times: np.ndarray
    er: np.ndarray
    surface_covered: np.ndarray
    interior_covered: np.ndarray
    max_gap: np.ndarray
    crossings: np.ndarray
    er_rebound: np.ndarray
    rebound_covered: np.ndarray
    radius_growth: np.ndarray
    max_radius_growth: np.ndarray
    grown: np.ndarray
    er_fresh: np.ndarray
    update_seconds: np.ndarray
    eval_seconds: np.ndarray
    rebound_seconds: np.ndarray
    fresh_seconds: np.ndarray
    weighting: str
    rebound: bool
    weights_seconds: float
    frames_covered: int
    frames_crossing: int
    seconds: float

    @property
    def covered(self) -> np.ndarray:
        ...

    def __len__(self) -> int:
        ...

    def to_dict(self) -> Dict[str, Any]:
        ...
def animate(rest_mesh: Union[Mesh, PathLike, None], spheres: Any, frames: Union[Animation, Sequence[Any], np.ndarray], *, rebound: bool=False, weighting: str='auto', bone_neighbours: int=8, fresh_fit: bool=False, max_crossings: int=1000, times: Any=None, progress: Optional[Callable[[int, int], None]]=None) -> AnimateResult:
    ...
@dataclass
class RobotLinkFit:
    link: str
    spheres: np.ndarray
    primitives: int
    skipped: bool
    from_visual: bool
    fitted: bool
    covered: bool
    files: List[str]
    repair: Optional[Dict[str, Any]]
    eval: Optional[Dict[str, Any]]
    er_sum: float
    outside_volume: float
    padding: float
    budget_curve: Optional[Dict[str, List[float]]]
    split_count: int
    even_count: int
    split_volume: float
    even_volume: float
    seconds: float
@dataclass
class RobotFitResult:
    robot: str
    urdf: str
    links: List[RobotLinkFit]
    budget_split: bool
    outside_volume: float
    split_outside_volume: float
    even_outside_volume: float
    seconds: float

    @property
    def spheres(self) -> Dict[str, np.ndarray]:
        ...

    @property
    def covered(self) -> bool:
        ...

    def to_dict(self) -> Dict[str, Any]:
        ...
def fit_robot(urdf: PathLike, *, budget: int=0, link_spheres: Optional[Dict[str, int]]=None, padding: float=0.0, link_padding: Optional[Dict[str, float]]=None, package_paths: Sequence[PathLike]=(), use_ros_package_path: bool=True, seed: int=1, quality: str='default', repair: Union[str, bool]='auto', weld_tolerance: Optional[float]=None, fill_cavities: bool=True, wrap_alpha: float=0.0, wrap_offset: float=0.0) -> RobotFitResult:
    ...

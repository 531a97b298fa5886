"""The result classes of the fit and the evaluation, written by scripts/gen_results.py from the
library's field lists (result_fields.hpp): do not edit; the tests check this file against the
script's output."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Dict, List, Optional

import numpy as np


def _plain(value: Any) -> Any:
    """Arrays as lists, through dicts and lists: what JSON takes."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value


@dataclass
class FitResult:
    """A fitted sphere set and the fit's diagnostics (fit.hpp's FitResult).

    ``spheres`` is (n, 4) float64 rows x, y, z, r; ``er_sum`` the paper's E_r (Σ outside volume
    / mesh volume, of the repaired solid's volume when the mesh was repaired); ``seconds`` the
    timings by phase; ``options`` the options the fit ran with (after the quality preset);
    ``repair`` what the repair did. The other fields are the library's (result_fields.hpp)."""

    spheres: np.ndarray
    """(n, 4) rows x, y, z, r"""
    outside_volume: np.ndarray
    """exact outside volume of each sphere"""
    energy_history: np.ndarray
    """Σ outside volume after each clustering round"""
    energy: float
    """Σ outside volume of the set (absolute units)"""
    energy_before_bounding: float
    """the same before the bound"""
    mesh_volume: float
    """volume of the solid fitted (the repaired one when repaired)"""
    er_sum: float
    """E_r: Σ outside volume / mesh volume"""
    er_sum_before_bounding: float
    """E_r before the bound"""
    rounds: int
    """assignment/update rounds run"""
    converged: bool
    """stopped because neither rounds nor teleports improved"""
    teleports: int
    """teleports tried"""
    teleports_kept: int
    """teleports that lowered the energy"""
    points: int
    """points clustered"""
    interior_points: int
    """of which inside the solid"""
    sov_queries: int
    """outside-volume evaluations in point assignment"""
    sov_queries_culled: int
    """assignment candidates settled by a lower bound instead"""
    optimizer_queries: int
    """outside-volume evaluations in sphere updates"""
    bounding_enlarged: int
    """spheres enlarged by the last bounding pass"""
    bounding_pieces: int
    """triangle pieces that made a sphere grow"""
    bounding_queries: int
    """outside-volume evaluations of the bound"""
    bounding_interior_cells: int
    """interior cubes that made a sphere grow"""
    shrink_passes: int
    """shrinking passes kept"""
    refine_points: int
    """points kept covered by the refinement (0: not run or not kept)"""
    radii: Dict[str, Any]
    """objective: Σ outside volume of the optimal-radii program's solution (its units, before the bound); lower_bound: the program's proven lower bound; gap: (objective - lower bound) / objective; 0: proven optimal, -1: not run; start: Σ outside volume of the set the program started from; units: surface pieces and interior points of the program; rows: its coverage rows after reduction; kept: its bounded solution replaced the set"""
    decimated: int
    """spheres removed by the decimation"""
    idle_teleports: int
    """spheres that covered nothing alone, moved to split another"""
    restart: int
    """which restart won (0: the one with the seed given)"""
    seconds: Dict[str, float]
    """total: seconds in all; sampling: seconds sampling points; assignment: seconds assigning points to spheres; update: seconds refitting spheres; teleport: seconds teleporting; bounding: seconds after the clustering: bound, shrink, refine and radii; bound: seconds in the exact bound's passes (surface with refits, interior, original); shrink: seconds in the shrinking passes; refine: seconds in the coverage-aware refinement; radii: seconds choosing optimal radii"""
    options: Dict[str, Any]
    """the options the fit ran with"""
    repair: Dict[str, Any]
    """what the repair did"""


    def to_dict(self) -> Dict[str, Any]:
        """The fields as a dict (arrays as lists), e.g. for JSON."""
        return {k: _plain(v) for k, v in dataclasses.asdict(self).items()}

@dataclass
class EvalResult:
    """How tightly a sphere set bounds a solid (evaluate.hpp's EvalResult, as
    ``sphereset eval --json`` reports it): E_r summed (exact) and of the union (Monte Carlo,
    with its standard error), certified surface/interior/original coverage with the largest gaps
    (fractions of the bounding-box diagonal), proximity and shadow errors."""

    spheres: int
    """spheres measured"""
    mesh_volume: float
    """volume of the solid"""
    bbox_diagonal: float
    """its bounding box's diagonal (the unit of the gaps)"""
    er_sum: float
    """E_r: Σ outside volume / mesh volume (exact)"""
    walls_volume: float
    """the walls' volume when the solid is their envelope (else the solid's)"""
    er_walls: float
    """E_r against the walls: Σ outside volume of them / their volume"""
    er_union: float
    """outside volume of the union / mesh volume (Monte Carlo)"""
    er_union_stderr: float
    """its standard error"""
    outside_volume: np.ndarray
    """exact outside volume of each sphere"""
    surface_covered: bool
    """the surface is certified covered"""
    max_surface_gap: float
    """largest surface gap found / diagonal"""
    surface_uncertified_area: float
    """area neither certified nor refuted"""
    uncovered_triangles: int
    """triangles not covered"""
    original_covered: bool
    """the original triangles are certified covered (true when the mesh was not repaired)"""
    max_original_gap: float
    """largest gap of the original triangles / diagonal"""
    original_uncovered_triangles: int
    """original triangles not covered"""
    interior_covered: bool
    """the interior is certified covered"""
    max_interior_gap: float
    """largest interior gap found / diagonal"""
    protrusion: Dict[str, Any]
    """bound: certified: no point of the union is farther than this from the solid (length); witness_distance: a point of the union this far from the solid was found; witness: that point; sphere: the ball it is in (-1: not run); per_sphere: each ball's certified bound; converged: bound within the tolerance of the witness (else a looser bound, still valid)"""
    interior_uncertified_cells: int
    """finest cells at the surface left undecided"""
    proximity_error: float
    """mean outside-length difference over random segments / diagonal"""
    shadow_error_sky: float
    """shadow RMS error under sky light"""
    shadow_error_lights: float
    """shadow RMS error under directional lights"""
    seconds: float
    """seconds of the evaluation"""
    repair: Dict[str, Any]
    """what the repair did"""

    @property
    def covered(self) -> bool:
        """Surface, interior and original triangles all certified covered."""
        return self.surface_covered and self.interior_covered and self.original_covered

    def to_dict(self) -> Dict[str, Any]:
        """The fields as a dict (arrays as lists), e.g. for JSON."""
        return {k: _plain(v) for k, v in dataclasses.asdict(self).items()}

@dataclass
class AnimateResult:
    """A sphere set moved through the frames of a deforming mesh (animate.hpp's AnimateResult,
    with the per-frame fields of AnimateFrameResult as arrays over the F frames).

    ``spheres`` (F, N, 4): the moved sets (grown, with ``rebound``); ``times`` the frames'
    times. ``er``, ``surface_covered``, ``interior_covered``, ``max_gap`` certify the moved set
    with the rest radii; ``crossings`` counts crossing triangle pairs of the deformed mesh (a
    frame that passes through itself is no solid: its figures are not meaningful). The rebound
    and fresh-fit fields are 0 unless asked for."""

    spheres: np.ndarray
    """(F, N, 4) the set in each frame"""
    times: np.ndarray
    """(F,) the frames' times"""
    er: np.ndarray
    """per frame: E_r of the moved set with the rest radii"""
    surface_covered: np.ndarray
    """per frame: its surface certificate"""
    interior_covered: np.ndarray
    """per frame: its interior certificate"""
    max_gap: np.ndarray
    """per frame: largest surface or interior gap / diagonal of the deformed mesh"""
    crossings: np.ndarray
    """per frame: crossing triangle pairs of the deformed mesh (capped)"""
    er_rebound: np.ndarray
    """per frame: rebound: E_r of the grown set"""
    rebound_covered: np.ndarray
    """per frame: rebound: the grown set certified"""
    radius_growth: np.ndarray
    """per frame: rebound: Σ (r' - r) / Σ r"""
    max_radius_growth: np.ndarray
    """per frame: rebound: max (r' - r) / r"""
    grown: np.ndarray
    """per frame: rebound: spheres whose radius grew"""
    er_fresh: np.ndarray
    """per frame: fresh fit: E_r of a fresh fit of the frame"""
    update_seconds: np.ndarray
    """per frame: seconds moving the centres"""
    eval_seconds: np.ndarray
    """per frame: seconds certifying"""
    rebound_seconds: np.ndarray
    """per frame: seconds in the rebound"""
    fresh_seconds: np.ndarray
    """per frame: seconds in the fresh fit"""
    weighting: str
    """the centres' weighting used"""
    weights_seconds: float
    """seconds precomputing the centre weights"""
    frames_covered: int
    """frames whose moved set covers surface and interior"""
    frames_crossing: int
    """frames whose deformed mesh passes through itself"""
    seconds: float
    """seconds in all"""
    rebound: bool
    """whether radii were grown per frame"""

    @property
    def covered(self) -> np.ndarray:
        """Per frame, whether the set in ``spheres`` is certified to cover the deformed surface
        and interior: ``rebound_covered`` with rebound, else surface and interior covered."""
        if self.rebound:
            return self.rebound_covered.copy()
        return self.surface_covered & self.interior_covered

    def __len__(self) -> int:
        return int(self.spheres.shape[0])

    def to_dict(self) -> Dict[str, Any]:
        """The fields as a dict (arrays as lists), e.g. for JSON."""
        return {k: _plain(v) for k, v in dataclasses.asdict(self).items()}

@dataclass
class RobotLinkFit:
    """One link of a robot fit (robot_fit.hpp's RobotLinkFit): ``spheres`` (N, 4), its sphere
    primitives first then the fitted spheres, padded; when fitted, ``repair`` and ``eval`` (the
    fitted spheres' evaluation before padding, as :class:`EvalResult`'s fields)."""

    spheres: np.ndarray
    """(N, 4) rows x, y, z, r"""
    link: str
    """the link's name"""
    count: int
    """spheres, primitives included"""
    primitives: int
    """sphere primitives of its geometry, kept exact"""
    files: List[str]
    """the mesh files of its geometry"""
    from_visual: bool
    """fitted to its <visual> geometry (it has no <collision>)"""
    skipped: bool
    """link_spheres set it to 0: no spheres"""
    fitted: bool
    """some spheres were fitted"""
    covered: bool
    """the coverage certificates of the fitted spheres"""
    solid: str
    """what was fitted: the link's walls or their envelope (openings closed)"""
    fill_openings: float
    """the envelope's opening size (0: walls)"""
    volume: float
    """the fitted solid's volume"""
    walls_volume: float
    """the walls' volume"""
    er_sum: float
    """E_r of the fitted spheres against the fitted solid, before padding"""
    er_walls: float
    """E_r of the same against the walls"""
    outside_volume: float
    """Σ outside volume of the fitted spheres"""
    protrusion: float
    """certified: no point of the link's spheres (padded) is farther than this from the fitted solid (length)"""
    sphere_protrusion: np.ndarray
    """each fitted sphere's certified bound (padded), in the order the fitted spheres follow the primitives in `spheres`"""
    padding: float
    """added to every radius"""
    budget_curve: Dict[str, np.ndarray]
    """counts: under a budget: the quick fits' sphere counts; outside_volume: and their outside volumes"""
    split_count: int
    """the curve split's count (-1: no budget)"""
    split_volume: float
    """its fit's outside volume"""
    seconds: float
    """seconds fitting the link (all its fits), without repair"""
    protrusion_limit: float
    """its protrusion limit (max_protrusion or link_max_protrusion; 0: none)"""
    limit_met: bool
    """covered and within its protrusion limit (true without one)"""
    repair: Optional[Dict[str, Any]]
    """when fitted: what the repair did"""
    eval: Optional[Dict[str, Any]]
    """when fitted: the fitted spheres' evaluation"""


    def to_dict(self) -> Dict[str, Any]:
        """The fields as a dict (arrays as lists), e.g. for JSON."""
        return {k: _plain(v) for k, v in dataclasses.asdict(self).items()}

@dataclass
class RobotFitResult:
    """A whole robot fitted (robot_fit.hpp's RobotFitResult): ``links`` in the robot's order
    (the links with geometry); with a budget, the total outside volume as chosen and for the
    curve split alone."""

    robot: str
    """the robot's name"""
    urdf: str
    """the URDF read"""
    links: List[RobotLinkFit]
    """the links with geometry, in order"""
    budget_split: bool
    """some link's count came from the budget"""
    outside_volume: float
    """Σ outside volume of the links the budget split"""
    split_outside_volume: float
    """the same for the curve split alone"""
    tolerance: bool
    """some link had a protrusion limit"""
    tolerance_met: bool
    """every link with a protrusion limit met it"""
    seconds: float
    """seconds in all"""

    @property
    def spheres(self) -> Dict[str, np.ndarray]:
        """{link: (N, 4) spheres} of the links not skipped, in order: what
        :func:`write_robot_spheres` and :func:`write_sphere_urdf` take."""
        return {lf.link: lf.spheres for lf in self.links if not lf.skipped}

    @property
    def covered(self) -> bool:
        """Every link's spheres certified to cover it."""
        return all(lf.covered for lf in self.links)

    def to_dict(self) -> Dict[str, Any]:
        """The fields as a dict (arrays as lists), e.g. for JSON."""
        return {k: _plain(v) for k, v in dataclasses.asdict(self).items()}


# AnimateResult's per-frame columns and their types.
FRAME_COLUMNS: Dict[str, Any] = {
    "er": np.float64,
    "surface_covered": bool,
    "interior_covered": bool,
    "max_gap": np.float64,
    "crossings": np.int64,
    "er_rebound": np.float64,
    "rebound_covered": bool,
    "radius_growth": np.float64,
    "max_radius_growth": np.float64,
    "grown": np.int64,
    "er_fresh": np.float64,
    "update_seconds": np.float64,
    "eval_seconds": np.float64,
    "rebound_seconds": np.float64,
    "fresh_seconds": np.float64,
}

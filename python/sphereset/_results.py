"""The result classes of the fit and the evaluation, written by scripts/gen_results.py from the
library's field lists (result_fields.hpp): do not edit; the tests check this file against the
script's output."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Dict

import numpy as np


def _plain(value: Any) -> Any:
    return value.tolist() if isinstance(value, np.ndarray) else value


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
    decimated: int
    """spheres removed by the decimation"""
    idle_teleports: int
    """spheres that covered nothing alone, moved to split another"""
    restart: int
    """which restart won (0: the one with the seed given)"""
    seconds: Dict[str, float]
    """total: seconds in all; sampling: seconds sampling points; assignment: seconds assigning points to spheres; update: seconds refitting spheres; teleport: seconds teleporting; bounding: seconds in the bound"""
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

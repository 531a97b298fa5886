// The fit's and the evaluation's results as field lists (result_fields.hpp): the one place
// where a result field gets the name, type and meaning every front door shows.
#include "sphereset/result_fields.hpp"

namespace sphereset {

std::vector<ResultField> fitResultFields(const FitResult& r, double mesh_volume) {
  const double v = mesh_volume;
  return {
      {"outside_volume", r.outside_volume, "exact outside volume of each sphere"},
      {"energy_history", r.energy_history, "Σ outside volume after each clustering round"},
      {"energy", r.energy, "Σ outside volume of the set (absolute units)"},
      {"energy_before_bounding", r.energy_before_bounding, "the same before the bound"},
      {"mesh_volume", v, "volume of the solid fitted (the repaired one when repaired)"},
      {"er_sum", r.energy / v, "E_r: Σ outside volume / mesh volume"},
      {"er_sum_before_bounding", r.energy_before_bounding / v, "E_r before the bound"},
      {"rounds", int64_t{r.iterations}, "assignment/update rounds run"},
      {"converged", r.converged, "stopped because neither rounds nor teleports improved"},
      {"teleports", int64_t{r.teleports}, "teleports tried"},
      {"teleports_kept", int64_t{r.teleports_accepted}, "teleports that lowered the energy"},
      {"points", r.points, "points clustered"},
      {"interior_points", r.interior_points, "of which inside the solid"},
      {"sov_queries", r.sov_queries, "outside-volume evaluations in point assignment"},
      {"sov_queries_culled", r.sov_queries_culled,
       "assignment candidates settled by a lower bound instead"},
      {"optimizer_queries", r.optimizer_queries, "outside-volume evaluations in sphere updates"},
      {"bounding_enlarged", r.bounding_enlarged, "spheres enlarged by the last bounding pass"},
      {"bounding_pieces", r.bounding_pieces, "triangle pieces that made a sphere grow"},
      {"bounding_queries", r.bounding_queries, "outside-volume evaluations of the bound"},
      {"bounding_interior_cells", r.bounding_interior_cells,
       "interior cubes that made a sphere grow"},
      {"shrink_passes", int64_t{r.shrink_passes}, "shrinking passes kept"},
      {"refine_points", r.refine_points,
       "points kept covered by the refinement (0: not run or not kept)"},
      {"radii.objective", r.radii.objective,
       "Σ outside volume of the optimal-radii program's solution (its units, before the bound)"},
      {"radii.lower_bound", r.radii.lower_bound, "the program's proven lower bound"},
      {"radii.gap", r.radii.gap,
       "(objective - lower bound) / objective; 0: proven optimal, -1: not run"},
      {"radii.start", r.radii.start, "Σ outside volume of the set the program started from"},
      {"radii.units", r.radii.units, "surface pieces and interior points of the program"},
      {"radii.rows", r.radii.rows, "its coverage rows after reduction"},
      {"radii.kept", r.radii.kept, "its bounded solution replaced the set"},
      {"decimated", int64_t{r.decimated}, "spheres removed by the decimation"},
      {"idle_teleports", int64_t{r.idle_teleports},
       "spheres that covered nothing alone, moved to split another"},
      {"restart", int64_t{r.restart}, "which restart won (0: the one with the seed given)"},
      {"seconds.total", r.seconds.total, "seconds in all"},
      {"seconds.sampling", r.seconds.sampling, "seconds sampling points"},
      {"seconds.assignment", r.seconds.assignment, "seconds assigning points to spheres"},
      {"seconds.update", r.seconds.update, "seconds refitting spheres"},
      {"seconds.teleport", r.seconds.teleport, "seconds teleporting"},
      {"seconds.bounding", r.seconds.bounding,
       "seconds after the clustering: bound, shrink, refine and radii"},
      {"seconds.bound", r.seconds.bound,
       "seconds in the exact bound's passes (surface with refits, interior, original)"},
      {"seconds.shrink", r.seconds.shrink, "seconds in the shrinking passes"},
      {"seconds.refine", r.seconds.refine, "seconds in the coverage-aware refinement"},
      {"seconds.radii", r.seconds.radii, "seconds choosing optimal radii"},
  };
}

std::vector<ResultField> evalResultFields(const EvalResult& r) {
  return {
      {"mesh_volume", r.mesh_volume, "volume of the solid"},
      {"bbox_diagonal", r.bbox_diagonal, "its bounding box's diagonal (the unit of the gaps)"},
      {"er_sum", r.er_sum, "E_r: Σ outside volume / mesh volume (exact)"},
      {"walls_volume", r.walls_volume,
       "the walls' volume when the solid is their envelope (else the solid's)"},
      {"er_walls", r.er_walls, "E_r against the walls: Σ outside volume of them / their volume"},
      {"er_union", r.er_union, "outside volume of the union / mesh volume (Monte Carlo)"},
      {"er_union_stderr", r.er_union_stderr, "its standard error"},
      {"outside_volume", r.outside_volume, "exact outside volume of each sphere"},
      {"surface_covered", r.surface_covered, "the surface is certified covered"},
      {"max_surface_gap", r.max_surface_gap, "largest surface gap found / diagonal"},
      {"surface_uncertified_area", r.surface_uncertified_area,
       "area neither certified nor refuted"},
      {"uncovered_triangles", r.uncovered_triangles, "triangles not covered"},
      {"original_covered", r.original_covered,
       "the original triangles are certified covered (true when the mesh was not repaired)"},
      {"max_original_gap", r.max_original_gap, "largest gap of the original triangles / diagonal"},
      {"original_uncovered_triangles", r.original_uncovered_triangles,
       "original triangles not covered"},
      {"interior_covered", r.interior_covered, "the interior is certified covered"},
      {"max_interior_gap", r.max_interior_gap, "largest interior gap found / diagonal"},
      {"protrusion.bound", r.protrusion,
       "certified: no point of the union is farther than this from the solid (length)"},
      {"protrusion.witness_distance", r.protrusion_witness_distance,
       "a point of the union this far from the solid was found"},
      {"protrusion.witness",
       std::vector<double>{r.protrusion_witness.x(), r.protrusion_witness.y(),
                           r.protrusion_witness.z()},
       "that point"},
      {"protrusion.sphere", int64_t{r.protrusion_sphere}, "the ball it is in (-1: not run)"},
      {"protrusion.per_sphere", r.sphere_protrusion, "each ball's certified bound"},
      {"protrusion.converged", r.protrusion_converged,
       "bound within the tolerance of the witness (else a looser bound, still valid)"},
      {"interior_uncertified_cells", r.interior_uncertified_cells,
       "finest cells at the surface left undecided"},
      {"proximity_error", r.proximity_error,
       "mean outside-length difference over random segments / diagonal"},
      {"shadow_error_sky", r.shadow_error_sky, "shadow RMS error under sky light"},
      {"shadow_error_lights", r.shadow_error_lights, "shadow RMS error under directional lights"},
      {"seconds", r.seconds, "seconds of the evaluation"},
  };
}

std::vector<ResultField> repairResultFields(const RepairResult& r) {
  return {
      {"kind", std::string(repairName(r.kind)), "what the repair did (repair.hpp's ladder)"},
      {"weld_tolerance", r.weld_tolerance, "the weld tolerance used (0: exact)"},
      {"triangles_flipped", r.triangles_flipped, "flipped by the consistent orientation"},
      {"holes_capped", r.holes_capped, "boundary loops closed"},
      {"shells_dropped", r.shells_dropped, "shells nested inside another, dropped"},
      {"cavities_filled", r.cavities_filled, "inward shells dropped (cavities filled)"},
      {"cavities_kept", r.cavities_kept, "inward shells kept as cavities"},
      {"triangles", static_cast<int64_t>(r.solid.triangles.size()), "the solid's triangles"},
      {"volume", signedVolume(r.solid), "the solid's volume"},
      {"volume_ratio", r.volume_ratio, "the solid's volume over the input's (NaN: undefined)"},
      {"wrap_alpha", r.wrap_alpha, "the wrap's alpha (0 unless wrapped)"},
      {"wrap_offset", r.wrap_offset, "the wrap's offset (0 unless wrapped)"},
      {"solid", std::string(solidName(r)),
       "what the solid is: the walls as repaired, or their envelope (openings closed)"},
      {"fill_openings", r.fill_openings, "the envelope's opening size (0: no envelope)"},
      {"walls_volume", r.fill_openings > 0.0 ? signedVolume(r.walls) : signedVolume(r.solid),
       "the walls' volume (the solid's when it is the walls)"},
      {"seconds", r.seconds, "seconds repairing"},
      {"notes", r.notes, "one sentence per step taken"},
  };
}

std::vector<ResultField> meshDiagnosisFields(const MeshDiagnosis& d) {
  const Aabb& b = d.bbox;
  return {
      {"vertices", d.vertices, "vertices"},
      {"triangles", d.triangles, "triangles"},
      {"edges", d.edges, "edges"},
      {"closed", d.closed, "no boundary edges"},
      {"manifold", d.manifold, "no non-manifold edges or vertices"},
      {"oriented", d.oriented, "every interior edge traversed once each way"},
      {"solid", d.isSolid(), "closed, manifold, oriented, positive volume: what a fit needs"},
      {"components", d.components, "edge-connected components"},
      {"boundary_edges", d.boundary_edges, "edges with one triangle"},
      {"nonmanifold_edges", d.nonmanifold_edges, "edges with three or more triangles"},
      {"nonmanifold_vertices", d.nonmanifold_vertices, "vertices whose fan is not one disk"},
      {"misoriented_edges", d.misoriented_edges, "edges traversed the same way twice"},
      {"volume", d.volume, "signed volume"},
      {"area", d.area, "surface area"},
      {"bbox_min", std::vector<double>{b.min.x(), b.min.y(), b.min.z()}, "bounding box corner"},
      {"bbox_max", std::vector<double>{b.max.x(), b.max.y(), b.max.z()}, "bounding box corner"},
      {"bbox_diagonal", b.diagonal(), "its diagonal"},
      {"min_edge", d.min_edge, "shortest edge"},
      {"max_edge", d.max_edge, "longest edge"},
  };
}

std::vector<ResultField> loadReportFields(const LoadReport& r) {
  return {
      {"scene_meshes", r.scene_meshes, "meshes in the file's scene graph"},
      {"file_vertices", r.file_vertices, "vertices as stored in the file"},
      {"file_triangles", r.file_faces, "faces after triangulation, before clean-up"},
      {"welded_vertices", r.welded_vertices, "vertices merged into another"},
      {"unused_vertices", r.unused_vertices, "vertices no kept triangle uses, removed"},
      {"degenerate_dropped", r.degenerate_dropped, "triangles without area, dropped"},
      {"duplicate_dropped", r.duplicate_dropped, "triangles repeating another, dropped"},
      {"flipped", r.flipped, "the orientation was reversed to make the volume positive"},
  };
}

std::vector<ResultField> shellCountFields(const ShellCounts& c) {
  return {
      {"shells", c.shells, "edge-connected shells"},
      {"closed_shells", c.closed, "of them closed"},
      {"clean_shells", c.clean, "closed, oriented and free of crossings"},
      {"inward_shells", c.inward, "closed and facing inward"},
      {"nested_shells", c.nested, "inside another shell"},
      {"intersecting_shell_pairs", c.intersecting_pairs, "pairs of shells that cross"},
      {"intersecting_triangle_pairs", c.triangle_pairs, "pairs of triangles that cross"},
      {"intersections_truncated", c.truncated, "the crossing search stopped at its cap"},
  };
}

}  // namespace sphereset

// The animation's results as field lists (animate.hpp, result_fields.hpp): the one place where a
// frame's and the whole run's result fields get the names, types and meanings that
// `sphereset animate`'s summary.json and Python's AnimateResult show.
#include <vector>

#include "sphereset/animate.hpp"

namespace sphereset {

std::vector<ResultField> animateFrameFields(const AnimateFrameResult& f) {
  return {
      {"er", f.er, "E_r of the moved set with the rest radii"},
      {"surface_covered", f.surface_covered, "its surface certificate"},
      {"interior_covered", f.interior_covered, "its interior certificate"},
      {"max_gap", f.max_gap, "largest surface or interior gap / diagonal of the deformed mesh"},
      {"crossings", f.crossings, "crossing triangle pairs of the deformed mesh (capped)"},
      {"er_rebound", f.er_rebound, "rebound: E_r of the grown set"},
      {"rebound_covered", f.rebound_covered, "rebound: the grown set certified"},
      {"radius_growth", f.radius_growth, "rebound: Σ (r' - r) / Σ r"},
      {"max_radius_growth", f.max_radius_growth, "rebound: max (r' - r) / r"},
      {"grown", f.grown, "rebound: spheres whose radius grew"},
      {"er_fresh", f.er_fresh, "fresh fit: E_r of a fresh fit of the frame"},
      {"update_seconds", f.update_seconds, "seconds moving the centres"},
      {"eval_seconds", f.eval_seconds, "seconds certifying"},
      {"rebound_seconds", f.rebound_seconds, "seconds in the rebound"},
      {"fresh_seconds", f.fresh_seconds, "seconds in the fresh fit"},
  };
}

std::vector<ResultField> animateResultFields(const AnimateResult& r) {
  return {
      {"weighting", std::string(centreWeightingName(r.weighting)), "the centres' weighting used"},
      {"weights_seconds", r.weights_seconds, "seconds precomputing the centre weights"},
      {"frames_covered", r.frames_covered, "frames whose moved set covers surface and interior"},
      {"frames_crossing", r.frames_crossing, "frames whose deformed mesh passes through itself"},
      {"seconds", r.seconds, "seconds in all"},
  };
}

}  // namespace sphereset

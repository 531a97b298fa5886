// The whole-robot fit's results as field lists (robot_fit.hpp, result_fields.hpp): the one
// place where a link's and the robot's result fields get the names, types and meanings that
// `sphereset robot --json` and Python's results show.
#include <cstdint>
#include <vector>

#include "sphereset/robot_fit.hpp"

namespace sphereset {

std::vector<ResultField> robotLinkFields(const RobotLinkFit& j) {
  std::vector<int64_t> counts(j.curve.counts.begin(), j.curve.counts.end());
  std::vector<double> sphere_protrusion;
  if (j.fitted)
    for (double b : j.eval.sphere_protrusion) sphere_protrusion.push_back(b + j.padding);
  return {
      {"link", j.link, "the link's name"},
      {"count", static_cast<int64_t>(j.spheres.size()), "spheres, primitives included"},
      {"primitives", int64_t{j.primitives}, "sphere primitives of its geometry, kept exact"},
      {"files", j.files, "the mesh files of its geometry"},
      {"from_visual", j.from_visual, "fitted to its <visual> geometry (it has no <collision>)"},
      {"skipped", j.skipped, "link_spheres set it to 0: no spheres"},
      {"fitted", j.fitted, "some spheres were fitted"},
      {"covered", j.covered, "the coverage certificates of the fitted spheres"},
      {"solid", std::string(solidName(j.repair)),
       "what was fitted: the link's walls or their envelope (openings closed)"},
      {"fill_openings", j.repair.fill_openings, "the envelope's opening size (0: walls)"},
      {"volume", j.fitted ? j.eval.mesh_volume : 0.0, "the fitted solid's volume"},
      {"walls_volume", j.fitted ? j.eval.walls_volume : 0.0, "the walls' volume"},
      {"er_sum", j.fitted ? j.eval.er_sum : 0.0,
       "E_r of the fitted spheres against the fitted solid, before padding"},
      {"er_walls", j.fitted ? j.eval.er_walls : 0.0, "E_r of the same against the walls"},
      {"outside_volume", j.outside_volume, "Σ outside volume of the fitted spheres"},
      {"protrusion", j.fitted ? j.eval.protrusion + j.padding : 0.0,
       "certified: no point of the link's spheres (padded) is farther than this from the "
       "fitted solid (length)"},
      {"sphere_protrusion", sphere_protrusion,
       "each fitted sphere's certified bound (padded), in the order the fitted spheres follow "
       "the primitives in `spheres`"},
      {"padding", j.padding, "added to every radius"},
      {"budget_curve.counts", counts, "under a budget: the quick fits' sphere counts"},
      {"budget_curve.outside_volume", j.curve.outside_volume, "and their outside volumes"},
      {"split_count", int64_t{j.split_count}, "the curve split's count (-1: no budget)"},
      {"split_volume", j.split_volume, "its fit's outside volume"},
      {"seconds", j.seconds, "seconds fitting the link (all its fits), without repair"},
      {"protrusion_limit", j.protrusion_limit,
       "its protrusion limit (max_protrusion or link_max_protrusion; 0: none)"},
      {"limit_met", j.limit_met, "covered and within its protrusion limit (true without one)"},
  };
}

std::vector<ResultField> robotFitFields(const RobotFitResult& r) {
  return {
      {"budget_split", r.budget_split, "some link's count came from the budget"},
      {"outside_volume", r.outside_volume, "Σ outside volume of the links the budget split"},
      {"split_outside_volume", r.split_outside_volume, "the same for the curve split alone"},
      {"tolerance", r.tolerance, "some link had a protrusion limit"},
      {"tolerance_met", r.tolerance_met, "every link with a protrusion limit met it"},
      {"seconds", r.seconds, "seconds in all"},
  };
}

}  // namespace sphereset

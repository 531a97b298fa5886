// Splitting a budget of spheres over the links of a robot: by what lowers the robot's total
// outside volume most, from each link's outside volume measured at a few sphere counts.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/options.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/result_fields.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// A link's outside volume (absolute units) after fits with a few sphere counts.
struct LinkFitCurve {
  std::vector<int> counts;             // increasing, at least one, all >= 1
  std::vector<double> outside_volume;  // one per count, > 0 where measured
};

// The outside volume at k spheres on the curve: piecewise linear in log k and log volume
// between the measured counts, and the last piece's power law beyond them (the first piece's
// below them); a single measured count gives a constant. A volume of 0 (a link bounded
// exactly) stays 0 from there on. The curve must be non-empty with increasing counts from 1 and
// one finite volume >= 0 each, and k >= 1: kInvalidArgument otherwise (a NaN is never returned).
Expected<double> curveVolume(const LinkFitCurve& curve, int k);

// The lower envelope the budget split uses: measured volumes made non-increasing (k + 1
// spheres can always do what k do: a repeated sphere adds nothing), then the lower convex
// hull of the points in log k / log volume, so that the interpolated curve is convex and
// decreasing and the greedy split is optimal on it. Quick fits at a few counts are noisy (a
// fit can land in a worse local minimum with more spheres); the envelope keeps the best
// measured at or below each count. Points after the first volume of 0 are dropped.
LinkFitCurve curveEnvelope(const LinkFitCurve& curve);

// Counts per link, from the envelopes of the curves (curveEnvelope). `fixed[i]` >= 0 fixes link i's
// count (0 skips it); -1 leaves it to the budget. Every free link gets one sphere, then each
// further sphere goes to the free link whose curve drops most with one more (ties to the lower
// index), until the budget is spent. Errors (kInvalidArgument): the budget below the fixed counts
// plus one per free link.
Expected<std::vector<int>> splitBudget(const std::vector<LinkFitCurve>& curves,
                                       const std::vector<int>& fixed, int budget);

// One fitted candidate for a link: its sphere count and the outside volume the fit measured.
struct LinkCandidate {
  int count = 0;
  double outside_volume = 0.0;
};

// Picks one candidate per link (every list non-empty) so that the counts add up to at most
// `budget` and the total outside volume is least (exact, by dynamic programming over the
// totals reachable; ties go to the smaller total count, then to earlier candidates). Returns
// the index chosen per link. The robot command fits each link at the count of the curve split
// and at counts either side of it and picks among them, so its total is never worse than the
// split's.
// Errors (kInvalidArgument): an empty list, or no choice within the budget.
Expected<std::vector<int>> pickCandidates(const std::vector<std::vector<LinkCandidate>>& candidates,
                                          int budget);

// What each link's solid is (RobotFitOptions::link_solid).
enum class LinkSolid {
  kEnvelope,  // the walls with the hollow behind their openings (RepairOptions::fill_openings)
  kWalls,     // the walls alone, as the repair makes them
};

// Fitting a whole robot (what `sphereset robot` does; fit_robot.cpp).
struct RobotFitOptions {
  // Spheres over the whole robot, sphere primitives included (at most: the split may use fewer
  // where fewer fitted better). 0: `default_link_spheres` per link not fixed below.
  int budget = 0;
  std::map<std::string, int> link_spheres;     // link -> its count; 0 skips the link
  double padding = 0.0;                        // added to every radius (absolute units)
  std::map<std::string, double> link_padding;  // link -> its padding instead
  FitQuality quality = FitQuality::kDefault;   // the presets of fit.hpp
  uint64_t seed = 1;
  RepairOptions repair;  // how each link's geometry is made a solid (repair.hpp)
  // kEnvelope: each link's solid is its envelope, repair.fill_openings (0 there means
  // kAutomatic: the link's smallest extent); kWalls: the walls (repair.fill_openings must be 0).
  // A planner treats a casing's hollow as part of the link; fitted as walls, the spheres avoid
  // it at a cost of outside volume that buys nothing.
  LinkSolid link_solid = LinkSolid::kEnvelope;
  // link -> its solid instead of link_solid, for a link the hollow rule gets wrong (it can take
  // concave corners for a hollow; docs/algorithm.md, "From a mesh to a solid"): kWalls, or
  // kEnvelope kept whatever its volume (RepairOptions::keep_envelope).
  std::map<std::string, LinkSolid> link_solid_for;
  int default_link_spheres = 8;
  // Protrusion limits (a length above 0; max_protrusion 0: none; a link_max_protrusion entry
  // must be above 0): the certified protrusion of a link's padded spheres from its solid
  // (evaluate.hpp, sphereProtrusion, plus the padding) at most this, for every link fitted
  // (max_protrusion) or for one (link_max_protrusion, instead). Without a budget, a
  // link with a limit gets the fewest spheres that meet it (at most 256); with one, every free
  // link needs a limit and the budget goes where the worst link's protrusion over its limit is
  // largest (protrusion_split.cpp). Counts fixed by link_spheres stay fixed.
  double max_protrusion = 0.0;
  std::map<std::string, double> link_max_protrusion;
  // The same limits as fractions of each link's own solid's bounding-box diagonal (the option's
  // text "P%" gives P / 100; 0: none). A row sets one form: max_protrusion or its fraction, and
  // a link's entry in one of the two maps, never both. A link's own limit (either map) comes
  // before the robot's.
  double max_protrusion_fraction = 0.0;
  std::map<std::string, double> link_max_protrusion_fraction;
  bool toleranceActive() const {
    return max_protrusion > 0.0 || max_protrusion_fraction > 0.0 || !link_max_protrusion.empty() ||
           !link_max_protrusion_fraction.empty();
  }
  std::string name;  // prefixes messages (e.g. the URDF's path)
  // Each link fit's progress (fit.hpp), with the link's name. Called from the threads that fit
  // the links, several at once; it must be thread-safe. It may throw to cancel: the exception
  // leaves fitRobot.
  std::function<void(const std::string& link, const FitProgress& progress)> progress;
  // Each finished link: its budget curve ("link curves") and each of its fits ("link fits").
  // Calls are one at a time (from the threads that fit the links). It may throw to cancel.
  std::function<void(const RobotProgress&)> steps;
};

// RobotFitOptions' numbers as one table (options.hpp): budget, default_link_spheres,
// link_spheres (keyed LINK=N), padding, link_padding (keyed LINK=R), link_solid and
// link_solid_for (keyed LINK=envelope|walls), max_protrusion and link_max_protrusion (keyed
// LINK=D; either may be "P%" of each link's diagonal). The command line's flags of `sphereset
// robot` and Python's fit_robot keywords are made from it. setRobotFitOption sets a row from the
// text a user typed (a keyed row adds or replaces its link's entry); checkRobotFitOptions checks a
// struct against the rows with the same messages. (quality and seed are the fit table's rows,
// fit.hpp; the repair's are repair.hpp's.)
std::span<const OptionSpec> robotFitOptionTable();
// The repair options `link`'s geometry is made a solid with: under its entry in `per_link`
// (RobotFitOptions::link_solid_for), else under `all` (link_solid). Walls: fill_openings 0. An
// envelope: repair.fill_openings, 0 meaning kAutomatic; one that `per_link` chose is kept even
// where it encloses no hollow (keep_envelope). fitRobot, the view and `sphereset eval
// ROBOT.urdf --link` use it, so a link is measured as the robot command fits it.
RepairOptions linkRepairOptions(const RepairOptions& repair, LinkSolid all,
                                const std::map<std::string, LinkSolid>& per_link,
                                const std::string& link);
// Checks the link solids for `robot` (kInvalidArgument, prefixed by `name`): `per_link` names
// links of the robot only, and a fill_openings other than 0 has a link to apply to (some link's
// solid is an envelope).
Status checkLinkSolids(const Robot& robot, const RepairOptions& repair, LinkSolid all,
                       const std::map<std::string, LinkSolid>& per_link, const std::string& name);
Status setRobotFitOption(RobotFitOptions* o, const std::string& name, const std::string& text);
Status checkRobotFitOptions(const RobotFitOptions& o);
// A robot's best effort (the spheres written when a link misses its limit: robot --best-effort)
// needs a protrusion limit (checkBestEffort's rule and message, naming max_protrusion and
// link_max_protrusion).
Status checkRobotBestEffort(bool best_effort, const RobotFitOptions& o);

// One link with geometry.
struct RobotLinkFit {
  std::string link;
  std::vector<Sphere> spheres;  // its sphere primitives, then the fitted spheres; padded
  int primitives = 0;
  bool skipped = false;      // link_spheres fixed it at 0: no spheres
  bool from_visual = false;  // fitted to its <visual> geometry (it has no <collision>)
  bool fitted = false;       // some spheres were fitted (it has geometry other than spheres)
  bool covered = true;       // the certificates of eval (surface, interior, original triangles)
  std::vector<std::string> files;  // the mesh files of its geometry
  RepairResult repair;             // when fitted: how its geometry became a solid
  EvalResult eval;                 // when fitted: of the fitted spheres, before padding
  double outside_volume = 0.0;     // Σ outside volume of the fitted spheres, before padding
  double padding = 0.0;
  LinkFitCurve curve;             // under a budget: the quick fits' outside volumes
  int split_count = -1;           // under a budget: the curve split's count...
  double split_volume = 0.0;      // ...and its fit's outside volume
  double seconds = 0.0;           // fitting (all its fits), without repair
  double protrusion_limit = 0.0;  // its limit (max_protrusion or link_max_protrusion; 0: none)
  bool limit_met = true;          // covered and within its limit (true without a limit)
};

struct RobotFitResult {
  std::vector<RobotLinkFit> links;  // the links with geometry, in the robot's order
  bool budget_split = false;        // some link's count came from the budget
  // Totals over the links the budget split: as chosen, and for the curve split alone.
  double outside_volume = 0.0, split_outside_volume = 0.0;
  bool tolerance = false;     // some link had a protrusion limit...
  bool tolerance_met = true;  // ...and every such link met it
  double seconds = 0.0;
};

// The results as field lists (result_fields.hpp), for `sphereset robot --json` and Python's
// RobotLinkFit/RobotFitResult: a link's counts, flags, E_r, outside volume, padding, budget
// curve and the curve split (-1 and 0 where they do not apply); the robot's totals.
std::vector<ResultField> robotLinkFields(const RobotLinkFit& link);
std::vector<ResultField> robotFitFields(const RobotFitResult& result);

// Fits every link of `robot`. Errors: options outside robotFitOptionTable's rows (as
// checkRobotFitOptions says them); messages prefixed by options.name: link_spheres,
// link_padding or link_solid_for naming no link (kInvalidArgument), a budget too small for the
// fixed counts and one sphere per other link (kInvalidArgument), a link's geometry that cannot be
// loaded or made a solid (as linkSolid).
Expected<RobotFitResult> fitRobot(const Robot& robot, const RobotFitOptions& options);

}  // namespace sphereset

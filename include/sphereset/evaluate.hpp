// Evaluation of a sphere set against the solid it should bound (paper Sec. 7, and more).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sphereset/cover.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/options.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

struct EvalOptions {
  uint64_t seed = 1;               // all sampling is seeded; results do not depend on threads
  int64_t union_samples = 200000;  // Monte Carlo samples for the union's outside volume
  int proximity_segments = 3000;   // random surface-to-surface segments (paper Sec. 7)
  int surface_max_depth = kSurfaceSplitDepth;    // 4^depth sub-triangles at most per triangle
  int interior_max_depth = kInteriorSplitDepth;  // octree refinement below an 8³ grid of the bounds
  // The protrusion's tolerance (sphereProtrusion below), as a fraction of the solid's bounding
  // box diagonal: its certified bound is within this of a witness's distance. 0 skips it.
  double protrusion_tolerance = 1e-3;
  // Shadow comparison on a ground plane under the object (paper Sec. 7): the up axis
  // (0 x, 1 y, 2 z), pixels per side of the plane and directional lights over the upper
  // hemisphere. A resolution of 0 skips it.
  int up_axis = 1;
  int shadow_resolution = 48;
  int shadow_lights = 64;
  // The triangles of the input a repaired solid was made from (repair.hpp), certified as
  // covered too; not owned, may be null.
  const Mesh* original = nullptr;
  // When the solid is an envelope (repair.hpp, envelopeWalls): its walls, against which E_r is
  // reported too (EvalResult::er_walls); not owned, may be null.
  const Mesh* walls = nullptr;
  // Called from the calling thread every `poll_interval` seconds or so inside the long loops
  // (samples, segments, coverage, shadows). It may throw to cancel the evaluation (how the
  // Python module honours Ctrl-C): the exception leaves evaluateSpheres.
  std::function<void()> poll;
  double poll_interval = 0.25;
};

struct EvalResult {
  double mesh_volume = 0.0;
  double bbox_diagonal = 0.0;
  // E_r of the paper (eq. 4 / volume): Σ_i SOV(S_i) / vol(mesh), exact.
  double er_sum = 0.0;
  // Outside volume of the union of the spheres (overlaps counted once) / vol(mesh), Monte
  // Carlo, with its standard error.
  double er_union = 0.0;
  double er_union_stderr = 0.0;
  std::vector<double> outside_volume;  // per sphere, exact
  // E_r against the walls when the solid is their envelope (EvalOptions::walls): Σ_i SOV(S_i)
  // against the walls / their volume, exact. Without walls: the solid's volume and er_sum.
  double walls_volume = 0.0;
  double er_walls = 0.0;
  // Surface coverage: certified by subdivision (every sub-triangle inside one sphere).
  bool surface_covered = false;
  double max_surface_gap = 0.0;           // largest distance found from surface to the union / diag
  double surface_uncertified_area = 0.0;  // area that could be neither certified nor refuted
  int64_t uncovered_triangles = 0;
  // Coverage of EvalOptions::original, certified like the surface's (true when none is given).
  bool original_covered = true;
  double max_original_gap = 0.0;  // / diag
  int64_t original_uncovered_triangles = 0;
  // Interior coverage: certified on an adaptive octree of cells.
  bool interior_covered = false;
  double max_interior_gap = 0.0;           // / diag
  int64_t interior_uncertified_cells = 0;  // finest cells at the surface left undecided
  // Proximity (paper Sec. 7): mean |outside length vs mesh - outside length vs spheres| over
  // random surface-to-surface segments, / diag.
  double proximity_error = 0.0;
  // Shadow RMS errors (irradiance on the ground plane, 1 = unoccluded light from straight
  // above): uniform sky light (ambient occlusion) and each directional light on its own.
  double shadow_error_sky = 0.0;
  double shadow_error_lights = 0.0;
  // Protrusion (sphereProtrusion, length units): no point of the union is farther than
  // `protrusion` from the solid, and `protrusion_witness` (in ball `protrusion_sphere`) is
  // `protrusion_witness_distance` from it; `sphere_protrusion`: each ball's bound. Zeros and
  // sphere -1 when skipped (protrusion_tolerance 0).
  double protrusion = 0.0;
  double protrusion_witness_distance = 0.0;
  Vec3 protrusion_witness = Vec3::Zero();
  int protrusion_sphere = -1;
  std::vector<double> sphere_protrusion;
  bool protrusion_converged = true;
  double seconds = 0.0;
};

// The evaluation `sphereset fit` (and the batch) runs on its result: the coverage certificates
// and E_r of the union by 100000 seeded samples; no proximity segments, no shadows.
inline EvalOptions fitCheckEvalOptions(uint64_t seed, const Mesh* original = nullptr,
                                       const Mesh* walls = nullptr) {
  EvalOptions eo;
  eo.seed = seed;
  eo.union_samples = 100000;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.original = original;
  eo.walls = walls;
  return eo;
}

// The evaluation's options as one table (options.hpp), from which `sphereset eval`'s flags and
// the keywords of Python's evaluate are made: seed, samples, segments, up ("x", "y", "z"),
// shadow_resolution, shadow_lights, surface_max_depth, interior_max_depth, with the limits of
// limits.hpp.
std::span<const OptionSpec> evalOptionTable();
// Sets the option `name` of `options` from a user's text; kInvalidArgument for an unknown name
// or a bad value (the message of parseOption).
Status setEvalOption(EvalOptions* options, const std::string& name, const std::string& text);
// Every field of `options` within the table's limits (for options built in code), with the
// message setEvalOption gives for the same value.
Status checkEvalOptions(const EvalOptions& options);

// Needs a closed solid (callers check with diagnoseMesh first). Errors (kInvalidArgument):
// options out of the table's limits, no spheres, a sphere with a NaN, infinite or negative
// value.
Expected<EvalResult> evaluateSpheres(const SolidIndex& index, const std::vector<Sphere>& spheres,
                                     const EvalOptions& options = {});

// Protrusion of a set from a solid: the largest distance from a point of the union of the
// balls to the solid (0 inside it), i.e. the one-sided Hausdorff distance from the union to the
// solid, certified by branch and bound over each ball (protrusion.cpp): `upper` bounds the
// distance of every point of the union, `lower` is the distance of `witness`, a point of ball
// `sphere`; upper - lower <= tolerance unless a ball ran out of cells (converged false, upper
// still valid). Per ball the same, for the bounds per sphere and per link, unless only the
// union's figure is asked for (union_only below).
struct ProtrusionOptions {
  double tolerance = 0.0;  // length units, above 0: the bound's slack over the witness
  // Octree cells per ball at most. A fitted ball needs up to about 27 000 at 0.001 of the
  // diagonal (ur5_upperarm, 64 spheres); a ball far larger than the solid needs many more to
  // tighten its bound, which stays valid, only looser (converged false), past the limit.
  int64_t max_cells = 50000;
  // Only the union's figures are wanted (a curve's checks): a ball is refined only while its
  // bound exceeds the settle value, the largest of `known` and the distances found on every
  // ball's seed directions, since no point of it can then set the union's figure. Its `upper`
  // is then a valid bound of at most that value, not within `tolerance` of its own `lower`; the
  // union's `upper` keeps its guarantee (within `tolerance` of the union's `lower`, or of
  // `known` when that is larger).
  bool union_only = false;
  // Length units, at least 0: a distance some point of the union reaches. A larger value keeps
  // every bound valid and only loosens the union's (to within the tolerance of `known`).
  double known = 0.0;
};
struct SphereProtrusionBound {
  double lower = 0.0, upper = 0.0;
  Vec3 witness = Vec3::Zero();
  int64_t cells = 0;
  bool converged = true;  // upper within tolerance of lower, or at most the settle value
};
struct ProtrusionResult {
  double upper = 0.0;
  double lower = 0.0;
  Vec3 witness = Vec3::Zero();
  int sphere = -1;
  std::vector<SphereProtrusionBound> spheres;
  int64_t cells = 0;
  bool converged = true;
  double seconds = 0.0;
};
// Errors (kInvalidArgument): a tolerance that is not a finite length above 0, max_cells below
// 1, `known` negative or not finite, a sphere with a NaN, infinite or negative value. The solid
// must be closed.
Expected<ProtrusionResult> sphereProtrusion(const SolidIndex& solid,
                                            const std::vector<Sphere>& spheres,
                                            const ProtrusionOptions& options);

// The fewest spheres that meet a tolerance: a certified protrusion of at most max_protrusion
// (length) or max_protrusion_fraction of the bounding-box diagonal (the smaller when both), and
// an E_r of at most max_er, each 0 for no limit, capped at max_spheres (tolerance_fit.cpp: fits
// at 1, 2, 4, ... spheres until one meets it, then bisection; the fits of progressive runs,
// ProgressiveFit, each started from the last one's clusterings, when the request allows them,
// else independent fits). The result is
// the fit and check of the smallest count tried that met it (met), or else of the best count
// tried (covered first, then the smaller protrusion, or E_r without a protrusion limit), and
// every count tried (`curve`, in the order tried). `original` and `walls` as EvalOptions'.
struct CurvePoint {
  int n = 0;
  double er_sum = 0.0;
  double protrusion = 0.0;  // certified bound
  bool covered = false;
  bool meets = false;
  // Its fit and check (fitCurve: a step's, not the other direction's; the last count, made
  // beside the others, ProgressiveOptions::top_alongside: the wait for it).
  double seconds = 0.0;
};
struct ToleranceOptions {
  double max_protrusion = 0.0;
  double max_protrusion_fraction = 0.0;
  double max_er = 0.0;
  int max_spheres = 256;
  // Whether max_spheres was given (setToleranceOption sets it): a cap given without a limit is
  // refused (checkToleranceRequest) rather than ignored.
  bool max_spheres_given = false;
  const Mesh* original = nullptr;
  const Mesh* walls = nullptr;
  // After each count tried, from the calling thread; may throw to end the search (the exception
  // propagates, nothing is returned).
  std::function<void(const CurvePoint&)> progress;
  // Each fit's progress within a count, as FitOptions::progress (FitProgress::spheres is the
  // count being fitted); may throw to end the search mid-fit, as progress may.
  std::function<void(const FitProgress&)> fit_progress;
  bool active() const;  // some limit is set
  // A cap is set: given (max_spheres_given) or not the default. A door that has no cap of its
  // own (a robot's request) or hands the options on (Python's item dicts) asks this.
  bool capSet() const;
};
struct ToleranceFitResult {
  bool met = false;
  int n = 0;
  double protrusion_limit = 0.0;  // the length the protrusion was held to (0: none)
  FitResult fit;
  EvalResult eval;
  std::vector<CurvePoint> curve;
  bool progressive = false;  // the counts were fits of progressive runs
  double seconds = 0.0;
};
// The table of the tolerance options (options.hpp): max_protrusion (a trailing % makes it a
// percentage of the diagonal), max_er, max_spheres; the fit command's flags and Python's
// keywords. setToleranceOption sets one from a user's text (kInvalidArgument as parseOption).
std::span<const OptionSpec> toleranceOptionTable();
Status setToleranceOption(ToleranceOptions* options, const std::string& name,
                          const std::string& text);
// The rules of a count and a tolerance (kInvalidArgument): a request whose n was given
// (FitRequest::count_given) and an active tolerance exclude each other ("n and a tolerance
// (max_protrusion, max_er) exclude each other: the tolerance chooses the count"), and a cap given
// (max_spheres_given) needs a limit ("max_spheres goes with a tolerance (max_protrusion, max_er)").
// Every door that takes both (fit, batch and its manifest lines, Python, the view) asks this
// before its work; fitToTolerance asks it too.
Status checkToleranceRequest(const FitRequest& request, const ToleranceOptions& tolerance);
// A door's best effort (when no count up to the cap meets the limit, the best set is written
// anyway: fit --best-effort, BatchOptions::best_effort, checkRobotBestEffort) needs a limit
// (kInvalidArgument, "best_effort goes with a tolerance (LIMITS): alone it writes nothing
// more"): `limited` whether one is given, `limits` the options that give one.
Status checkBestEffort(bool best_effort, bool limited, std::string_view limits);
// The same for a tolerance search: its limits max_protrusion and max_er.
Status checkBestEffort(bool best_effort, const ToleranceOptions& tolerance);
// The options of a tolerance search (kInvalidArgument): no limit set, a limit set that its
// option's row refuses (negative, NaN; the fraction as its percentage), max_spheres out of range.
// fitToTolerance asks it; a door asks it before loading or repairing anything.
Status checkToleranceOptions(const ToleranceOptions& tolerance);
// Errors: those of checkToleranceOptions, n given (checkToleranceRequest), the request's own
// (checkFitRequest), those of fitSpheres and evaluateSpheres.
Expected<ToleranceFitResult> fitToTolerance(const SolidIndex& index, const FitRequest& request,
                                            const ToleranceOptions& options);

// The curve of E_r and certified protrusion against the count, from one run (curve_fit.cpp): the
// fit at each of `counts` (increasing, each from 1 to limits::kMaxCurveCount; none: every count
// from 1 to max_spheres), as the fits of one progressive run (ProgressiveFit) that samples the
// points of the largest count, each count's clustering started from that of the largest count
// already clustered at most half its size (from seeds when there is none), except the counts 1,
// 2 and 8 (ProgressiveOptions::seeded) and the largest count, clustered from seeds
// (ProgressiveOptions::top_from_seeds: its set is fitSpheres's at that count, as `sphereset fit -n`
// gives it; made beside the smaller counts when more than one thread is allowed,
// ProgressiveOptions::top_alongside); independent fits when the request does not allow a run
// (restarts, decimation, a baseline method). In a run, a count one above the count before it is a
// local step (ProgressiveFit::step) unless it is a power of two or the last count: each stretch of
// such counts is stepped up from the fit below and, when the fit above follows it directly, down
// from that fit too (until a set is looser than the upward one), the counts up to the
// crossover of least total outside volume taking the upward sets. The whole curve 1 ... 64
// costs 1.3 to 2.9 fits at 64 (1.81 on average over the shared meshes), and its stepped
// counts are usually looser than fits at those counts (docs/benchmarks.md, "Progressive
// fitting"). Each set is checked as `sphereset fit` checks its result (the steps' by
// the certificate of the set before, kept up to date: the same figures, the protrusion within its
// tolerance). CurvePoint::meets is false
// (no tolerance). The same request and counts give the same curve for any thread count. A count's
// set differs from the tolerance search's at that count, whose runs sample the points of other
// counts.
struct CurveOptions {
  std::vector<int> counts;
  // The counts 1 ... max_spheres when `counts` is empty (from 1 to limits::kMaxCurveCount,
  // checked either way).
  int max_spheres = 64;
  const Mesh* original = nullptr;
  const Mesh* walls = nullptr;
  // After each count, and within each count's fit, as ToleranceOptions' (either may throw to end
  // the run; nothing is returned).
  std::function<void(const CurvePoint&)> progress;
  std::function<void(const FitProgress&)> fit_progress;
};
struct CurveResult {
  std::vector<CurvePoint> points;            // one per count, in order
  std::vector<std::vector<Sphere>> spheres;  // the fit at each count (padded as the request says)
  bool progressive = false;                  // one progressive run (else independent fits)
  double seconds = 0.0;
};
// The options of a curve (kInvalidArgument): counts not increasing or out of range,
// max_spheres out of range, a request that gives n (the counts are the curve's). fitCurve asks
// it; a door asks it before loading anything.
Status checkCurveOptions(const FitRequest& request, const CurveOptions& options);
// Errors: those of checkCurveOptions and checkFitRequest; those of fitSpheres and
// evaluateSpheres.
Expected<CurveResult> fitCurve(const SolidIndex& index, const FitRequest& request,
                               const CurveOptions& options);

// Shadows of the mesh and of the spheres on a ground plane just under the mesh's lowest point
// (a square 3 times the object's largest extent, resolution² pixels), lit by `lights`
// directional lights spread evenly over the upper hemisphere. See shadow.cpp.
struct ShadowResult {
  double sky_rms = 0.0;     // RMS over pixels of the sky-light irradiance difference
  double lights_rms = 0.0;  // RMS over pixels and lights of the per-light irradiance difference
  int pixels = 0, lights = 0;
};
ShadowResult compareShadows(const SolidIndex& index, const std::vector<Sphere>& spheres,
                            int up_axis, int resolution, int lights);

}  // namespace sphereset

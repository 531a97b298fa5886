// Variational sphere-set fitting (paper Sec. 5) with a guaranteed bound of the surface.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sphereset/cover.hpp"
#include "sphereset/options.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

enum class FitInit {
  kFarthestPoint,  // farthest-point seeding over the interior points (default)
  kRandom,         // random interior points, as in the paper
};

enum class FitMethod {
  kVariational,  // the paper's method (Sec. 5), the default
  kKMeans,       // baseline: L2 Lloyd clusters of the same points, minimal ball of each
  kOctree,       // baseline: minimal balls of the points in occupied octree leaves (Hubbard)
};

enum class SphereOptimizer {
  kPowell,    // derivative-free (NLopt BOBYQA, Powell's quadratic model method)
  kGradient,  // exact derivatives of the outside volume (NLopt MMA)
};

struct FitProgress {
  std::string phase;  // "sampling", "clustering", "bounding"; a step's "splitting", "removing"
  int iteration = 0;
  double energy = 0.0;  // Σ outside volume of the spheres
  int spheres = 0;
  double seconds = 0.0;
};

struct FitOptions {
  int num_spheres = 32;
  // Baselines share the points, the bounding step and the outputs; they skip teleports and
  // the refits of the bounding step, which are part of the variational method.
  FitMethod method = FitMethod::kVariational;
  uint64_t seed = 1;
  // Points clustered (interior grid + surface samples). 0 chooses max(5000, 100 n).
  int64_t target_points = 0;
  double interior_share = 0.5;  // fraction of the points on the interior grid
  int max_iterations = 100;     // assignment/update rounds
  double tolerance = 1e-3;  // a round "improves" when it lowers the best energy by this fraction
  int max_failed_teleports = 6;  // stop after this many teleports in a row that did not help
  FitInit init = FitInit::kFarthestPoint;
  SphereOptimizer optimizer = SphereOptimizer::kPowell;
  int optimizer_evaluations = 60;  // per sphere and round
  double padding = 0.0;            // added to every radius at the end (absolute units)
  // After bounding, passes that refit each sphere around what it alone covers (variational
  // method only); they stop when a pass gains less than `tolerance`.
  int shrink_passes = 10;
  // After the shrinking passes, the coverage-aware refinement (variational method only): all
  // spheres move at once to lower the outside volume of a set covering a dense set of points,
  // then are bounded exactly; kept only if it lowers the total outside volume.
  bool refine = true;
  // After the refinement (variational method only): the radii chosen by a covering integer
  // program with the centres fixed (every surface piece and interior point in a sphere, least
  // total outside volume; src/fit/optimal_radii.cpp), kept only if the bounded set has less
  // outside volume; FitResult::radii reports the program's gap. Off by default (it costs about
  // as much as the refinement and the refined radii are already within 0.01 % of its optimum,
  // docs/benchmarks.md); on in the best quality.
  bool optimal_radii = false;
  // Decimation (variational method only): the clustering starts with round(decimation * n)
  // extra spheres and removes the cheapest to remove (upper bound of the outside-volume
  // change when its points join their neighbours) in a few batches, clustering again after
  // each. 0 starts with n spheres, as the paper does.
  double decimation = 0.0;
  // Independent fits (the first with `seed`, the others with seeds derived from it); the one
  // with the lowest final outside volume is returned. The clustering's local minima vary a lot
  // with the seed, so this buys quality for time.
  int restarts = 1;
  // With restarts > 1: instead of keeping the best restart, choose n of all the restarts'
  // spheres by a weighted set cover of the surface pieces and interior points at least total
  // outside volume (src/fit/select.cpp), then bound and shrink them as a fit ends; the chosen
  // set is kept if it beats the best restart.
  bool select_among_restarts = false;
  // The triangles of the input a repaired solid was made from (repair.hpp): the bound covers
  // them too, exactly, after everything else (a last pass of the surface bound over them).
  // Not owned; may be null.
  const Mesh* original = nullptr;
  // Called from the calling thread at each phase and round, and again inside long phases (with
  // the same phase and round) once `progress_interval` seconds have passed since the last call.
  // It may throw to cancel the fit (how the Python module honours Ctrl-C): the exception leaves
  // fitSpheres, nothing is returned.
  std::function<void(const FitProgress&)> progress;
  double progress_interval = 0.25;
};

// teleport: choosing the moves and the decimation's removals (their rounds count as
// assignment and update). bounding is everything after the clustering; bound, shrink, refine
// and radii are its parts: the exact bound's passes (surface with refits, interior, original
// triangles), the shrinking passes, the coverage-aware refinement and the optimal radii.
struct FitTimings {
  double sampling = 0.0, assignment = 0.0, update = 0.0, teleport = 0.0, bounding = 0.0,
         total = 0.0;
  double bound = 0.0, shrink = 0.0, refine = 0.0, radii = 0.0;
};

// The optimal-radii program (FitOptions::optimal_radii): with the fit's centres fixed, the radii
// of least total outside volume that keep every unit (surface pieces, split until one sphere
// holds each, and interior points) in a sphere. Its figures are those of the program as posed
// (units, candidate spheres, quantised radius levels), before the exact bound of its solution.
struct RadiiCertificate {
  double objective = 0.0;    // Σ outside volume of the program's best solution
  double lower_bound = 0.0;  // its proven lower bound (branch and bound)
  double gap =
      -1.0;  // (objective - lower_bound) / objective; 0: optimal; -1: not run (or too large)
  double start = 0.0;  // Σ outside volume of the set the program started from
  int64_t units = 0, rows = 0;
  bool kept = false;  // its bounded solution had less outside volume and replaced the set
};

struct FitResult {
  std::vector<Sphere> spheres;
  std::vector<double> outside_volume;  // per sphere, exact, after bounding and padding
  std::vector<double> energy_history;  // Σ outside volume after each round
  double energy_before_bounding = 0.0;
  double energy = 0.0;  // final Σ outside volume
  int iterations = 0;
  int teleports = 0, teleports_accepted = 0;
  bool converged = false;  // stopped because neither rounds nor teleports improved
  int64_t points = 0, interior_points = 0;
  int64_t sov_queries = 0;              // outside-volume evaluations in point assignment
  int64_t sov_queries_culled = 0;       // assignment candidates settled by a lower bound instead
  int64_t optimizer_queries = 0;        // outside-volume evaluations in sphere updates
  int64_t bounding_enlarged = 0;        // spheres enlarged by the last bounding pass
  int64_t bounding_pieces = 0;          // triangle pieces that made a sphere grow (all passes)
  int64_t bounding_queries = 0;         // outside-volume evaluations of the bounding step
  int64_t bounding_interior_cells = 0;  // interior cubes that made a sphere grow
  int shrink_passes = 0;                // shrinking passes kept
  int64_t refine_points = 0;  // points kept covered by the refinement (0: not run or not kept)
  RadiiCertificate radii;
  int decimated = 0;       // spheres removed by the decimation
  int idle_teleports = 0;  // spheres that covered nothing alone, moved to split another
  int restart = 0;         // which restart won (0: the one with options.seed)
  FitTimings seconds;
};

// Quality presets: how much work a fit does, as `sphereset fit --quality` names them. The CLI,
// the batch and the Python module all take their options from fitPreset / fitOptionsFor.
enum class FitQuality {
  kFast,     // 0.25 of the default points, 20 rounds, 20 optimiser evaluations, 1 failed teleport
  kDefault,  // max(5000, 100 n) points, 100 rounds, 60 evaluations, 6 failed teleports
  kBest,     // the default's, with 4 restarts (their spheres selected among) and decimation 0.5
};

// "fast", "default", "best".
const char* fitQualityName(FitQuality quality);

// The quality named `name` (as fitQualityName spells it); kInvalidArgument naming the text and
// the valid names for anything else.
Expected<FitQuality> fitQualityFromName(const std::string& name);

// The options of a quality preset for `num_spheres` spheres: target_points (the preset's factor
// times max(5000, 100 n)), max_iterations, optimizer_evaluations, max_failed_teleports, restarts
// and decimation; every other field keeps its default. Callers override what their user gave
// explicitly afterwards (fitOptionsFor does).
FitOptions fitPreset(int num_spheres, FitQuality quality = FitQuality::kDefault);

// A fit as a user asks for one, i.e. the options of `sphereset fit`: a quality preset and the
// options given explicitly, which override the preset's. An unset optional (or points = 0)
// keeps the preset's value.
struct FitRequest {
  int num_spheres = 32;
  bool count_given = false;  // n was given (setFitRequestOption "n"): no tolerance may choose it
  FitQuality quality = FitQuality::kDefault;
  uint64_t seed = 1;
  double padding = 0.0;              // absolute units, added to every radius
  int64_t points = 0;                // points clustered; 0: the preset's
  std::optional<int> iterations;     // assignment/update rounds (FitOptions::max_iterations)
  std::optional<int> restarts;       // FitOptions::restarts
  std::optional<double> decimation;  // FitOptions::decimation
  SphereOptimizer optimizer = SphereOptimizer::kPowell;
  FitInit init = FitInit::kFarthestPoint;
  FitMethod method = FitMethod::kVariational;
};

// The options of a FitRequest, one row each (options.hpp), named as the Python keywords and the
// batch manifest's columns: n, quality, seed, points, iterations, restarts, decimation,
// padding, optimizer, init, method. The command line's flags, the manifest's columns and the
// Python keywords are all made from this table.
std::span<const OptionSpec> fitRequestOptions();

// Sets the option `name` of `request` from the text a user gave (parseOption with its row).
// kInvalidArgument: an unknown name (the message lists the names) or a bad value.
Status setFitRequestOption(FitRequest* request, const std::string& name, const std::string& text);

// Every number of `request` within the table's limits (for requests built in code), with the
// message setFitRequestOption gives for the same value.
Status checkFitRequest(const FitRequest& request);

// fitPreset(request.num_spheres, request.quality) with the request's explicit values applied:
// the options `sphereset fit` runs with for the same command line (no progress callback, no
// original triangles).
FitOptions fitOptionsFor(const FitRequest& request);

// Names of the enumerations as the command line spells them ("fps"/"random",
// "powell"/"gradient", "variational"/"kmeans"/"octree"), and back (kInvalidArgument naming the
// text and the valid names).
const char* fitInitName(FitInit init);
const char* sphereOptimizerName(SphereOptimizer optimizer);
const char* fitMethodName(FitMethod method);
Expected<FitInit> fitInitFromName(const std::string& name);
Expected<SphereOptimizer> sphereOptimizerFromName(const std::string& name);
Expected<FitMethod> fitMethodFromName(const std::string& name);

// Growing the radii of a given set minimally until it covers the solid: the fit's guaranteed
// bound (surface pieces, then interior cells, then the original triangles) started from the set
// as it is, centres fixed. `sphereset animate --rebound` and the view's bound use it.
struct BoundOptions {
  // Surface pieces are split down to about this length (absolute). 0: half the spacing of a
  // default fit's surface samples for this many spheres (kBoundSamplesPerSphere, at least
  // kBoundMinSamples samples over the surface).
  double min_edge = 0.0;
  // Octree depth of the interior passes, as EvalOptions::interior_max_depth.
  int interior_max_depth = kInteriorSplitDepth;
  // The triangles of the input a repaired solid was made from (repair.hpp), covered too; not
  // owned, may be null.
  const Mesh* original = nullptr;
};
inline constexpr double kBoundSamplesPerSphere = 50.0;
inline constexpr double kBoundMinSamples = 2500.0;
// Interior passes at most (each grows radii for the cells still uncovered).
inline constexpr int kBoundInteriorPasses = 4;

// The set with radii grown (never shrunk) so that the surface, the interior cells and the
// original triangles are covered. Errors (kInvalidArgument): no spheres, more than
// limits::kMaxSpheres, a sphere with a NaN, infinite or negative value, options out of range.
Expected<std::vector<Sphere>> boundSpheres(const SolidIndex& index, std::vector<Sphere> spheres,
                                           const BoundOptions& options = {});

// Fits options.num_spheres spheres to the closed solid behind `index`. Errors:
// kInvalidArgument (n < 1, n larger than the points, bad options), kNotSolid (zero volume).
Expected<FitResult> fitSpheres(const SolidIndex& index, const FitOptions& options);

// Progressive fitting (beyond the paper; src/fit/progressive.cpp): the fits of one solid at
// increasing sphere counts, each clustering started from a smaller count's: four doubling counts
// cost about 1.7 times one fit at the largest, every count from 1 to 64 by fit() about 27 times
// (each count is a warm clustering and a whole ending); step() adds or removes one sphere of the
// last count for under a fiftieth of a fit (docs/benchmarks.md, "Progressive fitting").
// A class because each fit reuses the points
// and the clusterings of the earlier ones; not for use from two threads at once.
// How a progressive run chooses where each count starts from.
struct ProgressiveOptions {
  // A count starts from the largest count already clustered at most count / start_ratio (1: the
  // largest below it), or from seeds when there is none. Doubling (2, the default) splits most
  // clusters, which keeps a chain of many close counts from staying in one minimum (spot.obj
  // through 1, 2, 3, 4, 6, ... 64: E_r 0.83 at 64 with 1, 0.17 with 2); 1 suits a few counts
  // next to each other started from one settled clustering (the robot's candidates).
  int start_ratio = 2;
  // Whether a count that start()'s warm_from clustered is taken as it is (only ended with this
  // run's options) or clustered by this run, started as start_ratio says from a smaller count:
  // a quick run's clustering taken as it is ends as a quick fit (docs/benchmarks.md, "The robot
  // budget with progressive curves").
  bool adopt = true;
  // Whether the largest count (start()'s options.num_spheres) is clustered from seeds, as
  // fitSpheres clusters it, rather than from a smaller count: its fit is then fitSpheres's own
  // (the same spheres for the same options), for the cost of a clustering from seeds. A curve's
  // last count (fitCurve) is so fitted: warm-started, the largest counts end about 5 % above an
  // independent fit in outside volume (docs/benchmarks.md, "Progressive fitting").
  bool top_from_seeds = false;
  // With top_from_seeds, and more than one thread allowed (the calling thread's arena and
  // tbb::global_control): the largest count's fit starts at once on a thread of its own (one
  // thread more than the limit; its task arena as wide as the caller's), beside the run's other
  // fits, and fit() at that count waits for it. The same spheres; sooner where the other fits
  // leave cores idle (a curve: fitCurve). options.progress is called only on the calling
  // thread: for that fit, while fit() waits for it (with its latest progress, and may throw to
  // cancel). Its FitResult::seconds are its own, made beside the others. A run destroyed before
  // taking it stops it within about options.progress_interval.
  bool top_alongside = false;
  // Counts clustered from seeds (on the run's points) whatever was clustered below them, so
  // that the warm starts begin there: a chain warm-started from one sphere ends further from
  // independent fits than one from 8 spheres (a curve's E_r at 32 over independent fits, 12
  // shared meshes, seeds 1 and 2: 1.038 against 1.005). fitCurve takes 1, 2 and 8 (its 4 starts
  // from 2: docs/benchmarks.md, "Progressive fitting").
  std::vector<int> seeded = {};
  // At most this many rounds (or the options' fewer) for a count below half the largest that
  // is clustered warm from a smaller one; 0: as the larger warm counts (30 rounds). fitCurve
  // takes 20 (its 4 and 16): only its 32 feeds the counts up to 64, and 20 rounds at 16 moved E_r
  // at 16 from 1.006 to 1.015 and 0.921 to 0.954 times independent fits (12 shared meshes,
  // seeds 1 and 3), at 32 from 0.996 to 0.989 and 1.016 to 0.990; 20 at 32 too: 1.056 and
  // 1.041 at 32 (docs/benchmarks.md, "Progressive fitting").
  int warm_rounds_below_half = 0;
};

class ProgressiveFit {
 public:
  // Whether start() takes these options: the variational method, one restart, no decimation.
  static bool allows(const FitOptions& options);
  // A run for counts up to options.num_spheres; samples the points of a fit at that count.
  // Errors (kInvalidArgument for a start_ratio below 1): those of fitSpheres for these options,
  // and kInvalidArgument for options it cannot honour: a method other than the variational
  // one, restarts > 1 or decimation > 0 (each count is one clustering, warm-started).
  // With `warm_from` (a run on the same solid, e.g. a quicker one), its clusterings are this
  // run's as if it had made them (their clusters are positions, so they carry over to this
  // run's points): a count it clustered is only ended (bound, refinement...) with this run's
  // options (ProgressiveOptions::adopt; else clustered again), and larger counts start from
  // them; its fits are not taken. The run refers to `index` and options.original: they must
  // outlive it.
  static Expected<ProgressiveFit> start(const SolidIndex& index, const FitOptions& options,
                                        const ProgressiveFit* warm_from = nullptr,
                                        const ProgressiveOptions& progressive = {});
  // A run moved from holds nothing: it may only be assigned to or destroyed (the other members
  // assert that it holds a run).
  ProgressiveFit(ProgressiveFit&&) noexcept;
  ProgressiveFit& operator=(ProgressiveFit&&) noexcept;
  ~ProgressiveFit();

  // The fit at `count` spheres (1 to maxCount()), as fitSpheres ends one (bound, shrinking,
  // refinement, padding). Its clustering starts from a clustering of a smaller count
  // (ProgressiveOptions::start_ratio): the clusters whose split in two lowers the outside volume
  // most are split (2-means, both halves refitted) until there are `count`, then the rounds and
  // teleports of the clustering run again (fewer of them than a fit from seeds gets). A count
  // fitted before returns its fit again (split_first and seconds those of its first call) and is
  // the run's last fit again for step(); with
  // no clustering to start from, the clustering starts from seeds as fitSpheres does (the same
  // spheres when the run's points are that count's: up to 50 spheres by default). Every count
  // clusters the points of a fit at options.num_spheres, sampled by start(). The same calls in the
  // same order give the same spheres for any thread count. FitResult::seconds is this call's.
  // Errors: kInvalidArgument for a count out of range or clusters that cannot all be placed.
  // options.progress is called as fitSpheres calls it (FitProgress::spheres = count), and may
  // throw to cancel.
  // With `split_first` (one value per sphere of the fit startCount(count) names), the first
  // splits go to the clusters of the largest values instead, e.g. each sphere's certified
  // protrusion (evaluate.hpp) to lower the set's; kInvalidArgument when its size does not match
  // or the fit would not start from a smaller count.
  Expected<FitResult> fit(int count, std::span<const double> split_first = {});
  // The fit at `count` made from this run's last step or last fit at count - 1 or count + 1 by one
  // local change (src/fit/local_split.cpp). Up, the sphere whose split in two lowers the outside
  // volume most is replaced by the two halves; down, the sphere whose removal adds least is
  // removed (the last sphere takes its index). Only the solid within the changed sphere's box
  // is bounded again; no rounds, shrinking or refinement. Far cheaper than fit(count), usually
  // looser (a set as bounded, with more outside volume: docs/benchmarks.md, "Progressive
  // fitting"). Each call steps from the run's state (a count stepped again may differ: up from
  // below, down from above). The FitResult holds the set, its outside volumes and energy, the
  // local bound's counters and seconds (bound: the local bound; teleport: measuring the splits
  // or removals); energy_before_bounding is the energy of the count it came from, iterations 0,
  // converged false. Progress and cancelling as fit()'s. Errors
  // (kInvalidArgument): count out of 1 to maxCount(), neither count - 1 nor count + 1 the last
  // count this run fitted or stepped, no sphere that can be split or removed.
  Expected<FitResult> step(int count);
  // The count fit(count) starts from: `count` itself if clustered (by warm_from only when
  // ProgressiveOptions::adopt), else 0 (from seeds) for the largest count with
  // ProgressiveOptions::top_from_seeds and for the counts in ProgressiveOptions::seeded, else the
  // largest smaller count clustered within ProgressiveOptions::start_ratio, or 0.
  int startCount(int count) const;
  int maxCount() const;
  // Frees what the run keeps only to go faster (the interior cubes' geometry its bounds met,
  // several MB on a fine mesh); later fits and steps give the same sets and keep it anew. For a
  // caller that holds many runs and is done with one for now (a robot's links).
  void forgetAnswers();

 private:
  struct Impl;
  explicit ProgressiveFit(std::unique_ptr<Impl> impl);
  // The run held, asserted (a moved-from object holds none).
  const Impl& impl() const;
  Impl& impl();
  std::unique_ptr<Impl> impl_;
};

}  // namespace sphereset

// Sphere hierarchies (paper Sec. 6): a fitted sphere set as leaves, levels above built bottom-up
// by Lloyd clustering of the child spheres, every parent enclosing its children entirely.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/options.hpp"
#include "sphereset/result_fields.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

enum class TreeParents {
  kMinimal,        // the minimal enclosing ball of the children's spheres
  kOutsideVolume,  // least outside volume of the solid among balls enclosing the children
};

struct TreeOptions {
  int branching = 8;  // B: children per node at most
  int depth = 2;      // D: levels below the root
  TreeParents parents = TreeParents::kMinimal;
  int max_iterations = 20;  // Lloyd rounds per level
  uint64_t seed = 1;        // seeds the clustering's starting centres
  // kOutsideVolume only: optimiser evaluations per parent.
  int optimizer_evaluations = 80;
};

// The layout options as one table (options.hpp): branching (2 to 1024), depth (1 to 26) and
// parents (minimal or outside). The command line's flags and the Python keywords are made from
// it. setTreeOption sets a row from the text a user typed; checkTreeOptions checks a struct
// against the rows and the tree's slot limit (SphereTree::kMaxSlots), with the same messages
// ("branching '1': expected an integer from 2 to 1024"). Every function below checks its
// options with it.
std::span<const OptionSpec> treeOptionTable();
Status setTreeOption(TreeOptions* o, const std::string& name, const std::string& text);
Status checkTreeOptions(const TreeOptions& o);
// "minimal" or "outside", the table's names.
const char* treeParentsName(TreeParents p);

struct TreeLevelStats {
  int level = 0;
  int64_t nodes = 0;            // used nodes
  int iterations = 0;           // Lloyd rounds run (0 for the leaves)
  bool converged = false;       // assignment stopped changing before the cap
  double outside_volume = 0.0;  // Σ SOV of the level (only when built with a SolidIndex)
};

// A level's statistics as a field list (result_fields.hpp), for `sphereset tree --json` and
// Python's tree results: level, spheres, rounds, convergence, outside volume and E_r against
// `volume` (0 when no solid was given).
std::vector<ResultField> treeLevelFields(const TreeLevelStats& level, double volume);

struct TreeResult {
  SphereTree tree;
  std::vector<TreeLevelStats> levels;  // root first
  double seconds = 0.0;
};

// Builds the levels above `leaves` (at most B^D of them; kInvalidArgument otherwise). `index`
// is needed for kOutsideVolume parents and for the per-level outside volumes; it may be null
// for kMinimal parents. Deterministic for given options, whatever the thread count.
Expected<TreeResult> buildSphereTree(std::span<const Sphere> leaves, const TreeOptions& options,
                                     const SolidIndex* index = nullptr);

// Fit and hierarchy in one call: the leaves are the variational fit with fit.num_spheres
// spheres (B^D when fit.num_spheres is 0).
struct TreeFitResult {
  FitResult fit;
  TreeResult tree;
};
Expected<TreeFitResult> fitSphereTree(const SolidIndex& index, FitOptions fit,
                                      const TreeOptions& options);

// Leaves of a fitted tree when no count is given: branching^depth, at most this many.
inline constexpr int64_t kMaxDefaultTreeLeaves = int64_t{1} << 16;

// The fit request of a tree's leaves, as `sphereset tree` and Python's tree make it: `request`
// with num_spheres = branching^depth when it is 0 (the preset's points then follow the leaves),
// checked (checkFitRequest). kInvalidArgument for tree options out of range, or a default
// count above kMaxDefaultTreeLeaves ("give the number of spheres").
Expected<FitRequest> treeFitRequest(FitRequest request, const TreeOptions& options);

}  // namespace sphereset

// Sphere hierarchies (paper Sec. 6): a fitted sphere set as leaves, levels above built bottom-up
// by Lloyd clustering of the child spheres, every parent enclosing its children entirely.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// The smallest ball that contains every given ball entirely (exact up to rounding: a
// combinatorial pivoting method on support sets of at most four balls, no generic optimiser).
// Radius grows by a few ulps so that containment holds in floating point. Empty input gives
// a zero ball at the origin.
Sphere minimalEnclosingBall(std::span<const Sphere> balls);

// A complete B-ary tree stored flat in Bradshaw's layout: level l holds B^l slots starting at
// (B^l - 1) / (B - 1); the children of node N are N·B + 1 + i, i < B. Unused slots have a
// negative radius. `depth` counts levels below the root: depth + 1 levels, at most B^depth
// leaves, all on the last level.
struct SphereTree {
  int branching = 8;
  int depth = 0;
  std::vector<Sphere> nodes;

  // Largest layout accepted (slots over all levels), against absurd branching and depth.
  static constexpr int64_t kMaxSlots = int64_t{1} << 26;
  // Slots of a tree of this branching and depth, or -1 when above kMaxSlots.
  static int64_t slotCount(int branching, int depth);

  int levels() const { return depth + 1; }
  int64_t levelBegin(int level) const;  // first slot of a level
  int64_t levelSize(int level) const;   // B^level
  bool used(int64_t node) const { return nodes[node].radius >= 0.0; }
  int64_t child(int64_t node, int i) const { return node * branching + 1 + i; }
  // The used spheres of one level, in slot order.
  std::vector<Sphere> level(int level) const;
  std::vector<Sphere> leaves() const { return level(depth); }
};

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

struct TreeLevelStats {
  int level = 0;
  int64_t nodes = 0;            // used nodes
  int iterations = 0;           // Lloyd rounds run (0 for the leaves)
  bool converged = false;       // assignment stopped changing before the cap
  double outside_volume = 0.0;  // Σ SOV of the level (only when built with a SolidIndex)
};

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

// Tree files: Bradshaw's .sph ("levels branching" then one "x y z r error" line per slot) or
// JSON with explicit parent/child links per node. Writes are atomic.
Status writeSphereTree(const std::string& path, const SphereTree& tree,
                       const SphereFileMeta& meta = {});
std::string formatSphereTree(SphereFormat format, const SphereTree& tree,
                             const SphereFileMeta& meta = {});
// Reads a .sph tree, or a JSON file written by writeSphereTree. A plain sphere set (any format
// readSpheres accepts) is returned as a one-level tree holding just those spheres.
Expected<SphereTree> readSphereTree(const std::string& path);

// Checks the structural invariants: slot count, every used node's children inside it
// entirely (up to `tolerance`, a length), no used child under an unused parent. The message
// names the first offending node.
Status checkSphereTree(const SphereTree& tree, double tolerance = 0.0);

}  // namespace sphereset

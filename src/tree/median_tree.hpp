// Private: a sphere tree over a set built fast, by median splits instead of the Lloyd clustering
// of buildSphereTree (which is quadratic in bad cases and too slow for a point cloud of a million
// points), with the position in the set of each leaf slot. queryTree and the robot's obstacle
// trees are made here.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sphereset/sphere.hpp"
#include "sphereset/sphere_tree.hpp"

namespace sphereset::detail {

struct IndexedTree {
  SphereTree tree;
  std::vector<int64_t> leaf_index;  // slot -> position in the set, -1 for other slots
};

// The depth of a median tree of `branching` over `count` spheres: the least >= 1 with
// branching^depth >= count.
int medianTreeDepth(int64_t count, int branching);

// Branching `branching` (>= 2), depth medianTreeDepth; the set must be non-empty, fit
// (SphereTree::kMaxSlots) and pass checkSphere. O(n log n) whatever the set (identical spheres
// included). Deterministic.
IndexedTree medianTree(std::span<const Sphere> spheres, int branching = 8);

}  // namespace sphereset::detail

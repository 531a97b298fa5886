// Private: a sphere tree over a large set built fast, by median splits instead of the Lloyd
// clustering of buildSphereTree (too slow for a point cloud of a million points), with the
// position in the set of each leaf slot.
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

// Branching 8, depth the least >= 1 with 8^depth >= the set's size; the set must be non-empty
// and fit (SphereTree::kMaxSlots). Deterministic.
IndexedTree medianTree(std::span<const Sphere> spheres);

}  // namespace sphereset::detail

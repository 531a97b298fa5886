// Sphere hierarchies as plain data: a complete B-ary tree of spheres in Bradshaw's flat layout,
// its invariants, and the minimal enclosing ball that makes parents. Building a tree from a
// mesh is in tree.hpp; reading and writing tree files in sphere_io.hpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// A complete B-ary tree stored flat in Bradshaw's layout: level l holds B^l slots starting at
// (B^l - 1) / (B - 1); the children of node N are N·B + 1 + i, i < B. Unused slots have a
// negative radius. `depth` counts levels below the root: depth + 1 levels, at most B^depth
// leaves, all on the last level.
struct SphereTree {
  int branching = 8;
  int depth = 0;
  std::vector<Sphere> nodes;

  // Largest layout accepted (slots over all levels, 128 MiB of spheres), against absurd
  // branching and depth: a 90-byte tree file must not make a reader allocate gigabytes.
  static constexpr int64_t kMaxSlots = int64_t{1} << 22;
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

// Checks the structural invariants: slot count, every used node's children inside it
// entirely (up to `tolerance`, a length), no used child under an unused parent. The message
// names the first offending node.
Status checkSphereTree(const SphereTree& tree, double tolerance = 0.0);

// A tree from a file's or an array's slots (unused slots have a negative radius): checks the
// layout, that used nodes are finite, and the invariants (checkSphereTree with `tolerance`;
// infinity checks the structure only), all as kInvalidData naming the node. A used node without
// used children above the last level is a leaf in Bradshaw's files; it is copied down to the
// last level, where queries, exports and leaves() find every leaf.
Expected<SphereTree> makeSphereTree(int branching, int depth, std::vector<Sphere> nodes,
                                    double tolerance = 0.0);

}  // namespace sphereset

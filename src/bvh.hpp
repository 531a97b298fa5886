// Private: bounding-volume hierarchy over triangles, stored with the triangle data it needs in
// traversal order so that queries touch contiguous memory.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// One cache line per node: the box, the children or triangles, and the node's patch.
struct BvhNode {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  int32_t first = 0;   // leaf: first triangle; inner: index of left child (right = first + 1)
  int32_t count = 0;   // leaf: number of triangles; inner: 0
  int32_t patch = -1;  // index into Bvh::patches, or -1
  int32_t unused = 0;
  bool leaf() const { return count > 0; }
};

// Sums over a node's triangles that make a ball containing the whole node cheap to
// evaluate (see outside_volume.cpp). Only for nodes with at least kMinPatch triangles.
struct NodePatch {
  Vec3 q = Vec3::Zero();          // reference point: the node's box centre
  double det_q = 0.0;             // Σ det(a - q, b - q, c - q)
  Vec3 cross = Vec3::Zero();      // Σ (b - a) × (c - a)  (twice the vector area)
  int32_t loop_begin = 0, loop_end = 0;  // boundary loops in Bvh::patch_loops
  int32_t edges = 0;                      // boundary edges in all loops
};

// One triangle as the kernels need it.
struct TriRecord {
  Vec3 a, b, c;
  Vec3 n;       // outward unit normal
  double area;  // full triangle area
};

struct Bvh {
  std::vector<BvhNode> nodes;
  std::vector<TriRecord> tris;   // in leaf order
  std::vector<int32_t> original;  // original triangle index of tris[i]
  std::vector<NodePatch> patches;  // referenced by BvhNode::patch
  // Boundary of node patches (the edges of a node's triangles whose neighbour across lies
  // outside the node), chained into closed loops: patch_loops[k] = [first, end) in
  // patch_vertices, whose consecutive entries are the directed edges.
  std::vector<std::array<int32_t, 2>> patch_loops;
  std::vector<Vec3> patch_vertices;
  static constexpr int32_t kMinPatch = 32;

  void build(const Mesh& mesh, int leaf_size = 4);

 private:
  // ranges[i]: the triangles below node i are tris[first, first + count) (build time only).
  void buildPatches(const Mesh& mesh, const std::vector<std::array<int32_t, 2>>& ranges);

 public:

  // Visits every leaf triangle whose node box passes `overlaps(min, max)`; `visit(i)` gets the
  // index into tris. Iterative with a fixed stack (depth is bounded by the build).
  template <class Overlaps, class Visit>
  void traverse(Overlaps&& overlaps, Visit&& visit) const {
    if (nodes.empty()) return;
    int32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const BvhNode& node = nodes[stack[--top]];
      if (!overlaps(node.min, node.max)) continue;
      if (node.leaf()) {
        for (int32_t i = node.first; i < node.first + node.count; ++i) visit(i);
      } else {
        stack[top++] = node.first + 1;
        stack[top++] = node.first;
      }
    }
  }
};

inline double boxPointSquaredDistance(const Vec3& mn, const Vec3& mx, const Vec3& p) {
  const Vec3 d = (mn - p).cwiseMax(p - mx).cwiseMax(0.0);
  return d.squaredNorm();
}

}  // namespace sphereset::detail

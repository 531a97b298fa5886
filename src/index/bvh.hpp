// Private: bounding-volume hierarchy over triangles, stored with the triangle data it needs in
// traversal order so that queries touch contiguous memory.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// 32 bytes per node, two siblings per cache line. The box is stored in float, rounded
// outwards, so it still contains the node's triangles; every test on it is conservative.
struct alignas(32) BvhNode {
  std::array<float, 3> lo{}, hi{};
  int32_t first = 0;  // leaf: first triangle; inner: index of left child (right = first + 1)
  int32_t count = 0;  // leaf: number of triangles; inner: 0
  bool leaf() const { return count > 0; }
  Vec3 min() const { return Vec3(lo[0], lo[1], lo[2]); }
  Vec3 max() const { return Vec3(hi[0], hi[1], hi[2]); }
  void setBox(const Vec3& mn, const Vec3& mx) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = static_cast<float>(mn[k]);
      if (lo[k] > mn[k]) lo[k] = std::nextafter(lo[k], -std::numeric_limits<float>::infinity());
      hi[k] = static_cast<float>(mx[k]);
      if (hi[k] < mx[k]) hi[k] = std::nextafter(hi[k], std::numeric_limits<float>::infinity());
    }
  }
};

// Allocates node arrays on cache-line boundaries so that sibling pairs share a line.
template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  CacheLineAllocator(const CacheLineAllocator<U>&) {}  // NOLINT: allocator rebinding
  T* allocate(size_t n) {
    return static_cast<T*>(::operator new (n * sizeof(T), std::align_val_t{64}));
  }
  void deallocate(T* p, size_t) { ::operator delete (p, std::align_val_t{64}); }
  bool operator==(const CacheLineAllocator&) const { return true; }
};

// Sums over a node's triangles that make a node lying wholly inside a ball cheap: with them
// Σ h_t A_t and Σ A_t n_t over the node are linear in the ball's centre.
struct NodeSums {
  Vec3 q = Vec3::Zero();      // reference point: the node's box centre
  double det_q = 0.0;         // Σ det(a - q, b - q, c - q)
  Vec3 cross = Vec3::Zero();  // Σ (b - a) × (c - a)  (twice the vector area)
};

// One triangle as the kernels need it.
struct TriRecord {
  Vec3 a, b, c;
  Vec3 n;       // outward unit normal
  double area;  // full triangle area
  // Position in Bvh::tris of the neighbour across edges (a, b), (b, c), (c, a); -1 where the
  // edge is not shared by exactly one oppositely oriented triangle.
  std::array<int32_t, 3> nbr{-1, -1, -1};
};

struct Bvh {
  // Node 0 is the root and node 1 unused, so that every sibling pair starts at an even index.
  std::vector<BvhNode, CacheLineAllocator<BvhNode>> nodes;
  std::vector<NodeSums> sums;     // per node
  std::vector<TriRecord> tris;    // in leaf order
  std::vector<int32_t> original;  // original triangle index of tris[i]
  bool closed = false;            // every triangle has its three neighbours

  void build(const Mesh& mesh, int leaf_size = 4);

 private:
  void buildNeighbours(const Mesh& mesh);
  void buildSums();

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
      if (!overlaps(node.min(), node.max())) continue;
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

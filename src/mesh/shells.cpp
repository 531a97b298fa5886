// Shells of a triangle mesh: edge-connected components, each diagnosed as a solid on its own
// (diagnoseMesh on its submesh), which of them cross each other (from findSelfIntersections),
// and how the closed ones nest. Containment is decided by the generalised winding number
// (Jacobson et al. 2013, "Robust inside-outside segmentation using generalized winding
// numbers"): the sum of the signed solid angles of the container's triangles, over 4π, at a
// point of the contained shell; |w| > 1/2 means inside whichever way the container faces.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>

#include "index/winding.hpp"
#include "sphereset/mesh_defects.hpp"
#include "sphereset/solid_index.hpp"
#include "util/union_find.hpp"

namespace sphereset {
namespace {

// Containers with more triangles than this are queried through a SolidIndex (ray crossings
// over a BVH) rather than by summing every triangle's solid angle.
constexpr size_t kDirectWindingTriangles = 512;
// |winding number| above this means inside.
constexpr double kInsideWinding = 0.5;

using detail::UnionFind;

// Edge-connected components, numbered in the order of their smallest triangle.
std::vector<std::vector<int32_t>> edgeComponents(const Mesh& mesh) {
  const int32_t nt = static_cast<int32_t>(mesh.triangles.size());
  struct Edge {
    int32_t lo, hi, tri;
    bool operator<(const Edge& o) const {
      return lo != o.lo ? lo < o.lo : (hi != o.hi ? hi < o.hi : tri < o.tri);
    }
  };
  std::vector<Edge> edges;
  edges.reserve(3 * static_cast<size_t>(nt));
  for (int32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), t});
    }
  std::sort(edges.begin(), edges.end());
  UnionFind uf(nt);
  for (size_t i = 1; i < edges.size(); ++i)
    if (edges[i].lo == edges[i - 1].lo && edges[i].hi == edges[i - 1].hi)
      uf.unite(edges[i - 1].tri, edges[i].tri);
  std::vector<int32_t> id(nt, -1);
  std::vector<std::vector<int32_t>> comps;
  for (int32_t t = 0; t < nt; ++t) {
    const int32_t root = uf.find(t);  // the smallest triangle of the component
    if (id[root] < 0) {
      id[root] = static_cast<int32_t>(comps.size());
      comps.emplace_back();
    }
    comps[id[root]].push_back(t);
  }
  return comps;
}

bool boxContains(const Aabb& outer, const Aabb& inner) {
  return (outer.min.array() <= inner.min.array()).all() &&
         (inner.max.array() <= outer.max.array()).all();
}

// A small median-split tree over boxes answering "which boxes contain this box".
class BoxTree {
 public:
  explicit BoxTree(std::vector<std::pair<Aabb, int32_t>> items) : items_(std::move(items)) {
    if (items_.empty()) return;
    nodes_.push_back({});
    build(0, 0, static_cast<int32_t>(items_.size()));
  }
  template <class Visit>
  void containing(const Aabb& query, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::vector<int32_t> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!boxContains(node.box, query)) continue;
      if (node.left < 0) {
        for (int32_t i = node.begin; i < node.end; ++i)
          if (boxContains(items_[i].first, query)) visit(items_[i].second);
      } else {
        stack.push_back(node.left);
        stack.push_back(node.left + 1);
      }
    }
  }

 private:
  struct Node {
    Aabb box;
    int32_t begin = 0, end = 0, left = -1;
  };
  static constexpr int32_t kLeafSize = 4;
  void build(int32_t index, int32_t begin, int32_t end) {
    Aabb box, centres;
    for (int32_t i = begin; i < end; ++i) {
      box.extend(items_[i].first);
      centres.extend(items_[i].first.center());
    }
    nodes_[index].box = box;
    nodes_[index].begin = begin;
    nodes_[index].end = end;
    int axis = 0;
    (centres.max - centres.min).maxCoeff(&axis);
    if (end - begin <= kLeafSize || centres.max[axis] <= centres.min[axis]) return;
    const int32_t mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                     [axis](const auto& x, const auto& y) {
                       const double cx = x.first.center()[axis], cy = y.first.center()[axis];
                       return cx != cy ? cx < cy : x.second < y.second;
                     });
    const int32_t left = static_cast<int32_t>(nodes_.size());
    nodes_.resize(nodes_.size() + 2);
    nodes_[index].left = left;
    build(left, begin, mid);
    build(left + 1, mid, end);
  }
  std::vector<std::pair<Aabb, int32_t>> items_;
  std::vector<Node> nodes_;
};

}  // namespace

Mesh submesh(const Mesh& mesh, const std::vector<int32_t>& triangles) {
  std::vector<int32_t> used;
  used.reserve(3 * triangles.size());
  for (int32_t t : triangles)
    for (int32_t v : mesh.triangles[t]) used.push_back(v);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  Mesh out;
  out.vertices.reserve(used.size());
  for (int32_t v : used) out.vertices.push_back(mesh.vertices[v]);
  out.triangles.reserve(triangles.size());
  auto remap = [&](int32_t v) {
    return static_cast<int32_t>(std::lower_bound(used.begin(), used.end(), v) - used.begin());
  };
  for (int32_t t : triangles) {
    const Triangle& tri = mesh.triangles[t];
    out.triangles.push_back({remap(tri[0]), remap(tri[1]), remap(tri[2])});
  }
  return out;
}

ShellAnalysis analyzeShells(const Mesh& mesh, const SelfIntersectionOptions& options) {
  ShellAnalysis out;
  const auto comps = edgeComponents(mesh);
  const int32_t ns = static_cast<int32_t>(comps.size());
  std::vector<int32_t> shell_of(mesh.triangles.size(), -1);
  std::vector<Mesh> meshes(ns);
  out.shells.resize(ns);
  for (int32_t s = 0; s < ns; ++s) {
    Shell& shell = out.shells[s];
    shell.triangles = comps[s];
    for (int32_t t : shell.triangles) shell_of[t] = s;
    meshes[s] = submesh(mesh, shell.triangles);
    const MeshDiagnosis d = diagnoseMesh(meshes[s]);
    shell.closed = d.closed;
    shell.manifold = d.manifold;
    shell.oriented = d.oriented;
    shell.volume = d.volume;
    shell.bbox = d.bbox;
  }

  out.intersections = findSelfIntersections(mesh, options);
  for (const auto& [a, b] : out.intersections.pairs) {
    const int32_t sa = shell_of[a], sb = shell_of[b];
    if (sa == sb) {
      out.shells[sa].self_intersecting = true;
    } else {
      out.intersecting.push_back({std::min(sa, sb), std::max(sa, sb)});
    }
  }
  std::sort(out.intersecting.begin(), out.intersecting.end());
  out.intersecting.erase(std::unique(out.intersecting.begin(), out.intersecting.end()),
                         out.intersecting.end());
  auto crossing = [&](int32_t a, int32_t b) {
    const std::array<int32_t, 2> key{std::min(a, b), std::max(a, b)};
    return std::binary_search(out.intersecting.begin(), out.intersecting.end(), key);
  };

  // Nesting among closed shells. The test point of a shell is the centroid of its largest
  // triangle: shells that do not cross may still touch at vertices or edges, never there.
  std::vector<std::pair<Aabb, int32_t>> closed_boxes;
  for (int32_t s = 0; s < ns; ++s)
    if (out.shells[s].closed) closed_boxes.emplace_back(out.shells[s].bbox, s);
  const BoxTree tree(closed_boxes);
  std::vector<std::unique_ptr<SolidIndex>> index(ns);
  auto inside = [&](int32_t container, const Vec3& p) {
    const Mesh& m = meshes[container];
    if (m.triangles.size() > kDirectWindingTriangles) {
      if (!index[container]) index[container] = std::make_unique<SolidIndex>(m);
      const Containment c = index[container]->classify(p);
      if (c != Containment::kBoundary) return c == Containment::kInside;
    }
    double total = 0.0;
    for (const Triangle& t : m.triangles)
      total += triangleSolidAngle(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], p);
    return std::abs(total / (4.0 * std::numbers::pi)) > kInsideWinding;
  };
  for (const auto& [box, s] : closed_boxes) {
    const Mesh& m = meshes[s];
    size_t best = 0;
    double best_area = -1.0;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
      const Triangle& tri = m.triangles[t];
      const double area = (m.vertices[tri[1]] - m.vertices[tri[0]])
                              .cross(m.vertices[tri[2]] - m.vertices[tri[0]])
                              .squaredNorm();
      if (area > best_area) {
        best_area = area;
        best = t;
      }
    }
    const Triangle& tri = m.triangles[best];
    const Vec3 p = (m.vertices[tri[0]] + m.vertices[tri[1]] + m.vertices[tri[2]]) / 3.0;
    Shell& shell = out.shells[s];
    double parent_volume = std::numeric_limits<double>::infinity();
    std::vector<int32_t> containers;
    const int32_t self = s;  // a structured binding cannot be captured before C++20 in clang 14
    tree.containing(box, [&](int32_t a) {
      if (a != self && !crossing(a, self)) containers.push_back(a);
    });
    std::sort(containers.begin(), containers.end());
    for (int32_t a : containers) {
      if (!inside(a, p)) continue;
      ++shell.depth;
      // The innermost container encloses the least volume.
      const double v = std::abs(out.shells[a].volume);
      if (v < parent_volume) {
        parent_volume = v;
        shell.parent = a;
      }
    }
  }
  return out;
}

ShellCounts countShells(const ShellAnalysis& sa) {
  ShellCounts c;
  c.shells = static_cast<int64_t>(sa.shells.size());
  for (const Shell& s : sa.shells) {
    c.closed += s.closed;
    c.clean += s.clean();
    c.inward += s.closed && s.volume < 0.0;
    c.nested += s.parent >= 0;
  }
  c.intersecting_pairs = static_cast<int64_t>(sa.intersecting.size());
  c.triangle_pairs = static_cast<int64_t>(sa.intersections.pairs.size());
  c.truncated = sa.intersections.truncated;
  return c;
}

}  // namespace sphereset

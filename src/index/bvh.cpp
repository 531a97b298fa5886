// Bounding-volume hierarchy over triangles: median split of centroids along the longest axis
// of their bounds. Simple, deterministic, O(n log n), and depth-bounded (median splits halve
// the range), which keeps the fixed traversal stack safe.
#include "index/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace sphereset::detail {

void Bvh::build(const Mesh& mesh, int leaf_size) {
  const int32_t n = static_cast<int32_t>(mesh.triangles.size());
  nodes.clear();
  tris.clear();
  original.resize(n);
  std::iota(original.begin(), original.end(), 0);
  if (n == 0) return;

  std::vector<Vec3> centroid(n);
  std::vector<Aabb> box(n);
  for (int32_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) box[t].extend(mesh.vertices[tri[k]]);
    centroid[t] = box[t].center();
  }

  nodes.reserve(2 * (n / std::max(1, leaf_size)) + 8);
  nodes.push_back({});
  nodes.push_back({});  // unused: keeps sibling pairs on even indices
  struct Task {
    int32_t node, begin, end;
  };
  std::vector<Task> stack{{0, 0, n}};
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    Aabb bounds, cbounds;
    for (int32_t i = task.begin; i < task.end; ++i) {
      bounds.extend(box[original[i]]);
      cbounds.extend(centroid[original[i]]);
    }
    nodes[task.node].setBox(bounds.min, bounds.max);
    const int32_t count = task.end - task.begin;
    int axis = 0;
    const Vec3 extent = cbounds.max - cbounds.min;
    extent.maxCoeff(&axis);
    if (count <= leaf_size || extent[axis] <= 0.0) {
      nodes[task.node].first = task.begin;
      nodes[task.node].count = count;
      continue;
    }
    const int32_t mid = task.begin + count / 2;
    std::nth_element(original.begin() + task.begin, original.begin() + mid,
                     original.begin() + task.end, [&](int32_t x, int32_t y) {
                       if (centroid[x][axis] != centroid[y][axis])
                         return centroid[x][axis] < centroid[y][axis];
                       return x < y;  // deterministic order for equal keys
                     });
    const int32_t left = static_cast<int32_t>(nodes.size());
    nodes.push_back({});
    nodes.push_back({});
    nodes[task.node].first = left;
    nodes[task.node].count = 0;
    stack.push_back({left + 1, mid, task.end});
    stack.push_back({left, task.begin, mid});
  }

  tris.resize(n);
  for (int32_t i = 0; i < n; ++i) {
    const auto& tri = mesh.triangles[original[i]];
    TriRecord& r = tris[i];
    r.a = mesh.vertices[tri[0]];
    r.b = mesh.vertices[tri[1]];
    r.c = mesh.vertices[tri[2]];
    const Vec3 nn = (r.b - r.a).cross(r.c - r.a);
    const double len = nn.norm();
    r.area = 0.5 * len;
    r.n = len > 0.0 ? Vec3(nn / len) : Vec3::Zero();
  }
  buildNeighbours(mesh);
  buildSums();
}

void Bvh::buildNeighbours(const Mesh& mesh) {
  const int32_t n = static_cast<int32_t>(tris.size());
  std::vector<int32_t> pos_of(n);
  for (int32_t i = 0; i < n; ++i) pos_of[original[i]] = i;
  // Directed edges sorted by (from, to); the neighbour across (u, v) owns (v, u). An edge is
  // used only if both directions occur exactly once (closed, manifold, oriented).
  struct DirEdge {
    int64_t key;
    int32_t tri;
  };
  const int64_t nv = static_cast<int64_t>(mesh.vertices.size());
  std::vector<DirEdge> edges;
  edges.reserve(3 * static_cast<size_t>(n));
  for (int32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      edges.push_back({mesh.triangles[t][k] * nv + mesh.triangles[t][(k + 1) % 3], t});
  std::sort(edges.begin(), edges.end(), [](const DirEdge& a, const DirEdge& b) {
    return a.key < b.key || (a.key == b.key && a.tri < b.tri);
  });
  auto uniqueOwner = [&](int64_t key) -> int32_t {
    auto it = std::lower_bound(edges.begin(), edges.end(), key,
                               [](const DirEdge& e, int64_t k) { return e.key < k; });
    if (it == edges.end() || it->key != key) return -1;
    if (it + 1 != edges.end() && (it + 1)->key == key) return -1;
    return it->tri;
  };
  closed = true;
  for (int32_t i = 0; i < n; ++i) {
    const Triangle& t = mesh.triangles[original[i]];
    for (int k = 0; k < 3; ++k) {
      const int64_t u = t[k], v = t[(k + 1) % 3];
      const int32_t self = uniqueOwner(u * nv + v);
      const int32_t other = self >= 0 ? uniqueOwner(v * nv + u) : -1;
      tris[i].nbr[k] = other >= 0 ? pos_of[other] : -1;
      if (other < 0) closed = false;
    }
  }
}

void Bvh::buildSums() {
  sums.assign(nodes.size(), NodeSums{});
  // Children come after their parent, so a reverse sweep sees children first. Moving the
  // reference point from q to p changes det by -(p - q) · cross.
  for (size_t ni = nodes.size(); ni-- > 0;) {
    if (ni == 1) continue;  // the unused slot
    const BvhNode& node = nodes[ni];
    NodeSums& s = sums[ni];
    s.q = 0.5 * (node.min() + node.max());
    if (node.leaf()) {
      for (int32_t i = node.first; i < node.first + node.count; ++i) {
        const TriRecord& t = tris[i];
        s.det_q += (t.a - s.q).dot((t.b - s.q).cross(t.c - s.q));
        s.cross += (t.b - t.a).cross(t.c - t.a);
      }
    } else {
      for (int32_t c = node.first; c <= node.first + 1; ++c) {
        const NodeSums& cs = sums[c];
        s.det_q += cs.det_q - (s.q - cs.q).dot(cs.cross);
        s.cross += cs.cross;
      }
    }
  }
}

}  // namespace sphereset::detail

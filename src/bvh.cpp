// Bounding-volume hierarchy over triangles: median split of centroids along the longest axis
// of their bounds. Simple, deterministic, O(n log n), and depth-bounded (median splits halve
// the range), which keeps the fixed traversal stack safe.
#include "bvh.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

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
  std::vector<std::array<int32_t, 2>> ranges;
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
    if (ranges.size() < nodes.size()) ranges.resize(nodes.size());
    ranges[task.node] = {task.begin, task.end - task.begin};
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
  buildPatches(mesh, ranges);
}

void Bvh::buildPatches(const Mesh& mesh, const std::vector<std::array<int32_t, 2>>& ranges) {
  const int32_t n = static_cast<int32_t>(tris.size());
  patches.clear();
  node_patch.assign(nodes.size(), -1);
  patch_loops.clear();
  patch_vertices.clear();
  // Position in `tris` of the neighbour across each directed edge, -1 where the edge is not
  // shared by exactly one oppositely oriented triangle (open or non-manifold meshes: the
  // nodes touching such edges get no patch and are always evaluated triangle by triangle).
  std::vector<int32_t> pos_of(n);
  for (int32_t i = 0; i < n; ++i) pos_of[original[i]] = i;
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
  std::sort(edges.begin(), edges.end(),
            [](const DirEdge& a, const DirEdge& b) { return a.key < b.key || (a.key == b.key && a.tri < b.tri); });
  auto twinOf = [&](int64_t u, int64_t v) -> int32_t {
    const int64_t key = v * nv + u;
    auto it = std::lower_bound(edges.begin(), edges.end(), key,
                               [](const DirEdge& e, int64_t k) { return e.key < k; });
    if (it == edges.end() || it->key != key) return -1;
    if (it + 1 != edges.end() && (it + 1)->key == key) return -1;  // non-manifold
    return pos_of[it->tri];
  };
  std::vector<int32_t> twin(3 * static_cast<size_t>(n));
  for (int32_t i = 0; i < n; ++i) {
    const Triangle& t = mesh.triangles[original[i]];
    for (int k = 0; k < 3; ++k) {
      // The directed edge must also be unique, or its twin is ambiguous.
      const int64_t u = t[k], v = t[(k + 1) % 3];
      const auto lo = std::lower_bound(edges.begin(), edges.end(), u * nv + v,
                                       [](const DirEdge& e, int64_t key) { return e.key < key; });
      const bool unique = lo + 1 == edges.end() || (lo + 1)->key != u * nv + v;
      twin[3 * i + k] = unique ? twinOf(u, v) : -1;
    }
  }
  std::vector<std::array<int32_t, 2>> edges_uv;  // the current patch's boundary edges
  std::unordered_map<int32_t, std::vector<int32_t>> out_edges;
  for (size_t ni = 0; ni < nodes.size(); ++ni) {
    if (ni == 1) continue;  // the unused slot
    const BvhNode& node = nodes[ni];
    const int32_t begin = ranges[ni][0], total = ranges[ni][1];
    if (total < kMinPatch) continue;
    NodePatch p;
    p.q = 0.5 * (node.min() + node.max());
    edges_uv.clear();
    bool ok = true;
    for (int32_t i = begin; i < begin + total && ok; ++i) {
      const TriRecord& tr = tris[i];
      p.det_q += (tr.a - p.q).dot((tr.b - p.q).cross(tr.c - p.q));
      p.cross += (tr.b - tr.a).cross(tr.c - tr.a);
      const Triangle& t = mesh.triangles[original[i]];
      for (int k = 0; k < 3; ++k) {
        const int32_t tw = twin[3 * i + k];
        if (tw < 0) {
          ok = false;
          break;
        }
        if (tw < begin || tw >= begin + total) edges_uv.push_back({t[k], t[(k + 1) % 3]});
      }
    }
    // A patch pays off only when its boundary is shorter than its triangle list.
    if (!ok || static_cast<int32_t>(edges_uv.size()) >= total) continue;
    // Chain the directed boundary edges into closed loops, stored as vertex sequences with
    // the first vertex repeated at the end, so that consecutive entries are the edges.
    out_edges.clear();
    for (int32_t e = 0; e < static_cast<int32_t>(edges_uv.size()); ++e)
      out_edges[edges_uv[e][0]].push_back(e);
    std::vector<char> used(edges_uv.size(), 0);
    p.loop_begin = static_cast<int32_t>(patch_loops.size());
    for (size_t e0 = 0; e0 < edges_uv.size(); ++e0) {
      if (used[e0]) continue;
      const int32_t start = static_cast<int32_t>(patch_vertices.size());
      int32_t e = static_cast<int32_t>(e0);
      patch_vertices.push_back(mesh.vertices[edges_uv[e][0]]);
      while (e >= 0 && !used[e]) {
        used[e] = 1;
        const int32_t v = edges_uv[e][1];
        patch_vertices.push_back(mesh.vertices[v]);
        e = -1;
        for (int32_t cand : out_edges[v])
          if (!used[cand]) {
            e = cand;
            break;
          }
      }
      patch_loops.push_back({start, static_cast<int32_t>(patch_vertices.size())});
    }
    p.loop_end = static_cast<int32_t>(patch_loops.size());
    p.edges = static_cast<int32_t>(edges_uv.size());
    node_patch[ni] = static_cast<int32_t>(patches.size());
    patches.push_back(p);
  }
}

}  // namespace sphereset::detail

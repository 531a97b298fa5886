// Bounding-volume hierarchy over triangles: median split of centroids along the longest axis
// of their bounds. Simple, deterministic, O(n log n), and depth-bounded (median splits halve
// the range), which keeps the fixed traversal stack safe.
#include "bvh.hpp"

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
    nodes[task.node].min = bounds.min;
    nodes[task.node].max = bounds.max;
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
}

}  // namespace sphereset::detail

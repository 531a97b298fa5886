// Consistent orientation by breadth-first propagation across two-triangle edges: the standard
// approach (e.g. Botsch, Kobbelt, Pauly, Alliez, Lévy 2010, "Polygon Mesh Processing", Sec.
// 3.3); a triangle's orientation is forced by its first oriented neighbour, and a neighbour
// that disagrees with an already oriented one proves the component non-orientable. Each
// component then keeps the orientation of the majority of its triangles.
#include "repair/orient.hpp"

#include <algorithm>
#include <deque>
#include <utility>
#include <vector>

namespace sphereset::detail {

int64_t orientConsistently(Mesh* mesh) {
  const auto nt = static_cast<int32_t>(mesh->triangles.size());
  // Directed edges (lo, hi, triangle, forward), sorted by the undirected key.
  struct Edge {
    int32_t lo, hi, tri;
    bool forward;
  };
  std::vector<Edge> edges;
  edges.reserve(3 * static_cast<size_t>(nt));
  for (int32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = mesh->triangles[t][k], b = mesh->triangles[t][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.tri < y.tri);
  });
  // Neighbours across two-triangle edges, with whether the two traverse it the same way.
  std::vector<std::vector<std::pair<int32_t, bool>>> adj(nt);
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    if (j - i == 2) {
      const bool same = edges[i].forward == edges[i + 1].forward;
      adj[edges[i].tri].emplace_back(edges[i + 1].tri, same);
      adj[edges[i + 1].tri].emplace_back(edges[i].tri, same);
    }
    i = j;
  }
  // flip[t]: -1 not reached, 0 keep, 1 flip.
  std::vector<int8_t> flip(nt, -1);
  std::deque<int32_t> queue;
  std::vector<int32_t> component;
  for (int32_t s = 0; s < nt; ++s) {
    if (flip[s] >= 0) continue;
    flip[s] = 0;
    queue.push_back(s);
    component.clear();
    while (!queue.empty()) {
      const int32_t t = queue.front();
      queue.pop_front();
      component.push_back(t);
      for (const auto& [u, same] : adj[t]) {
        // Traversed the same way: one of the two must be flipped relative to the other.
        const int8_t want = static_cast<int8_t>(flip[t] ^ (same ? 1 : 0));
        if (flip[u] < 0) {
          flip[u] = want;
          queue.push_back(u);
        } else if (flip[u] != want) {
          return -1;
        }
      }
    }
    // Keep the orientation most of the component's triangles already have: a few flipped
    // faces are the defect, and the rest says whether the shell faces out or in (a cavity).
    size_t to_flip = 0;
    for (int32_t t : component) to_flip += flip[t] == 1;
    if (2 * to_flip > component.size())
      for (int32_t t : component) flip[t] = static_cast<int8_t>(1 - flip[t]);
  }
  int64_t flipped = 0;
  for (int32_t t = 0; t < nt; ++t)
    if (flip[t] == 1) {
      std::swap(mesh->triangles[t][1], mesh->triangles[t][2]);
      ++flipped;
    }
  return flipped;
}

}  // namespace sphereset::detail

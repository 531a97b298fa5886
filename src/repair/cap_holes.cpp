// Hole capping: the boundary loops of an otherwise sound surface, closed by fans. This is the
// simplest hole filling (no fairing, no minimal-area triangulation, cf. Liepa 2003, "Filling
// holes in meshes"): the repair only needs the cap to close the solid without crossing the
// surface, and checks that afterwards (repair.cpp); a cap that crosses it sends the mesh to
// the wrapping instead.
#include "repair/cap_holes.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace sphereset::detail {

int64_t capHoles(Mesh* mesh) {
  // Directed edges and how often each undirected edge occurs.
  std::map<std::pair<int32_t, int32_t>, int> uses;
  for (const Triangle& t : mesh->triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  // Boundary half-edges a -> b (as the triangle traverses them), keyed by a; the loop goes on
  // from b. Sorted, so the walk is deterministic.
  std::multimap<int32_t, int32_t> next;
  for (const Triangle& t : mesh->triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      if (uses[{std::min(a, b), std::max(a, b)}] == 1) next.emplace(a, b);
    }
  int64_t loops = 0;
  while (!next.empty()) {
    const int32_t start = next.begin()->first;
    std::vector<int32_t> loop;
    int32_t v = start;
    bool closed = false;
    while (true) {
      auto it = next.find(v);
      if (it == next.end()) break;  // an open chain (should not happen for boundary edges)
      loop.push_back(v);
      v = it->second;
      next.erase(it);
      if (v == start) {
        closed = true;
        break;
      }
    }
    if (!closed || loop.size() < 3) continue;
    ++loops;
    // The surface traverses the loop as loop[i] -> loop[i+1]; the cap runs the other way.
    const size_t n = loop.size();
    if (n == 3) {
      mesh->triangles.push_back({loop[0], loop[2], loop[1]});
      continue;
    }
    Vec3 c = Vec3::Zero();
    for (int32_t k : loop) c += mesh->vertices[k];
    c /= static_cast<double>(n);
    const auto ci = static_cast<int32_t>(mesh->vertices.size());
    mesh->vertices.push_back(c);
    for (size_t i = 0; i < n; ++i) mesh->triangles.push_back({loop[(i + 1) % n], loop[i], ci});
  }
  return loops;
}

}  // namespace sphereset::detail

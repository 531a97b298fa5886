// Hole capping: the boundary loops of an otherwise sound surface, closed by a triangulation over
// the loop's own vertices chosen by the dynamic programme of Liepa 2003, "Filling holes in
// meshes", Sec. 3 (after Barequet and Sharir 1995): the largest dihedral angle between
// neighbouring triangles (cap-cap and cap-surface) is minimised first, then the area. A cap
// that bends least is also least likely to cut through the surface beside the hole. No
// refinement or fairing follows (Liepa's Sec. 4-5): the cap only has to close the solid. Long
// loops, where the O(n^3) programme would be slow, get a fan around their centroid instead. The
// repair only needs the cap to close the solid without crossing the surface, and checks that
// afterwards (repair.cpp); a cap that crosses it sends the mesh to the wrapping instead.
#include "repair/cap_holes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace sphereset::detail {
namespace {

// Loops longer than this are fanned: the programme costs n^3 / 6 steps (4.5e6 at 300).
constexpr size_t kMaxProgrammeLoop = 300;

// Liepa's weight: (largest dihedral angle, total area), compared in that order.
struct Weight {
  double angle = 0.0, area = 0.0;
  bool operator<(const Weight& o) const {
    return angle != o.angle ? angle < o.angle : area < o.area;
  }
};

Vec3 normal(const Mesh& mesh, int32_t a, int32_t b, int32_t c) {
  const Vec3& p = mesh.vertices[a];
  return (mesh.vertices[b] - p).cross(mesh.vertices[c] - p);
}

// Angle between two normals (0 for coplanar neighbours that continue each other). A triangle
// without area (collinear corners) has no normal and gets the worst angle, so that the
// programme avoids it whenever it can.
double angleBetween(const Vec3& n1, const Vec3& n2) {
  const double d = n1.norm() * n2.norm();
  if (!(d > 0.0)) return std::numbers::pi;
  return std::acos(std::clamp(n1.dot(n2) / d, -1.0, 1.0));
}

// Appends Liepa's triangulation of the polygon `loop` (vertex indices); `opp[i]` is the third
// vertex of the surface triangle on the loop edge loop[i] -> loop[i+1] (cyclic). Each triangle
// is ordered (loop[i], loop[k], loop[m]) for i < m < k, against the loop's direction.
void liepaCap(const Mesh& mesh, const std::vector<int32_t>& loop, const std::vector<int32_t>& opp,
              std::vector<Triangle>* out) {
  const size_t n = loop.size();
  std::vector<Weight> w(n * n);
  std::vector<int32_t> split(n * n, -1);
  // The normal of the triangle next to the edge (i, k) of the sub-polygon loop[i..k], on its
  // outer side: the surface for a loop edge, the sub-polygon's apex triangle otherwise.
  auto outer = [&](size_t i, size_t k) -> Vec3 {
    if (k == i + 1) return normal(mesh, loop[i], loop[k], opp[i]);
    if (i == 0 && k == n - 1) return normal(mesh, loop[k], loop[0], opp[n - 1]);
    return normal(mesh, loop[i], loop[k], loop[split[i * n + k]]);
  };
  for (size_t len = 2; len < n; ++len)
    for (size_t i = 0; i + len < n; ++i) {
      const size_t k = i + len;
      Weight best{std::numeric_limits<double>::infinity(), 0.0};
      for (size_t m = i + 1; m < k; ++m) {
        const Vec3 nt = normal(mesh, loop[i], loop[k], loop[m]);
        Weight c;
        c.angle = std::max({w[i * n + m].angle, w[m * n + k].angle, angleBetween(nt, outer(i, m)),
                            angleBetween(nt, outer(m, k))});
        if (len == n - 1) c.angle = std::max(c.angle, angleBetween(nt, outer(0, n - 1)));
        c.area = w[i * n + m].area + w[m * n + k].area + nt.norm();
        if (c < best) {
          best = c;
          split[i * n + k] = static_cast<int32_t>(m);
        }
      }
      w[i * n + k] = best;
    }
  std::vector<std::pair<size_t, size_t>> todo = {{0, n - 1}};
  while (!todo.empty()) {
    const auto [i, k] = todo.back();
    todo.pop_back();
    if (k < i + 2) continue;
    const auto m = static_cast<size_t>(split[i * n + k]);
    out->push_back({loop[i], loop[k], loop[m]});
    todo.push_back({i, m});
    todo.push_back({m, k});
  }
}

}  // namespace

int64_t capHoles(Mesh* mesh) {
  // Undirected edges, sorted, so that how often one occurs is a binary search.
  std::vector<std::pair<int32_t, int32_t>> edges;
  edges.reserve(3 * mesh->triangles.size());
  for (const Triangle& t : mesh->triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  auto uses = [&](int32_t a, int32_t b) {
    const auto r = std::equal_range(edges.begin(), edges.end(),
                                    std::pair(std::min(a, b), std::max(a, b)));
    return r.second - r.first;
  };
  // Boundary half-edges a -> b (as the triangle traverses them), keyed by a, with b and the
  // triangle's third vertex; the loop goes on from b. Sorted, so the walk is deterministic.
  std::multimap<int32_t, std::pair<int32_t, int32_t>> next;
  for (const Triangle& t : mesh->triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      if (uses(a, b) == 1) next.emplace(a, std::pair(b, t[(k + 2) % 3]));
    }
  int64_t loops = 0;
  while (!next.empty()) {
    const int32_t start = next.begin()->first;
    std::vector<int32_t> loop, opp;
    int32_t v = start;
    bool closed = false;
    while (true) {
      auto it = next.find(v);
      if (it == next.end()) break;  // an open chain (should not happen for boundary edges)
      loop.push_back(v);
      opp.push_back(it->second.second);
      v = it->second.first;
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
    if (n <= kMaxProgrammeLoop) {
      liepaCap(*mesh, loop, opp, &mesh->triangles);
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

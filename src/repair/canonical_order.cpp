// Canonical order of a mesh's vertices and triangles (canonical_order.hpp).
//
// Why: CGAL's corefinement finds intersecting triangles with box_intersection_d on box
// pointers, whose ties are broken by memory address, so the order of the vertices and
// triangles it creates depends on the heap's state (which differs between runs when other work
// runs alongside, as when a robot's links are repaired in parallel). The geometry is the same;
// the numbering is not, and the fit samples triangles in order. Sorting restores determinism.
#include "repair/canonical_order.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>
#include <vector>

namespace sphereset::detail {

Mesh canonicalOrder(Mesh mesh) {
  const size_t nv = mesh.vertices.size();
  std::vector<int32_t> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
    const Vec3& p = mesh.vertices[a];
    const Vec3& q = mesh.vertices[b];
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  });
  std::vector<int32_t> new_index(nv);
  Mesh out;
  out.vertices.reserve(nv);
  for (size_t k = 0; k < nv; ++k) {
    new_index[order[k]] = static_cast<int32_t>(k);
    out.vertices.push_back(mesh.vertices[order[k]]);
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    Triangle r = {new_index[t[0]], new_index[t[1]], new_index[t[2]]};
    // A rotation keeps the orientation.
    const int first = r[1] < r[0] ? (r[2] < r[1] ? 2 : 1) : (r[2] < r[0] ? 2 : 0);
    std::rotate(r.begin(), r.begin() + first, r.end());
    out.triangles.push_back(r);
  }
  std::sort(out.triangles.begin(), out.triangles.end());
  return out;
}

}  // namespace sphereset::detail

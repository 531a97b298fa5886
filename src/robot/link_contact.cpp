// Exact contact between two link solids, for the self-collision sampling's mesh check: two
// closed meshes touch when a triangle of one meets a triangle of the other (candidates from the
// solid index's hierarchy, then the triangle-triangle test of the self-intersection search,
// mesh/triangle_intersection.hpp; both hierarchies walked together, one placed in the other's
// frame), or else when a part of one lies inside the other (one vertex of each connected part
// classified by the solid index's point-in-solid test). A sphere touches
// a mesh when its centre is inside or nearer the surface than its radius.
#include "robot/link_contact.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "index/solid_index_impl.hpp"
#include "mesh/triangle_intersection.hpp"
#include "util/union_find.hpp"

namespace sphereset::detail {
namespace {

bool ballsMeet(const Sphere& a, const Sphere& b) {
  const double reach = a.radius + b.radius;
  return (a.center - b.center).squaredNorm() < reach * reach;
}

// Whether a sphere (in the mesh's frame) touches the solid.
bool sphereTouchesSolid(const SolidIndex& solid, const Sphere& s) {
  if (s.radius > 0.0 && solid.distance(s.center) < s.radius) return true;
  return solid.classify(s.center) != Containment::kOutside;
}

// A node's box as centre and half extents.
struct CentredBox {
  Vec3 c, h;
};

CentredBox centredBox(const BvhNode& n) {
  return {0.5 * (n.min() + n.max()), 0.5 * (n.max() - n.min())};
}

// Whether a triangle of `b`, placed in `a`'s frame by `b_in_a`, meets one of `a`: both
// hierarchies walked together, b's node boxes placed as the boxes that hold them.
bool trianglesCross(const Bvh& a, const Bvh& b, const Eigen::Isometry3d& b_in_a) {
  if (a.nodes.empty() || b.nodes.empty()) return false;
  const Eigen::Matrix3d abs_r = b_in_a.linear().cwiseAbs();
  std::vector<std::array<int32_t, 2>> todo{{0, 0}};
  while (!todo.empty()) {
    const auto [ia, ib] = todo.back();
    todo.pop_back();
    const BvhNode& na = a.nodes[ia];
    const BvhNode& nb = b.nodes[ib];
    const CentredBox ba = centredBox(na), bb = centredBox(nb);
    const Vec3 c = b_in_a * bb.c, h = abs_r * bb.h;
    if (((ba.c - c).cwiseAbs().array() > (ba.h + h).array()).any()) continue;
    if (na.leaf() && nb.leaf()) {
      for (int32_t j = nb.first; j < nb.first + nb.count; ++j) {
        const TriRecord& t = b.tris[j];
        const Vec3 q[3] = {b_in_a * t.a, b_in_a * t.b, b_in_a * t.c};
        const TriangleGeometry gq = triangleGeometry(q[0], q[1], q[2]);
        for (int32_t i = na.first; i < na.first + na.count; ++i) {
          const TriRecord& r = a.tris[i];
          const Vec3 p[3] = {r.a, r.b, r.c};
          if (separateTrianglesIntersect(p, q, triangleGeometry(r.a, r.b, r.c), gq)) return true;
        }
      }
    } else if (nb.leaf() || (!na.leaf() && ba.h.prod() >= bb.h.prod())) {
      todo.push_back({na.first, ib});
      todo.push_back({na.first + 1, ib});
    } else {
      todo.push_back({ia, nb.first});
      todo.push_back({ia, nb.first + 1});
    }
  }
  return false;
}

// Whether some part of `inner` (its shell points, placed in `outer`'s frame) is in `outer`.
bool partInside(const LinkBody& outer, const LinkBody& inner, const Eigen::Isometry3d& placed) {
  for (const Vec3& p : inner.shell_points)
    if (outer.index->classify(placed * p) != Containment::kOutside) return true;
  return false;
}

bool meshesTouch(const LinkBody& a, const LinkBody& b, const Eigen::Isometry3d& b_in_a) {
  const bool crossed = trianglesCross(a.index->impl().bvh, b.index->impl().bvh, b_in_a);
  // No crossing: each part of one is wholly inside or wholly outside the other.
  return crossed || partInside(a, b, b_in_a) || partInside(b, a, b_in_a.inverse());
}

}  // namespace

Sphere boundingSphere(const std::vector<Sphere>& spheres) {
  if (spheres.empty()) return Sphere{Vec3::Zero(), -1.0};
  Aabb box;
  for (const Sphere& s : spheres) {
    box.extend(s.center - Vec3::Constant(s.radius));
    box.extend(s.center + Vec3::Constant(s.radius));
  }
  const Vec3 c = 0.5 * (box.min + box.max);
  double r = 0.0;
  for (const Sphere& s : spheres) r = std::max(r, (s.center - c).norm() + s.radius);
  return Sphere{c, r};
}

LinkBody makeLinkBody(const Mesh& mesh, std::vector<Sphere> spheres) {
  LinkBody body;
  std::vector<Sphere> held = spheres;
  if (!mesh.triangles.empty()) {
    body.index = std::make_unique<SolidIndex>(mesh);
    UnionFind parts(mesh.vertices.size());
    for (const Triangle& t : mesh.triangles) {
      parts.unite(t[0], t[1]);
      parts.unite(t[1], t[2]);
    }
    std::vector<bool> used(mesh.vertices.size(), false);
    for (const Triangle& t : mesh.triangles) {
      const int32_t root = parts.find(t[0]);
      if (!used[root]) body.shell_points.push_back(mesh.vertices[t[0]]);
      used[root] = true;
    }
    // The mesh's vertices as points of radius 0 for the bound.
    for (const Vec3& v : mesh.vertices) held.push_back(Sphere{v, 0.0});
  }
  body.spheres = std::move(spheres);
  body.bound = boundingSphere(held);
  return body;
}

bool bodiesTouch(const LinkBody& a, const LinkBody& b, const Eigen::Isometry3d& b_in_a) {
  if (a.bound.radius < 0.0 || b.bound.radius < 0.0) return false;
  const Sphere bb{b_in_a * b.bound.center, b.bound.radius};
  // Touching counts for solids, so the bounds are compared with a margin.
  const double reach = a.bound.radius + bb.radius;
  if ((a.bound.center - bb.center).squaredNorm() > reach * reach * (1.0 + 1e-12)) return false;
  for (const Sphere& sb : b.spheres) {
    const Sphere placed{b_in_a * sb.center, sb.radius};
    const double r = a.bound.radius + sb.radius;
    if ((a.bound.center - placed.center).squaredNorm() > r * r * (1.0 + 1e-12)) continue;
    for (const Sphere& sa : a.spheres)
      if (ballsMeet(sa, placed)) return true;
    if (a.index && sphereTouchesSolid(*a.index, placed)) return true;
  }
  const Eigen::Isometry3d a_in_b = b_in_a.inverse();
  if (b.index)
    for (const Sphere& sa : a.spheres)
      if (sphereTouchesSolid(*b.index, Sphere{a_in_b * sa.center, sa.radius})) return true;
  return a.index && b.index && meshesTouch(a, b, b_in_a);
}

}  // namespace sphereset::detail

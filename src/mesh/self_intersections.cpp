// Self-intersections of a triangle mesh: candidate pairs from a bounding-volume hierarchy over
// the triangles' boxes (median splits, subtrees built in parallel), then an exact-topology,
// tolerance-geometry triangle–triangle test. The test rests on the observation behind Möller 1997
// ("A fast triangle-triangle intersection test") and Guigue & Devillers 2003 ("Fast and robust
// triangle-triangle overlap test using orientation predicates"): two closed triangles meet iff an
// edge of one meets the other, both when they are coplanar and when they are not. Shared vertices
// and edges (by index) are handled by the case analysis in trianglesIntersect().
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/triangle_intersection.hpp"
#include "sphereset/mesh_defects.hpp"

namespace sphereset {
namespace {

// Triangles per block of the candidate search. Blocks run in index order, each in parallel,
// so that stopping at max_pairs keeps the pairs with the smallest first index: deterministic.
constexpr int32_t kBlockTriangles = 1 << 15;
// Triangles per leaf of the hierarchy, and the size above which a node's two subtrees are
// built in parallel.
constexpr int32_t kLeafTriangles = 4;
constexpr int32_t kParallelBuild = 1 << 14;

bool boxesOverlap(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

// The hierarchy over triangle boxes, nodes in depth-first order: a node's left child follows
// it, `right` is the index of its right child (-1 for a leaf, whose triangles are
// order[first, first + count)).
struct BoxNode {
  Aabb box;
  int32_t right = -1;
  int32_t first = 0, count = 0;
};

struct BoxHierarchy {
  std::vector<int32_t> order;
  std::vector<BoxNode> nodes;

  BoxHierarchy(std::vector<int32_t> items, const std::vector<Aabb>& boxes)
      : order(std::move(items)) {
    if (!order.empty()) nodes = build(boxes, 0, static_cast<int32_t>(order.size()));
  }

  // Calls visit(t) for every triangle t whose box overlaps `query`.
  template <class Visit>
  void overlapping(const Aabb& query, const std::vector<Aabb>& boxes, Visit&& visit) const {
    if (nodes.empty()) return;
    int32_t stack[64];  // median splits: depth below log2(n) + 2
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const int32_t ni = stack[--top];
      const BoxNode& node = nodes[ni];
      if (!boxesOverlap(node.box, query)) continue;
      if (node.right < 0) {
        for (int32_t k = node.first; k < node.first + node.count; ++k)
          if (boxesOverlap(boxes[order[k]], query)) visit(order[k]);
      } else {
        stack[top++] = node.right;
        stack[top++] = ni + 1;
      }
    }
  }

 private:
  std::vector<BoxNode> build(const std::vector<Aabb>& boxes, int32_t begin, int32_t end) {
    BoxNode node;
    const int32_t count = end - begin;
    if (count <= kLeafTriangles) {
      for (int32_t k = begin; k < end; ++k) node.box.extend(boxes[order[k]]);
      node.first = begin;
      node.count = count;
      return {node};
    }
    // Split at the median box centre along the longest axis of the centres' bounds (twice the
    // centres, which orders the same).
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int32_t k = begin; k < end; ++k) {
      const Vec3 c = boxes[order[k]].min + boxes[order[k]].max;
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int32_t mid = begin + count / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](int32_t x, int32_t y) {
                       const double cx = boxes[x].min[axis] + boxes[x].max[axis];
                       const double cy = boxes[y].min[axis] + boxes[y].max[axis];
                       return cx != cy ? cx < cy : x < y;  // deterministic for equal keys
                     });
    std::vector<BoxNode> left, right;
    if (count > kParallelBuild) {
      tbb::parallel_invoke([&] { left = build(boxes, begin, mid); },
                           [&] { right = build(boxes, mid, end); });
    } else {
      left = build(boxes, begin, mid);
      right = build(boxes, mid, end);
    }
    std::vector<BoxNode> out;
    out.reserve(1 + left.size() + right.size());
    node.right = static_cast<int32_t>(1 + left.size());
    node.box = left.front().box;
    node.box.extend(right.front().box);
    out.push_back(node);
    auto append = [&out](const std::vector<BoxNode>& part) {
      const int32_t base = static_cast<int32_t>(out.size());
      for (BoxNode n : part) {
        if (n.right >= 0) n.right += base;
        out.push_back(n);
      }
    };
    append(left);
    append(right);
    return out;
  }
};

}  // namespace

namespace detail {
namespace {

// Dimensionless: lengths below kIntersectionRelTol × (longest edge of the two triangles),
// in the mesh's length units, count as zero (a point on a plane, on an edge line).
constexpr double kRelTol = kIntersectionRelTol;

struct Tri {
  Vec3 a, b, c;
};

// Signed distance of x from the line e0 e1 inside the plane of unit normal n, positive on the
// side where a counter-clockwise (about n) triangle lies.
double edgeDistance(const Vec3& n, const Vec3& e0, const Vec3& e1, const Vec3& x) {
  const Vec3 e = e1 - e0;
  const double len = e.norm();
  return n.cross(e).dot(x - e0) / len;
}

// Whether the closed segment s0 s1 meets the closed triangle t (unit normal n, counter-
// clockwise about n), within eps (length units).
bool segmentMeetsTriangle(const Vec3& s0, const Vec3& s1, const Tri& t, const Vec3& n, double eps) {
  double d0 = n.dot(s0 - t.a), d1 = n.dot(s1 - t.a);
  if (std::abs(d0) <= eps) d0 = 0.0;
  if (std::abs(d1) <= eps) d1 = 0.0;
  if ((d0 > 0.0 && d1 > 0.0) || (d0 < 0.0 && d1 < 0.0)) return false;
  const Vec3* corners[4] = {&t.a, &t.b, &t.c, &t.a};
  if (d0 != 0.0 || d1 != 0.0) {
    // One crossing point: inside the three edge half-planes?
    const Vec3 x = d0 == 0.0 ? s0 : d1 == 0.0 ? s1 : Vec3(s0 + (d0 / (d0 - d1)) * (s1 - s0));
    for (int k = 0; k < 3; ++k)
      if (edgeDistance(n, *corners[k], *corners[k + 1], x) < -eps) return false;
    return true;
  }
  // The segment lies in the plane: clip its parameter range by the three edge half-planes.
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double g0 = edgeDistance(n, *corners[k], *corners[k + 1], s0) + eps;
    const double g1 = edgeDistance(n, *corners[k], *corners[k + 1], s1) + eps;
    if (g0 < 0.0 && g1 < 0.0) return false;
    if (g0 < 0.0) lo = std::max(lo, g0 / (g0 - g1));
    if (g1 < 0.0) hi = std::min(hi, g0 / (g0 - g1));
    if (lo > hi) return false;
  }
  return true;
}

// Whether direction r lies in the closed planar cone spanned by u and w (angle below π), all
// unit vectors in the plane of unit normal n; sin_tol is the angular tolerance (radians).
bool directionInCone(const Vec3& n, const Vec3& u, const Vec3& w, const Vec3& r, double sin_tol) {
  const double orient = n.dot(u.cross(w));
  const double s = orient >= 0.0 ? 1.0 : -1.0;
  return s * n.dot(u.cross(r)) >= -sin_tol && s * n.dot(r.cross(w)) >= -sin_tol;
}

}  // namespace

TriangleGeometry triangleGeometry(const Vec3& a, const Vec3& b, const Vec3& c) {
  TriangleGeometry g;
  const Vec3 cr = (b - a).cross(c - a);
  g.longest_edge = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const double len = cr.norm();
  // Degenerate: height below kRelTol × longest edge (twice the area is height × base).
  g.degenerate = !(len > kRelTol * g.longest_edge * g.longest_edge);
  g.normal = g.degenerate ? Vec3::Zero() : Vec3(cr / len);
  return g;
}

bool trianglesIntersect(const Mesh& mesh, int32_t i, int32_t j, const TriangleGeometry& gi,
                        const TriangleGeometry& gj) {
  if (gi.degenerate || gj.degenerate) return false;
  const Triangle& ti = mesh.triangles[i];
  const Triangle& tj = mesh.triangles[j];
  // Shared vertex indices: position in ti and in tj.
  int shared = 0;
  int si[3], sj[3];
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q)
      if (ti[p] == tj[q]) {
        si[shared] = p;
        sj[shared] = q;
        ++shared;
      }
  if (shared >= 3) return true;  // the same vertex set: a duplicated face

  const auto& V = mesh.vertices;
  const Tri A{V[ti[0]], V[ti[1]], V[ti[2]]};
  const Tri B{V[tj[0]], V[tj[1]], V[tj[2]]};
  const Vec3 pa[3] = {A.a, A.b, A.c};
  const Vec3 pb[3] = {B.a, B.b, B.c};
  const double eps = kRelTol * std::max(gi.longest_edge, gj.longest_edge);

  if (shared == 2) {
    // Common edge u w; third vertices p (of i) and q (of j). Only a folded coplanar pair (p and
    // q on the same side of the edge) overlaps beyond the edge.
    const int pi = 3 - si[0] - si[1], qj = 3 - sj[0] - sj[1];
    const Vec3& u = pa[si[0]];
    const Vec3& p = pa[pi];
    const Vec3& q = pb[qj];
    if (std::abs(gi.normal.dot(q - u)) > eps || std::abs(gj.normal.dot(p - u)) > eps) {
      return false;
    }
    const Vec3 w = pa[si[1]] - u;
    return w.cross(p - u).dot(w.cross(q - u)) > 0.0;
  }

  if (shared == 1) {
    const Vec3& v = pa[si[0]];
    const Vec3& p1 = pa[(si[0] + 1) % 3];
    const Vec3& p2 = pa[(si[0] + 2) % 3];
    const Vec3& q1 = pb[(sj[0] + 1) % 3];
    const Vec3& q2 = pb[(sj[0] + 2) % 3];
    const bool coplanar =
        std::abs(gi.normal.dot(q1 - v)) <= eps && std::abs(gi.normal.dot(q2 - v)) <= eps &&
        std::abs(gj.normal.dot(p1 - v)) <= eps && std::abs(gj.normal.dot(p2 - v)) <= eps;
    if (!coplanar) {
      // Both meet the line of the two planes in a segment from v; they share more than v iff
      // the shorter one ends on its triangle's edge opposite v inside the other triangle.
      return segmentMeetsTriangle(p1, p2, B, gj.normal, eps) ||
             segmentMeetsTriangle(q1, q2, A, gi.normal, eps);
    }
    // Coplanar: two convex triangles sharing v share a point x ≠ v iff they share the segment
    // v x, i.e. iff their closed angular wedges at v share a direction. Two wedges (angles
    // below π) share one iff a boundary ray of one lies in the other.
    const Vec3& n = gi.normal;
    const Vec3 u1 = (p1 - v).normalized(), w1 = (p2 - v).normalized();
    const Vec3 u2 = (q1 - v).normalized(), w2 = (q2 - v).normalized();
    const double sin_tol = kRelTol;
    return directionInCone(n, u1, w1, u2, sin_tol) || directionInCone(n, u1, w1, w2, sin_tol) ||
           directionInCone(n, u2, w2, u1, sin_tol) || directionInCone(n, u2, w2, w1, sin_tol);
  }

  return separateTrianglesIntersect(pa, pb, gi, gj);
}

bool separateTrianglesIntersect(const Vec3 (&a)[3], const Vec3 (&b)[3], const TriangleGeometry& ga,
                                const TriangleGeometry& gb) {
  if (ga.degenerate || gb.degenerate) return false;
  const Tri A{a[0], a[1], a[2]};
  const Tri B{b[0], b[1], b[2]};
  const double eps = kRelTol * std::max(ga.longest_edge, gb.longest_edge);
  // The closed triangles meet iff an edge of one meets the other.
  for (int k = 0; k < 3; ++k) {
    if (segmentMeetsTriangle(a[k], a[(k + 1) % 3], B, gb.normal, eps)) return true;
    if (segmentMeetsTriangle(b[k], b[(k + 1) % 3], A, ga.normal, eps)) return true;
  }
  return false;
}

std::vector<std::array<int32_t, 2>> selfIntersectionsAllPairs(const Mesh& mesh) {
  const int32_t n = static_cast<int32_t>(mesh.triangles.size());
  std::vector<TriangleGeometry> geom(n);
  for (int32_t t = 0; t < n; ++t) {
    const Triangle& tri = mesh.triangles[t];
    geom[t] = triangleGeometry(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
  }
  std::vector<std::array<int32_t, 2>> pairs;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = i + 1; j < n; ++j)
      if (trianglesIntersect(mesh, i, j, geom[i], geom[j])) pairs.push_back({i, j});
  return pairs;
}

}  // namespace detail

SelfIntersections findSelfIntersections(const Mesh& mesh, const SelfIntersectionOptions& options) {
  SelfIntersections out;
  const int32_t n = static_cast<int32_t>(mesh.triangles.size());
  if (n < 2) return out;

  std::vector<detail::TriangleGeometry> geom(n);
  std::vector<Aabb> box(n);
  double longest = 0.0;
  for (int32_t t = 0; t < n; ++t) {
    const Triangle& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    geom[t] = detail::triangleGeometry(a, b, c);
    box[t].extend(a);
    box[t].extend(b);
    box[t].extend(c);
    longest = std::max(longest, geom[t].longest_edge);
  }
  // Boxes grown by the largest tolerance any pair can use, so touching pairs are candidates.
  const double pad = 2.0 * detail::kIntersectionRelTol * longest;
  for (Aabb& b : box) {
    b.min.array() -= pad;
    b.max.array() += pad;
  }

  std::vector<int32_t> usable;
  usable.reserve(n);
  for (int32_t t = 0; t < n; ++t)
    if (!geom[t].degenerate) usable.push_back(t);
  const BoxHierarchy bvh(std::move(usable), box);

  const int64_t max_pairs = std::max<int64_t>(0, options.max_pairs);
  tbb::enumerable_thread_specific<std::vector<std::array<int32_t, 2>>> found;
  std::vector<std::array<int32_t, 2>> pairs;
  for (int32_t begin = 0; begin < n; begin += kBlockTriangles) {
    const int32_t end = std::min(n, begin + kBlockTriangles);
    tbb::parallel_for(tbb::blocked_range<int32_t>(begin, end, 256),
                      [&](const tbb::blocked_range<int32_t>& range) {
                        auto& local = found.local();
                        for (int32_t i = range.begin(); i < range.end(); ++i) {
                          if (geom[i].degenerate) continue;
                          bvh.overlapping(box[i], box, [&](int32_t j) {
                            if (j > i && detail::trianglesIntersect(mesh, i, j, geom[i], geom[j]))
                              local.push_back({i, j});
                          });
                        }
                      });
    for (auto& local : found) {
      pairs.insert(pairs.end(), local.begin(), local.end());
      local.clear();
    }
    if (static_cast<int64_t>(pairs.size()) > max_pairs) break;
  }
  std::sort(pairs.begin(), pairs.end());
  if (static_cast<int64_t>(pairs.size()) > max_pairs) {
    pairs.resize(static_cast<size_t>(max_pairs));
    out.truncated = true;
  }
  out.pairs = std::move(pairs);
  return out;
}

}  // namespace sphereset

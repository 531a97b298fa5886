// Diagnosis of a triangle mesh as a solid: closedness, manifoldness, orientation,
// components, volume, area and bounds.
#include <algorithm>
#include <numeric>

#include "sphereset/mesh.hpp"
#include "util/union_find.hpp"

namespace sphereset {
namespace {

using detail::UnionFind;

struct HalfEdge {
  int32_t lo, hi;  // undirected key
  int32_t tri;
  bool forward;  // stored as lo -> hi in the triangle
  bool operator<(const HalfEdge& o) const {
    return lo != o.lo ? lo < o.lo : (hi != o.hi ? hi < o.hi : tri < o.tri);
  }
};

}  // namespace

MeshDiagnosis diagnoseMesh(const Mesh& mesh) {
  MeshDiagnosis d;
  const int32_t nv = static_cast<int32_t>(mesh.vertices.size());
  const int32_t nt = static_cast<int32_t>(mesh.triangles.size());
  d.vertices = nv;
  d.triangles = nt;
  d.bbox = boundingBox(mesh);
  d.volume = signedVolume(mesh);
  d.area = surfaceArea(mesh);

  std::vector<HalfEdge> he;
  he.reserve(3 * static_cast<size_t>(nt));
  for (int32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      he.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(he.begin(), he.end());

  UnionFind comps(nt);
  double min_edge = std::numeric_limits<double>::infinity(), max_edge = 0.0;
  // Edges that are manifold (exactly two triangles), for the vertex-fan test below.
  std::vector<std::pair<int32_t, int32_t>> manifold_pairs;
  manifold_pairs.reserve(he.size() / 2);
  std::vector<int32_t> manifold_edge_lo, manifold_edge_hi;
  for (size_t i = 0; i < he.size();) {
    size_t j = i;
    while (j < he.size() && he[j].lo == he[i].lo && he[j].hi == he[i].hi) ++j;
    const size_t count = j - i;
    ++d.edges;
    const double len = (mesh.vertices[he[i].lo] - mesh.vertices[he[i].hi]).norm();
    min_edge = std::min(min_edge, len);
    max_edge = std::max(max_edge, len);
    for (size_t k = i + 1; k < j; ++k) comps.unite(he[i].tri, he[k].tri);
    if (count == 1) {
      ++d.boundary_edges;
    } else if (count == 2) {
      if (he[i].forward == he[i + 1].forward) ++d.misoriented_edges;
      manifold_pairs.emplace_back(he[i].tri, he[i + 1].tri);
      manifold_edge_lo.push_back(he[i].lo);
      manifold_edge_hi.push_back(he[i].hi);
    } else {
      ++d.nonmanifold_edges;  // orientation is undefined here; counted as not oriented
    }
    i = j;
  }
  d.min_edge = std::isfinite(min_edge) ? min_edge : 0.0;
  d.max_edge = max_edge;

  std::vector<char> root_seen(nt, 0);
  for (int32_t t = 0; t < nt; ++t) {
    const int32_t r = comps.find(t);
    if (!root_seen[r]) {
      root_seen[r] = 1;
      ++d.components;
    }
  }

  // Vertex fans: the triangles around a vertex, joined across manifold edges at that vertex,
  // must form a single fan; two or more fans (a "bow tie") make the vertex non-manifold.
  std::vector<int32_t> start(nv + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (int32_t k : t) ++start[k + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int32_t> incident(start[nv]);
  {
    std::vector<int32_t> fill(start.begin(), start.end() - 1);
    for (int32_t t = 0; t < nt; ++t)
      for (int32_t k : mesh.triangles[t]) incident[fill[k]++] = t;
  }
  UnionFind fans(nt > 0 ? 3 * static_cast<size_t>(nt) : 0);  // node = (triangle, corner)
  auto corner = [&](int32_t t, int32_t v) {
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[t][k] == v) return 3 * t + k;
    return 3 * t;
  };
  for (size_t e = 0; e < manifold_pairs.size(); ++e) {
    const auto [t0, t1] = manifold_pairs[e];
    for (int32_t v : {manifold_edge_lo[e], manifold_edge_hi[e]})
      fans.unite(corner(t0, v), corner(t1, v));
  }
  for (int32_t v = 0; v < nv; ++v) {
    int32_t first_root = -1;
    for (int32_t i = start[v]; i < start[v + 1]; ++i) {
      const int32_t r = fans.find(corner(incident[i], v));
      if (first_root < 0) {
        first_root = r;
      } else if (r != first_root) {
        ++d.nonmanifold_vertices;
        break;
      }
    }
  }

  d.closed = d.boundary_edges == 0 && nt > 0;
  d.manifold = d.nonmanifold_edges == 0 && d.nonmanifold_vertices == 0;
  d.oriented = d.misoriented_edges == 0 && d.nonmanifold_edges == 0;
  return d;
}

Error notSolidError(const std::string& path, const MeshDiagnosis& d) {
  std::string why;
  auto add = [&](const std::string& s) { why += (why.empty() ? "" : ", ") + s; };
  if (d.boundary_edges > 0) add(std::to_string(d.boundary_edges) + " boundary edges (open)");
  if (d.nonmanifold_edges > 0) add(std::to_string(d.nonmanifold_edges) + " non-manifold edges");
  if (d.nonmanifold_vertices > 0)
    add(std::to_string(d.nonmanifold_vertices) + " non-manifold vertices");
  if (d.misoriented_edges > 0)
    add(std::to_string(d.misoriented_edges) + " inconsistently oriented edges");
  if (why.empty() && !(d.volume > 0.0)) add("zero volume");
  return Error{ErrorCode::kNotSolid, path + ": not a closed solid: " + why};
}

}  // namespace sphereset

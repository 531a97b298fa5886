// Private to sphereset_repair: conversion between sphereset::Mesh and CGAL::Surface_mesh for
// any CGAL kernel (the wrapping uses inexact constructions, the union exact ones). Included by
// the .cpp files of this library only, so that CGAL's headers stay out of the rest.
#pragma once

#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

// Copies `mesh` into `out` (emptied first). Fails when a vertex is not finite, an index is out
// of range or a triangle cannot be added to a halfedge structure (non-manifold edge, or a
// triangle with a repeated vertex).
template <class Point>
Status toSurfaceMesh(const Mesh& mesh, CGAL::Surface_mesh<Point>& out, const std::string& what) {
  using SM = CGAL::Surface_mesh<Point>;
  out.clear();
  out.reserve(mesh.vertices.size(), 3 * mesh.triangles.size() / 2, mesh.triangles.size());
  std::vector<typename SM::Vertex_index> ids;
  ids.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) {
    if (!v.allFinite()) return Error{ErrorCode::kInvalidData, what + ": non-finite vertex"};
    ids.push_back(out.add_vertex(Point(v.x(), v.y(), v.z())));
  }
  const auto n = static_cast<int64_t>(ids.size());
  for (const Triangle& t : mesh.triangles) {
    for (int32_t i : t)
      if (i < 0 || i >= n)
        return Error{ErrorCode::kInvalidData, what + ": triangle index out of range"};
    if (out.add_face(ids[t[0]], ids[t[1]], ids[t[2]]) == SM::null_face())
      return Error{ErrorCode::kInvalidData,
                   what + ": not a 2-manifold oriented surface (a triangle could not be added)"};
  }
  return {};
}

// A coordinate as a double. An exact (lazy) number is rounded from its exact value, not from
// its current interval approximation: that interval tightens whenever some predicate needed
// the exact value, so rounding it would make the output depend on the history of the
// computation (and, through the memory addresses CGAL breaks ties with, on whatever else the
// process did before), and the fit of a repaired link would not be reproducible.
template <class FT>
double roundCoordinate(const FT& x) {
  if constexpr (std::is_floating_point_v<FT>)
    return x;
  else
    return CGAL::to_double(CGAL::exact(x));
}

// Copies a triangulated Surface_mesh into a Mesh (coordinates rounded to double), dropping
// removed elements. Fails on a face that is not a triangle.
template <class Point>
Expected<Mesh> fromSurfaceMesh(const CGAL::Surface_mesh<Point>& sm, const std::string& what) {
  using SM = CGAL::Surface_mesh<Point>;
  Mesh out;
  out.vertices.reserve(sm.number_of_vertices());
  out.triangles.reserve(sm.number_of_faces());
  std::vector<int32_t> index(sm.num_vertices(), -1);  // includes removed vertices
  for (typename SM::Vertex_index v : sm.vertices()) {
    const Point& p = sm.point(v);
    index[static_cast<std::size_t>(v)] = static_cast<int32_t>(out.vertices.size());
    out.vertices.emplace_back(roundCoordinate(p.x()), roundCoordinate(p.y()),
                              roundCoordinate(p.z()));
  }
  for (typename SM::Face_index f : sm.faces()) {
    Triangle t{};
    int k = 0;
    for (typename SM::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (k == 3) break;
      t[k++] = index[static_cast<std::size_t>(v)];
    }
    if (k != 3 || sm.degree(f) != 3)
      return Error{ErrorCode::kInvalidData, what + ": output face is not a triangle"};
    out.triangles.push_back(t);
  }
  return out;
}

// Reverses every triangle when the signed volume is negative (inside-out).
// CGAL's failure messages span several lines ("CGAL ERROR: ...", "Expr: ...", "File: ...");
// errors are one line.
inline std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

inline void orientOutward(Mesh& mesh) {
  if (signedVolume(mesh) >= 0.0) return;
  for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace sphereset::detail

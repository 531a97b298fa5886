// detail::alphaWrap: CGAL's 3D Alpha Wrapping of a triangle soup, the last step of the repair
// ladder (repair.hpp). Reference: CGAL 5.5 manual, "3D Alpha Wrapping" (Portaneri,
// Rouxel-Labbé, Hemmer, Cohen-Steiner, Alliez, "Alpha Wrapping with an Offset", ACM
// Transactions on Graphics 41(4), SIGGRAPH 2022).
//
// Licence: CGAL's Alpha_wrap_3 package is GPL-3+; this file belongs to the sphereset_repair
// library, which is built apart from the MIT-licensed core (see the README).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <string>
#include <vector>

#include "repair_cgal/cgal_ops.hpp"
#include "repair_cgal/surface_mesh_convert.hpp"

namespace sphereset::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

// Floors, relative to the bounding box diagonal: the wrap's size grows as alpha and the offset
// shrink, and at alpha = d/400 CGAL 5.5 already takes a minute on a 6k-triangle chair; below
// these a wrap would run for hours or exhaust memory instead of failing.
constexpr double kMinAlphaRel = 1e-3;
constexpr double kMinOffsetRel = 1e-5;

Error wrapError(ErrorCode code, const std::string& what) {
  return Error{code, "alpha wrap: " + what};
}

}  // namespace

Expected<Mesh> alphaWrap(const Mesh& soup, double alpha, double offset) {
  if (!(std::isfinite(alpha) && alpha > 0.0))
    return wrapError(ErrorCode::kInvalidArgument,
                     "alpha must be a finite length > 0, got " + std::to_string(alpha));
  if (!(std::isfinite(offset) && offset > 0.0))
    return wrapError(ErrorCode::kInvalidArgument,
                     "offset must be a finite length > 0, got " + std::to_string(offset));
  if (soup.triangles.empty()) return wrapError(ErrorCode::kInvalidData, "no triangles");

  std::vector<Point> points;
  points.reserve(soup.vertices.size());
  Aabb box;
  for (const Vec3& v : soup.vertices) {
    if (!v.allFinite()) return wrapError(ErrorCode::kInvalidData, "non-finite vertex");
    points.emplace_back(v.x(), v.y(), v.z());
    box.extend(v);
  }
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(soup.triangles.size());
  const auto n = static_cast<int64_t>(points.size());
  const Kernel::Collinear_3 collinear = Kernel().collinear_3_object();
  for (const Triangle& t : soup.triangles) {
    for (int32_t i : t)
      if (i < 0 || i >= n) return wrapError(ErrorCode::kInvalidData, "index out of range");
    // CGAL skips degenerate triangles, and crashes when none is left: drop them here (exact
    // predicate, as CGAL's).
    if (collinear(points[t[0]], points[t[1]], points[t[2]])) continue;
    faces.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                     static_cast<std::size_t>(t[2])});
  }
  if (faces.empty()) return wrapError(ErrorCode::kInvalidData, "no triangle with area");
  if (alpha < kMinAlphaRel * box.diagonal())
    return wrapError(ErrorCode::kInvalidArgument,
                     "alpha " + std::to_string(alpha) + " is below " +
                         std::to_string(kMinAlphaRel) + " of the bounding box diagonal " +
                         std::to_string(box.diagonal()) + " (the wrap would be too large)");
  if (offset < kMinOffsetRel * box.diagonal())
    return wrapError(ErrorCode::kInvalidArgument,
                     "offset " + std::to_string(offset) + " is below " +
                         std::to_string(kMinOffsetRel) + " of the bounding box diagonal " +
                         std::to_string(box.diagonal()) + " (the wrap would be too large)");

  SurfaceMesh wrap;
  try {
    CGAL::alpha_wrap_3(points, faces, alpha, offset, wrap);
  } catch (const std::exception& e) {
    return wrapError(ErrorCode::kInvalidData, "CGAL failed: " + oneLine(e.what()));
  } catch (...) {
    return wrapError(ErrorCode::kInvalidData, "CGAL failed with an unknown exception");
  }
  if (wrap.number_of_faces() == 0)
    return wrapError(ErrorCode::kInvalidData, "empty output (no triangle with area?)");

  auto mesh = fromSurfaceMesh(wrap, "alpha wrap");
  if (!mesh) return mesh;
  orientOutward(*mesh);
  return mesh;
}

}  // namespace sphereset::detail

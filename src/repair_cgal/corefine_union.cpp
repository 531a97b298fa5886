// detail::solidUnion: the union of clean closed shells by corefinement with exact
// constructions, the "union" step of the repair ladder (repair.hpp). Reference: CGAL 5.5
// manual, "Polygon Mesh Processing", section "Corefinement and Boolean Operations"
// (CGAL::Polygon_mesh_processing::corefine_and_compute_union).
//
// Licence: CGAL's Polygon_mesh_processing package is GPL-3+; this file belongs to the
// sphereset_repair library, which is built apart from the MIT-licensed core (see the README).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "repair_cgal/cgal_ops.hpp"
#include "repair_cgal/surface_mesh_convert.hpp"

namespace sphereset::detail {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

Error unionError(ErrorCode code, const std::string& what) {
  return Error{code, "solid union: " + what};
}

// Checks the preconditions of the corefinement, which CGAL does not check in release builds.
Status checkShell(const SurfaceMesh& sm, const std::string& name) {
  if (!CGAL::is_closed(sm)) return unionError(ErrorCode::kNotSolid, name + " is not closed");
  if (PMP::does_self_intersect(sm))
    return unionError(ErrorCode::kNotSolid, name + " intersects itself");
  if (!PMP::does_bound_a_volume(sm))
    return unionError(ErrorCode::kNotSolid, name + " does not bound a volume");
  return {};
}

Expected<Mesh> unite(const std::vector<Mesh>& solids) {
  SurfaceMesh result;
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const std::string name = "shell " + std::to_string(i);
    SurfaceMesh shell;
    if (Status s = toSurfaceMesh(solids[i], shell, "solid union: " + name); !s) return s.error();
    if (shell.number_of_faces() == 0) continue;
    if (Status s = checkShell(shell, name); !s) return s.error();
    if (result.number_of_faces() == 0) {
      result = std::move(shell);
      continue;
    }
    SurfaceMesh out;
    if (!PMP::corefine_and_compute_union(result, shell, out))
      return unionError(ErrorCode::kNotSolid,
                        "the corefinement could not make the union with " + name);
    result = std::move(out);
  }
  if (result.number_of_faces() == 0) return unionError(ErrorCode::kInvalidData, "no triangles");
  result.collect_garbage();
  auto mesh = fromSurfaceMesh(result, "solid union");
  if (!mesh) return mesh;
  orientOutward(*mesh);
  return mesh;
}

}  // namespace

Expected<Mesh> solidUnion(const std::vector<Mesh>& solids) {
  if (solids.empty()) return unionError(ErrorCode::kInvalidArgument, "no shells given");
  try {
    return unite(solids);
  } catch (const std::exception& e) {
    return unionError(ErrorCode::kInvalidData, "CGAL failed: " + oneLine(e.what()));
  } catch (...) {
    return unionError(ErrorCode::kInvalidData, "CGAL failed with an unknown exception");
  }
}

}  // namespace sphereset::detail

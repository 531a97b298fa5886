// A robot link's geometry as one triangle mesh in the link frame: mesh files loaded, scaled and
// placed by their origin, MJCF meshes as MuJoCo compiled them; primitives as meshes that contain
// them (primitive_mesh.hpp); all elements concatenated as separate shells. Also the link's
// sphere primitives as exact spheres.
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "robot/primitive_mesh.hpp"
#include "sphereset/load.hpp"
#include "sphereset/robot.hpp"

namespace sphereset {
namespace {

// Appends `part` to `out`, its vertices mapped by `to_link`. A mirroring map (negative
// determinant, e.g. one negative scale) reverses the triangles to keep them outward.
void append(Mesh& out, const Mesh& part, const Eigen::Affine3d& to_link) {
  const auto base = static_cast<int32_t>(out.vertices.size());
  const bool mirrored = to_link.linear().determinant() < 0.0;
  for (const Vec3& v : part.vertices) out.vertices.push_back(to_link * v);
  for (const Triangle& t : part.triangles) {
    out.triangles.push_back(mirrored ? Triangle{base + t[0], base + t[2], base + t[1]}
                                     : Triangle{base + t[0], base + t[1], base + t[2]});
  }
}

}  // namespace

Expected<Mesh> linkMesh(const RobotLink& link, int cylinder_segments) {
  using detail::boxMesh, detail::cylinderMesh, detail::sphereMesh;
  if (cylinder_segments < detail::kMinPrimitiveSegments) {
    return Error{ErrorCode::kInvalidArgument, "link '" + link.name + "': cylinder segments " +
                                                  std::to_string(cylinder_segments) +
                                                  " (at least 3)"};
  }
  Mesh out;
  for (const LinkGeometry& g : link.geometry) {
    Eigen::Affine3d to_link(g.origin);
    switch (g.kind) {
      case LinkGeometry::Kind::kMesh: {
        Expected<LoadedMesh> loaded = loadMesh(g.mesh_path);
        if (!loaded) {
          return Error{loaded.error().code, "link '" + link.name + "': " + loaded.error().message};
        }
        append(out, loaded->mesh, to_link * Eigen::Scaling(g.scale));
        break;
      }
      case LinkGeometry::Kind::kBox:
        append(out, boxMesh(g.box_size), to_link);
        break;
      case LinkGeometry::Kind::kCylinder:
        append(out, cylinderMesh(g.radius, g.length, cylinder_segments), to_link);
        break;
      case LinkGeometry::Kind::kSphere:
        append(out, sphereMesh(g.radius, cylinder_segments), to_link);
        break;
      case LinkGeometry::Kind::kCapsule:
        append(out, detail::capsuleMesh(g.radius, g.length, cylinder_segments), to_link);
        break;
      case LinkGeometry::Kind::kEllipsoid:
        append(out, detail::ellipsoidMesh(g.radii, cylinder_segments), to_link);
        break;
      case LinkGeometry::Kind::kTriangles:
        if (g.triangles) append(out, *g.triangles, to_link);
        break;
    }
  }
  return out;
}

std::vector<Sphere> linkSpheres(const RobotLink& link) {
  std::vector<Sphere> spheres;
  for (const LinkGeometry& g : link.geometry) {
    if (g.kind == LinkGeometry::Kind::kSphere) {
      spheres.push_back(Sphere{g.origin.translation(), g.radius});
    }
  }
  return spheres;
}

Expected<SolidInput> linkSolid(const RobotLink& link, const RepairOptions& options,
                               const std::string& name) {
  RobotLink rest = link;
  std::erase_if(rest.geometry,
                [](const LinkGeometry& g) { return g.kind == LinkGeometry::Kind::kSphere; });
  if (rest.geometry.empty())
    return Error{ErrorCode::kInvalidArgument,
                 name + ": no geometry to fit (none, or only sphere primitives)"};
  auto mesh = linkMesh(rest);
  if (!mesh) {
    // linkMesh names the link too; `name` already does.
    std::string what = mesh.error().message;
    const std::string own = "link '" + link.name + "': ";
    if (what.starts_with(own)) what.erase(0, own.size());
    return Error{mesh.error().code, name + ": " + what};
  }
  auto clean = cleanMesh(std::move(mesh->vertices), std::move(mesh->triangles), {}, name);
  if (!clean) return clean.error();
  auto r = repairMesh(clean->mesh, options, name);
  if (!r) return r.error();
  SolidInput out;
  out.loaded = std::move(clean).value();
  out.repair = std::move(r).value();
  return out;
}

}  // namespace sphereset

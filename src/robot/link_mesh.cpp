// A robot link's geometry as one triangle mesh in the link frame: mesh files loaded, scaled and
// placed by their origin; boxes, cylinders and spheres tessellated (outward, counter-clockwise
// seen from outside); all elements concatenated as separate shells. Also the link's sphere
// primitives as exact spheres.
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "sphereset/load.hpp"
#include "sphereset/robot.hpp"

namespace sphereset {
namespace {

// The fewest sides of a tessellated circle (cylinders; sphere meridians, whose rings number
// half as many).
constexpr int kMinSegments = 3;

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

// An axis-aligned box of edge lengths `size`, centred on the origin.
Mesh boxMesh(const Vec3& size) {
  Mesh m;
  const Vec3 h = 0.5 * size;
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                            (i & 4) ? h.z() : -h.z());
  }
  // Two triangles per face, counter-clockwise seen from outside.
  m.triangles = {{0, 2, 1}, {1, 2, 3},   // z = -h
                 {4, 5, 6}, {5, 7, 6},   // z = +h
                 {0, 1, 4}, {1, 5, 4},   // y = -h
                 {2, 6, 3}, {3, 6, 7},   // y = +h
                 {0, 4, 2}, {2, 4, 6},   // x = -h
                 {1, 3, 5}, {3, 7, 5}};  // x = +h
  return m;
}

// A cylinder along z of the given radius and length, centred on the origin, as a prism over a
// regular polygon of `segments` sides inscribed in the circle.
Mesh cylinderMesh(double radius, double length, int segments) {
  Mesh m;
  const double h = 0.5 * length;
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / segments;
    m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), -h);
    m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), h);
  }
  const auto bottom = static_cast<int32_t>(m.vertices.size());
  m.vertices.emplace_back(0.0, 0.0, -h);
  m.vertices.emplace_back(0.0, 0.0, h);
  const int32_t top = bottom + 1;
  for (int i = 0; i < segments; ++i) {
    const int32_t b0 = 2 * i, t0 = 2 * i + 1;
    const int32_t b1 = 2 * ((i + 1) % segments), t1 = b1 + 1;
    m.triangles.push_back({b0, b1, t1});
    m.triangles.push_back({b0, t1, t0});
    m.triangles.push_back({bottom, b1, b0});
    m.triangles.push_back({top, t0, t1});
  }
  return m;
}

// A UV sphere of `segments` meridians and segments / 2 rings, vertices on the sphere.
Mesh sphereMesh(double radius, int segments) {
  Mesh m;
  const int rings = std::max(2, segments / 2);
  m.vertices.emplace_back(0.0, 0.0, -radius);
  for (int r = 1; r < rings; ++r) {
    const double polar = std::numbers::pi * r / rings;  // from the south pole
    const double z = -radius * std::cos(polar), rho = radius * std::sin(polar);
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * std::numbers::pi * i / segments;
      m.vertices.emplace_back(rho * std::cos(a), rho * std::sin(a), z);
    }
  }
  const auto north = static_cast<int32_t>(m.vertices.size());
  m.vertices.emplace_back(0.0, 0.0, radius);
  auto at = [&](int ring, int i) {
    return static_cast<int32_t>(1 + (ring - 1) * segments + (i % segments));
  };
  for (int i = 0; i < segments; ++i) {
    m.triangles.push_back({0, at(1, i + 1), at(1, i)});
    m.triangles.push_back({north, at(rings - 1, i), at(rings - 1, i + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      m.triangles.push_back({at(r, i), at(r, i + 1), at(r + 1, i + 1)});
      m.triangles.push_back({at(r, i), at(r + 1, i + 1), at(r + 1, i)});
    }
  }
  return m;
}

}  // namespace

Expected<Mesh> linkMesh(const RobotLink& link, int cylinder_segments) {
  if (cylinder_segments < kMinSegments) {
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

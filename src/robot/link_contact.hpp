// Private: exact contact between two link solids (robot_collision.hpp's CollisionCheck::kMeshes),
// with the project's own geometry: the solid index's hierarchy for candidate triangles, the
// triangle-triangle test of the self-intersection search, and point-in-solid for containment.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"

namespace sphereset::detail {

// A link's solid in its frame: a closed mesh (may be empty) and exact spheres.
struct LinkBody {
  std::unique_ptr<SolidIndex> index;  // null when the mesh is empty
  std::vector<Sphere> spheres;
  std::vector<Vec3> shell_points;  // one vertex of each connected part of the mesh
  Sphere bound;                    // holds the mesh and the spheres
};

// The body of `mesh` and `spheres`; `bound` from both.
LinkBody makeLinkBody(const Mesh& mesh, std::vector<Sphere> spheres);

// Whether the bodies touch or one holds a point of the other, with b placed in a's frame by
// `b_in_a`. Thread-safe (read-only).
bool bodiesTouch(const LinkBody& a, const LinkBody& b, const Eigen::Isometry3d& b_in_a);

// A sphere holding all of `spheres` (not the smallest: centred on their box).
Sphere boundingSphere(const std::vector<Sphere>& spheres);

}  // namespace sphereset::detail

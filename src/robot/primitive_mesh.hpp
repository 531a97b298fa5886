// Private: robot primitives (MJCF geoms and URDF shapes) as triangle meshes that contain them.
// A box is its own mesh. The round shapes are convex polyhedra circumscribed about the shape:
// every face plane is at least the shape's radius from it, so a set of spheres that covers the
// polyhedron covers the primitive too, and the fit and its certificate, which see triangles
// only, certify the primitive. The price is volume: with 48 sides, a cylinder's prism holds
// 1/cos²(π/48) = 1.0043 times the cylinder.
#pragma once

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// The fewest sides of a tessellated circle.
inline constexpr int kMinPrimitiveSegments = 3;

// An axis-aligned box of full edge lengths `size`, centred on the origin (exact).
Mesh boxMesh(const Vec3& size);
// A cylinder along z, centred on the origin: a prism over the regular polygon of `segments`
// sides circumscribed about the circle of `radius`.
Mesh cylinderMesh(double radius, double length, int segments);
// A ball of `radius` at the origin: a polyhedron of `segments` meridians and an even number of
// rings (at least segments / 2) through points of one sphere, scaled so that its nearest face
// plane is `radius` from the centre.
Mesh sphereMesh(double radius, int segments);
// A capsule along z: the balls of `radius` at z = ±length / 2 and the cylinder between; the
// ball's polyhedron cut at its equator, its halves moved apart by `length` and joined by a band
// (the polyhedron's Minkowski sum with the segment, which holds the ball's sum with it).
Mesh capsuleMesh(double radius, double length, int segments);
// An ellipsoid of semi-axes `radii` along x, y, z: the unit ball's polyhedron scaled by them
// (an affine map keeps the ball inside its polyhedron).
Mesh ellipsoidMesh(const Vec3& radii, int segments);

}  // namespace sphereset::detail

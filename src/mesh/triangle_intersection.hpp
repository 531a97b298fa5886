// Private: the triangle–triangle test behind findSelfIntersections, exposed for the tests'
// all-pairs oracle.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// Dimensionless relative tolerance of the triangle–triangle test. For a pair of triangles,
// distances (mesh length units) below kIntersectionRelTol × the longest edge of the two count
// as zero: a point that close to a plane is on it, that close to an edge line is on it. Also
// the sine of the angular tolerance of the coplanar wedge test, and the height/longest-edge
// ratio below which a triangle is degenerate (skipped).
constexpr double kIntersectionRelTol = 1e-10;

struct TriangleGeometry {
  Vec3 normal = Vec3::Zero();  // unit, counter-clockwise; zero when degenerate
  double longest_edge = 0.0;
  bool degenerate = true;
};

TriangleGeometry triangleGeometry(const Vec3& a, const Vec3& b, const Vec3& c);

// Whether triangles i and j of the mesh share a point other than a common vertex or a common
// edge (by vertex index). Degenerate triangles never intersect anything.
bool trianglesIntersect(const Mesh& mesh, int32_t i, int32_t j, const TriangleGeometry& gi,
                        const TriangleGeometry& gj);

// Whether two triangles given by their corners, with no vertex in common (e.g. of two different
// meshes), share a point: the no-shared-vertex case of trianglesIntersect, same tolerance.
// Degenerate triangles never intersect anything.
bool separateTrianglesIntersect(const Vec3 (&a)[3], const Vec3 (&b)[3], const TriangleGeometry& ga,
                                const TriangleGeometry& gb);

// Every pair (i < j, sorted) for which trianglesIntersect holds, by testing all pairs: O(n²).
std::vector<std::array<int32_t, 2>> selfIntersectionsAllPairs(const Mesh& mesh);

}  // namespace sphereset::detail

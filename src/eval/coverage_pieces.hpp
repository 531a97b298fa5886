// Private: the pieces of the coverage certificates, shared by the full evaluation
// (evaluate.cpp) and the incremental certificate (incremental_certificate.cpp), so that both
// give the same verdicts by construction: the sphere checks, the grown spheres, the verdict on
// one triangle, and the sums over triangles and cells. (The verdict on one interior cube is
// cellVerdict in cover/cover_cells.hpp, shared with the fit's bound.)
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cover/sphere_grid.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

// kInvalidArgument when a set of `count` spheres cannot be certified: "no spheres to evaluate",
// or more than limits::kMaxSpheres.
Status checkSphereCount(size_t count);
// kInvalidArgument "sphere `index` has a NaN, infinite or negative value".
Status checkSphere(const Sphere& sphere, size_t index);
// Both, for every sphere of the set.
Status checkSpheres(const std::vector<Sphere>& spheres);

// The spheres the certificates test: radii grown by the rounding tolerance (cover.hpp,
// kCoverageToleranceRel) of the solid's bounding-box diagonal.
Sphere grownSphere(const Sphere& sphere, double diag);
std::vector<Sphere> grownSpheres(const std::vector<Sphere>& spheres, double diag);

// The certificate of one triangle (or one interior root cube): the largest gap found from its
// points to the union (a length, 0 when certified) and what was left undecided (an area for a
// triangle, a count of finest cells for the interior).
struct PieceCover {
  double gap = 0.0;
  double uncertified = 0.0;
  bool uncovered() const { return gap > 0.0 || uncertified > 0.0; }
};

// A triangle is certified when one sphere holds its three vertices (convexity), otherwise split
// in four down to max_depth. Any vertex or centroid outside every sphere refutes it and gives a
// gap; the split then goes on to half the depth only, to refine the gap a little.
PieceCover certifyTriangle(const SphereGrid& grown, const Vec3& a, const Vec3& b, const Vec3& c,
                           int max_depth);
PieceCover certifyTriangle(const SphereGrid& grown, const Mesh& mesh, size_t triangle,
                           int max_depth);

// The surface certificate of a mesh from the certificates of its triangles (in triangle order).
struct SurfaceCover {
  bool covered = false;
  double max_gap = 0.0;  // / diag
  double uncertified = 0.0;
  int64_t uncovered = 0;
};
// `uncovered_ids`, when given, receives the uncovered triangles in increasing order.
SurfaceCover summarizeSurface(std::span<const PieceCover> triangles, size_t spheres, double diag,
                              std::vector<int64_t>* uncovered_ids = nullptr);

// The interior certificate from the certificates of its root cubes: the largest gap / diag and
// the undecided finest cells; covered when there is no gap and the surface is covered.
struct InteriorCover {
  bool covered = false;
  double max_gap = 0.0;  // / diag
  int64_t uncertified_cells = 0;
};
InteriorCover summarizeInterior(std::span<const PieceCover> roots, size_t spheres, double diag,
                                bool surface_covered);

}  // namespace sphereset::detail

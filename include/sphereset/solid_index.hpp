// A bounding-volume hierarchy over the triangles of a closed mesh, answering the queries the
// rest of the library is built on: exact outside volume of a ball, point-in-solid,
// distance to the surface and segment crossings.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/sphere.hpp"

namespace sphereset {

enum class Containment { kOutside, kInside, kBoundary };

// Result of one outside-volume query, with both derivatives from the same pass.
struct OutsideVolume {
  double volume = 0.0;           // SOV(o, r): volume of the ball outside the solid
  double d_radius = 0.0;         // dSOV/dr: area of the sphere's surface outside the solid
  Vec3 gradient = Vec3::Zero();  // dSOV/do at fixed r: Σ area(t ∩ B) n_t
  // Closed-form kernel evaluations: triangles met by the ball, plus the boundary fans of
  // hierarchy nodes wholly inside it (whose triangles are summed in one go).
  int64_t triangles_tested = 0;
  Containment center = Containment::kOutside;
};

// The first surface point met by a ray.
struct RayHit {
  double t = 0.0;              // ray parameter (in units of the direction vector)
  int32_t triangle = -1;       // original triangle index
  Vec3 normal = Vec3::Zero();  // the triangle's outward unit normal
};

class SolidIndex {
 public:
  // The mesh is copied into the index (in the hierarchy's order); it should be a closed,
  // outward-oriented solid for the volume and containment queries to be meaningful.
  explicit SolidIndex(const Mesh& mesh);
  ~SolidIndex();
  SolidIndex(SolidIndex&&) noexcept;
  SolidIndex& operator=(SolidIndex&&) noexcept;

  // Exact outside volume of a ball and its derivatives (paper Sec. 4, in closed form).
  OutsideVolume outsideVolume(const Sphere& ball) const;

  // Point in solid by signed ray crossings (non-zero winding rule). Points within
  // boundaryTolerance() of the surface are kBoundary.
  Containment classify(const Vec3& p) const;

  // Unsigned distance from p to the surface, and the closest triangle (original index).
  double distance(const Vec3& p, int32_t* closest_triangle = nullptr) const;

  // Parameters t in (0, 1) where the segment a + t (b - a) meets a triangle, sorted.
  std::vector<double> segmentCrossings(const Vec3& a, const Vec3& b) const;
  // Closest hit of the ray o + t d with t_min < t <= t_max (edges and vertices count as hits).
  bool raycast(const Vec3& o, const Vec3& d, double t_min, double t_max, RayHit* hit) const;
  // Whether the ray o + t d, t_min < t <= t_max, meets the surface at all (stops at the first hit).
  bool occluded(const Vec3& o, const Vec3& d, double t_min, double t_max) const;
  // Length of the part of segment [a, b] that lies outside the solid.
  double outsideLength(const Vec3& a, const Vec3& b) const;

  // Frees the answers the index remembers (up to about 6.5 MB once it answered outside-volume
  // queries, sov_memo.hpp); later queries give the same answers and remember anew. For a caller
  // that holds many indices and is done with one for now (a robot's links). Not concurrently
  // with queries on the same index.
  void forgetAnswers() const;

  const Mesh& mesh() const;  // the original mesh
  const Aabb& bounds() const;
  double boundaryTolerance() const;
  int64_t nodeCount() const;

  struct Impl;                                 // opaque; defined in the library's sources
  const Impl& impl() const { return *impl_; }  // for the library's own sources

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace sphereset

// What makes a triangle mesh fail to be a solid beyond its edge topology: triangles that cross
// each other, and how its closed shells sit relative to each other (apart, overlapping or
// nested). The fit's repair (repair.hpp) decides from these what to do.
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset {

struct SelfIntersectionOptions {
  // Stop collecting after this many intersecting pairs (the count is then a lower bound). The
  // pairs kept are the max_pairs smallest, so a truncated result is deterministic too.
  int64_t max_pairs = 100000;
};

// Pairs of triangles that share a point other than a common vertex or a common edge: crossing
// triangles, and coplanar triangles that overlap (a duplicated or folded face). Vertices are
// shared by index; contact within a relative tolerance (kIntersectionRelTol in
// src/mesh/triangle_intersection.hpp, times the longest edge of the pair) counts. Degenerate
// (zero-area) triangles are skipped.
struct SelfIntersections {
  std::vector<std::array<int32_t, 2>> pairs;  // (a, b) with a < b, sorted
  bool truncated = false;                     // max_pairs was reached
  bool any() const { return !pairs.empty(); }
};

SelfIntersections findSelfIntersections(const Mesh& mesh,
                                        const SelfIntersectionOptions& options = {});

// One edge-connected component of a mesh.
struct Shell {
  std::vector<int32_t> triangles;  // indices into the mesh
  bool closed = false;             // no boundary edges
  bool manifold = false;           // no non-manifold edges or vertices
  bool oriented = false;           // every edge traversed once each way
  bool self_intersecting = false;  // two of its own triangles intersect
  double volume = 0.0;             // signed; negative for an inward-facing shell
  Aabb bbox;
  // The innermost other shell that contains this one (both closed, not intersecting each
  // other), or -1. Containment is decided at one point of this shell (the centroid of its
  // largest triangle) by the container's winding number.
  int32_t parent = -1;
  int depth = 0;  // number of shells that contain it

  // Closed, manifold, oriented and free of self-intersections: it bounds a solid by itself.
  bool clean() const { return closed && manifold && oriented && !self_intersecting; }
};

struct ShellAnalysis {
  std::vector<Shell> shells;
  // Pairs of shells whose triangles intersect (i < j, sorted).
  std::vector<std::array<int32_t, 2>> intersecting;
  SelfIntersections intersections;  // of the whole mesh
};

ShellAnalysis analyzeShells(const Mesh& mesh, const SelfIntersectionOptions& options = {});

// What `check` reports of an analysis: shells, and of them closed, clean (closed, oriented,
// free of crossings), closed and inward, nested in another; intersecting shell pairs, crossing
// triangle pairs and whether their search stopped at its cap.
struct ShellCounts {
  int64_t shells = 0, closed = 0, clean = 0, inward = 0, nested = 0, intersecting_pairs = 0;
  int64_t triangle_pairs = 0;
  bool truncated = false;
};
ShellCounts countShells(const ShellAnalysis& sa);

// The mesh made of the given triangles of `mesh` (unused vertices dropped).
Mesh submesh(const Mesh& mesh, const std::vector<int32_t>& triangles);

}  // namespace sphereset

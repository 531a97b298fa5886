// Private: the guaranteed-bounding step of the fit.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "cover/cover_cells.hpp"
#include "sphereset/cover.hpp"
#include "sphereset/solid_index.hpp"
#include "util/poll.hpp"

namespace sphereset::detail {

struct BoundStats {
  int64_t enlarged = 0;  // spheres whose radius grew
  int64_t pieces = 0;    // triangle pieces that needed an enlargement
  int64_t queries = 0;   // outside-volume evaluations
};

// Splits triangle (a, b, c) in four, recursively, until settled(piece) says a piece needs no
// more work; a piece still unsettled when its longest edge is at most min_edge (or after
// kSurfaceSplitDepth splits) goes to small(piece).
template <class Settled, class Small>
void splitPieces(const Vec3& a, const Vec3& b, const Vec3& c, double min_edge, Settled&& settled,
                 Small&& small) {
  struct Piece {
    std::array<Vec3, 3> v;
    int depth;
  };
  std::vector<Piece> todo{{{a, b, c}, 0}};
  while (!todo.empty()) {
    pollCancel();
    const Piece pc = todo.back();
    todo.pop_back();
    if (settled(pc.v)) continue;
    const auto& [p, q, r] = pc.v;
    const double edge = std::max({(q - p).norm(), (r - q).norm(), (p - r).norm()});
    if (edge <= min_edge || pc.depth >= kSurfaceSplitDepth) {
      small(pc.v);
      continue;
    }
    const Vec3 pq = 0.5 * (p + q), qr = 0.5 * (q + r), rp = 0.5 * (r + p);
    todo.push_back({{p, pq, rp}, pc.depth + 1});
    todo.push_back({{pq, q, qr}, pc.depth + 1});
    todo.push_back({{rp, qr, r}, pc.depth + 1});
    todo.push_back({{pq, qr, rp}, pc.depth + 1});
  }
}

// Radii get this fraction of the bounding-box diagonal on top of the exact requirement, so
// that the containment of vertices survives rounding (the bound's and the optimal radii's).
inline constexpr double kBoundSlackRel = 1e-12;

// How many pieces splitting every triangle of `mesh` in four (as splitPieces does) until its
// edges are at most `edge` makes.
double splitPieceCount(const Mesh& mesh, double edge);

// How boundSurface splits and what it reports.
struct SurfaceBoundOptions {
  // Pieces are split until their longest edge is at most this (absolute units).
  double min_edge = 0.0;
  // If given, (*held)[i] receives the vertices of the pieces sphere i was enlarged for (or
  // their centroids, with held_centroids).
  std::vector<std::vector<Vec3>>* held = nullptr;
  bool held_centroids = false;
  // With `held`: only the pieces of the spheres marked here are kept (null: every sphere's; else
  // one flag per sphere); a local bound that refits two spheres keeps no others' (left empty).
  const std::vector<bool>* held_for = nullptr;
  // The triangles covered: those of `surface`, or of the index's mesh when it is null.
  const Mesh* surface = nullptr;
};

// Enlarges spheres until every point of every triangle lies in some sphere: each triangle is
// split in four until each piece has its three vertices in one sphere (then the piece is
// inside it, by convexity) or is shorter than `min_edge`; such a piece is given to the sphere whose
// outside volume grows least when enlarged to hold its vertices. The evaluation's certificate
// splits the same way, as deep (kSurfaceSplitDepth), so it confirms what the bound proves: every
// piece given to a sphere is a node of its tree.
BoundStats boundSurface(const SolidIndex& index, std::vector<Sphere>* spheres,
                        const SurfaceBoundOptions& options);

inline BoundStats boundSurface(const SolidIndex& index, std::vector<Sphere>* spheres,
                               double min_edge, std::vector<std::vector<Vec3>>* held = nullptr,
                               const Mesh* surface = nullptr) {
  SurfaceBoundOptions o;
  o.min_edge = min_edge;
  o.held = held;
  o.surface = surface;
  return boundSurface(index, spheres, o);
}

// Interior coverage on the octree of cover_cells.hpp (the same test `evaluateSpheres` runs):
// cubes down to `max_depth` whose centre lies inside the solid but in no sphere are handed
// whole to the sphere whose outside volume grows least. One pass; radii only grow. With
// `region`, only the cubes that meet it are walked (a local bound: nothing outside it lost its
// cover). With `cells` (kept by a caller that bounds the same solid again), the cubes' geometry
// is taken from it and kept there (cover_cells.hpp, GeometryTree): the same spheres either way.
BoundStats boundInterior(const SolidIndex& index, std::vector<Sphere>* spheres, int max_depth,
                         const Aabb* region = nullptr, GeometryForest* cells = nullptr);

// For each sphere, what it alone covers: the vertices of the surface pieces (triangles split
// until one sphere holds each piece, as in boundSurface) that no other sphere holds, and the
// given interior points no other sphere contains. A sphere refitted around these keeps
// everything covered that only it covered. The triangles are `surface`'s when given (else the
// solid's). With `only` (a sphere's index), only that sphere's list is made: pieces whose box
// misses it are not split further (the other lists are then incomplete).
std::vector<std::vector<Vec3>> soleCover(const SolidIndex& index, const std::vector<Sphere>& sp,
                                         const std::vector<Vec3>& interior, double min_edge,
                                         const Mesh* surface = nullptr, int only = -1);

}  // namespace sphereset::detail

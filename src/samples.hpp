// Private: the points that the fit clusters (paper Sec. 5, "Preprocessing").
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

struct PointSet {
  std::vector<Vec3> points;  // interior grid points first, then surface samples
  int64_t interior = 0;      // how many of `points` are interior grid points
  double spacing = 0.0;      // grid spacing of the interior points
  // Flood-fill adjacency (CSR): neighbours of point i are adj[adj_start[i] .. adj_start[i+1]).
  std::vector<int32_t> adj_start, adj;
  double cell = 0.0;  // the adjacency's cell size
};

// (Re)builds the adjacency: neighbours are points closer than 1.8 cells.
void buildAdjacency(PointSet* ps, double cell);

// Interior points on a regular grid of cell centres (robust point-in-solid), about
// target * interior_share of them, refined when the solid is too thin to hold them; surface
// points sampled in proportion to triangle area (seeded); adjacency between points closer
// than about 1.8 grid cells.
PointSet samplePoints(const SolidIndex& index, int64_t target, double interior_share,
                      uint64_t seed);

}  // namespace sphereset::detail

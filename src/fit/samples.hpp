// Private: the points that the fit clusters (paper Sec. 5, "Preprocessing").
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "sphereset/solid_index.hpp"
#include "util/cell_key.hpp"

namespace sphereset::detail {

// Points bucketed in a uniform grid of cubic cells (cell_key.hpp), for nearest-point queries.
class PointGrid {
 public:
  PointGrid() = default;
  PointGrid(const std::vector<Vec3>& points, double cell);
  // The point of `points` (the ones the grid was built on) nearest `q`, the lowest index
  // among equally near ones, as a scan of all points would find it; -1 if there are none.
  int64_t nearest(const std::vector<Vec3>& points, const Vec3& q) const;

 private:
  double cell_ = 0.0;
  CellKey lo_{}, hi_{};          // occupied cell range
  std::vector<int32_t> sorted_;  // point indices grouped by cell
  std::unordered_map<CellKey, std::pair<int32_t, int32_t>, CellKeyHash> cells_;
};

struct PointSet {
  std::vector<Vec3> points;  // interior grid points first, then surface samples
  int64_t interior = 0;      // how many of `points` are interior grid points
  double spacing = 0.0;      // grid spacing of the interior points
  // Flood-fill adjacency (CSR): neighbours of point i are adj[adj_start[i] .. adj_start[i+1]).
  std::vector<int32_t> adj_start, adj;
  double cell = 0.0;  // the adjacency's cell size
  PointGrid grid;     // over `points`, cells of size `cell`
};

// The spacing of the surface samples of `ps`, sqrt(surface area / their count) (the area's
// square root when there are none), and the bound's smallest pieces as the fit sizes them: half
// the smaller of it and the interior grid's spacing.
double surfaceSpacing(const SolidIndex& index, const PointSet& ps);
double boundMinEdge(const SolidIndex& index, const PointSet& ps);

// (Re)builds the adjacency: neighbours are points closer than 1.8 cells.
void buildAdjacency(PointSet* ps, double cell);

// Interior points on a regular grid of cell centres (robust point-in-solid), about
// target * interior_share of them, refined when the solid is too thin to hold them; surface
// points sampled in proportion to triangle area (seeded); adjacency between points closer
// than about 1.8 grid cells.
PointSet samplePoints(const SolidIndex& index, int64_t target, double interior_share,
                      uint64_t seed);

}  // namespace sphereset::detail

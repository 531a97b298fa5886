// Private: a fit one sphere larger or smaller by a single local split or removal
// (ProgressiveFit::step).
#pragma once

#include <limits>
#include <vector>

#include "cover/cover_cells.hpp"
#include "fit/samples.hpp"
#include "fit/sphere_update.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// A point set split in two by 2-means from its farthest pair, both halves refitted (the sphere
// update, Eq. 5); `ok` false when a half came out empty (fewer than two distinct points).
struct PointSplit {
  bool ok = false;
  std::vector<Vec3> a, b;
  SphereUpdate ua, ub;
};
PointSplit splitPoints(const SolidIndex& index, const std::vector<Vec3>& points,
                       const FitOptions& o);

// A bounded fit that local splits grow one sphere at a time: its spheres as returned (padded),
// each one's outside volume, and each one's split once measured (kept until a step changes
// what it alone covers).
struct SplitChain {
  int count = 0;
  std::vector<Sphere> spheres;
  std::vector<double> sov;
  std::vector<PointSplit> splits;
  std::vector<double> gain;     // the outside volume its split would save (padded, as `sov`)
  std::vector<double> removal;  // the outside volume its removal would add, to first order
  std::vector<bool> split_measured, removal_measured;
};

// The chain of a finished fit: its padded spheres and their outside volumes.
SplitChain startChain(std::vector<Sphere> spheres, std::vector<double> sov);

// One sphere more: the sphere whose split lowers the outside volume most (what it alone covers,
// split in two and each half refitted) is replaced by its two halves, and the solid within its old
// box is bounded again (bound.cpp, restricted: nothing outside that box lost its cover, since every
// other sphere only grows). Fills res (spheres, outside volumes, energy, bound counters and
// seconds: bound for the local bound, teleport for measuring). False when no sphere can be split:
// the chain's measures are then up to date, its set unchanged. `cells`: the interior cubes'
// geometry kept between the bounds of one solid (boundInterior), or none.
bool splitLocally(const SolidIndex& index, const PointSet& ps, const FitOptions& o,
                  SplitChain* chain, FitResult* res, GeometryForest* cells = nullptr);

// One sphere fewer: the sphere whose removal adds least outside volume (what it alone covers
// taken by the neighbours that grow least) is removed, the last sphere taking its index, and the
// solid within its old box is bounded again by the others growing. False when no sphere can be
// removed: the chain's measures are then up to date, its set unchanged. `cells` as for
// splitLocally.
bool removeLocally(const SolidIndex& index, const PointSet& ps, const FitOptions& o,
                   SplitChain* chain, FitResult* res, GeometryForest* cells = nullptr);

}  // namespace sphereset::detail

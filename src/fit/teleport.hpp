// Private: sphere teleportation of the fit (paper Sec. 5, "Sphere Teleportation"): choosing a
// move, the removal costs it shares with the decimation, and the 2-means split of a cluster.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// A teleport candidate: sphere `src` leaves its place and, with `dst`, splits dst's cluster.
struct TeleportMove {
  int src = -1, dst = -1;
  Vec3 src_centre, dst_centre;  // where the two start
  double predicted = 0.0;       // predicted decrease of the energy
};

// A sphere's split, kept while its points stay the same.
struct SplitCache {
  std::vector<Vec3> members;
  bool valid = false;
  double halves_sov = 0.0;  // outside volume of the two refitted halves
  Vec3 ca, cb;
};

// Splits points in two: 2-means from the farthest pair. Either half can come out empty.
void splitTwoMeans(const std::vector<Vec3>& pts, std::vector<Vec3>* a, std::vector<Vec3>* b);

// For each sphere, an upper bound on the change of the energy if it is removed: each of its
// points joins the other sphere it sticks out of least (ties: lower index), and those spheres
// grow about fixed centres (one outside-volume query per grown sphere, counted in q[i]).
// If `receivers` is given, (*receivers)[i] lists the spheres that would grow.
std::vector<double> removalCosts(const SolidIndex& index, const std::vector<Sphere>& sp,
                                 const std::vector<std::vector<Vec3>>& members,
                                 const std::vector<double>& sov, std::vector<int64_t>* q,
                                 std::vector<std::vector<int>>* receivers);

// The most promising teleport not in `tried`, or none: pairs are ranked by the destination's
// gain from being split minus the source's cost of removal (ties: lower destination, then
// lower source). `cache` keeps the splits of clusters whose points did not change; the
// outside-volume queries spent are added to *queries.
std::optional<TeleportMove> bestTeleport(const SolidIndex& index, const std::vector<Sphere>& sp,
                                         const std::vector<std::vector<Vec3>>& members,
                                         const std::vector<double>& sov, SphereOptimizer optimizer,
                                         int evaluations,
                                         const std::vector<std::pair<int, int>>& tried,
                                         std::vector<SplitCache>* cache, int64_t* queries);

}  // namespace sphereset::detail

// Private: point assignment by least outside-volume increase (paper Sec. 5).
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "fit/samples.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

struct Cluster {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;  // smallest radius about `center` enclosing the assigned points
  double sov = 0.0;     // SOV(center, radius)
  // Known values of SOV(table_center, ·) at increasing radii: exact at those radii, lower
  // bounds for larger ones, since the outside volume never decreases with the radius. Kept
  // across calls while the centre stays where it is.
  std::vector<std::pair<double, double>> table;
  Vec3 table_center = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
};

struct AssignStats {
  int64_t queries = 0;  // exact outside-volume evaluations
  int64_t culled = 0;   // candidate clusters dismissed by their lower bound
  int64_t reused = 0;   // evaluations answered by a cluster's table (same centre and radius)
};

// Assigns every point to the cluster whose sphere grows least in outside volume, in
// breadth-first flood-fill order from the points nearest the centres; ties go to the nearest
// centre.
// Centres stay fixed; radii and outside volumes grow as points are added. labels[i] is the
// cluster of point i. A cluster whose centre has not moved since the last call keeps its
// table of outside volumes.
void assignPoints(const SolidIndex& index, const PointSet& ps, std::vector<Cluster>* clusters,
                  std::vector<int32_t>* labels, AssignStats* stats);

}  // namespace sphereset::detail

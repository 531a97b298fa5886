// Private: the queries of sphereset/query.hpp over a plain vector, looping over every sphere
// (or pair). The tests' oracles and the benchmarks' baselines.
#pragma once

#include <vector>

#include "sphereset/query.hpp"

namespace sphereset {

PointQuery pointDistanceBruteForce(const std::vector<Sphere>& spheres, const Vec3& p);
bool containsPointBruteForce(const std::vector<Sphere>& spheres, const Vec3& p);

double segmentOutsideLengthBruteForce(const std::vector<Sphere>& spheres, const Vec3& a,
                                      const Vec3& b);

PairQuery separationBruteForce(const std::vector<Sphere>& a, const Pose& pose_a,
                               const std::vector<Sphere>& b, const Pose& pose_b);
bool overlapsBruteForce(const std::vector<Sphere>& a, const Pose& pose_a,
                        const std::vector<Sphere>& b, const Pose& pose_b);

}  // namespace sphereset

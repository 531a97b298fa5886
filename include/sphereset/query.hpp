// Queries on sphere sets and sphere trees (paper Sec. 7 "Proximity Application", and the
// collision queries users run on sphere-trees). Tree queries visit a node's children only
// when the node itself can matter, which is sound because every parent encloses its
// children. Their brute-force twins, the tests' oracles, are private (src/tree/query_oracles.hpp).
//
// Every query checks its points and poses: coordinates must be finite and at most
// limits::kMaxCoordinate in magnitude (kInvalidArgument otherwise, naming the input), so that
// no answer is silently NaN or infinite. Trees are checked where they are made (readers,
// buildSphereTree).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sphereset/sphere.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// A rigid motion x -> rotation * x + translation (rotation orthonormal, det +1).
struct Pose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();
  Vec3 apply(const Vec3& x) const { return rotation * x + translation; }
};

// Signed distance from a point to a sphere set: min_i (|p - c_i| - r_i). It is the exact
// Euclidean distance to the union when positive (the point is outside every sphere); when
// it is <= 0 the point is inside and its magnitude is the largest depth inside one sphere.
struct PointQuery {
  double distance = 0.0;
  int64_t sphere = -1;  // the sphere attaining it: slot id in a tree, position in a vector
  int64_t visited = 0;  // spheres or nodes examined
};
Expected<PointQuery> pointDistance(const SphereTree& tree, const Vec3& p);
Expected<bool> containsPoint(const SphereTree& tree, const Vec3& p);

// Length of segment [a, b] outside the union of the leaf spheres (paper Sec. 7: the 1D
// intervals where the segment is inside some sphere are merged, overlaps counted once).
Expected<double> segmentOutsideLength(const SphereTree& tree, const Vec3& a, const Vec3& b);

// Between two sets, each under its own pose: the signed distance of the closest pair of leaf
// spheres, min |c_a - c_b| - r_a - r_b (negative when they overlap; then the magnitude is the
// deepest pairwise penetration), with that pair.
struct PairQuery {
  double distance = 0.0;
  int64_t sphere_a = -1, sphere_b = -1;  // slot ids (trees) or positions (vectors)
  int64_t visited = 0;                   // node or sphere pairs examined
};
Expected<PairQuery> separation(const SphereTree& a, const Pose& pose_a, const SphereTree& b,
                               const Pose& pose_b);
// Whether any two leaf spheres overlap (distance < 0); stops at the first such pair, which is
// returned in *pair when given (its distance field is that pair's signed distance).
Expected<bool> overlaps(const SphereTree& a, const Pose& pose_a, const SphereTree& b,
                        const Pose& pose_b, PairQuery* pair = nullptr);

// A pose's translation within limits::kMaxCoordinate and its rotation orthonormal with
// determinant +1 (to kPoseRotationTolerance); kInvalidArgument naming `what` otherwise.
inline constexpr double kPoseRotationTolerance = 1e-6;  // max |RᵀR - I| entry, and |det R - 1|
Status checkPose(const std::string& what, const Pose& pose);

// A query tree over a plain set: median splits along the largest extent (O(n log n) for any set,
// identical spheres included), minimal enclosing parents, `branching` children per node (2 to
// kMaxQueryBranching), as deep as needed. Every sphere must pass checkSphere; an empty set gives
// an empty tree (nothing is inside it). A set larger than the layout holds
// (maxQueryTreeSpheres) is refused: kInvalidArgument, never an empty tree. `leaf_index`, when
// given, receives for each slot the sphere's position in `spheres` (-1 for other slots).
inline constexpr int kMaxQueryBranching = 1024;
Expected<SphereTree> queryTree(const std::vector<Sphere>& spheres, int branching = 8,
                               std::vector<int64_t>* leaf_index = nullptr);
// The most spheres a query tree of `branching` holds within SphereTree::kMaxSlots.
int64_t maxQueryTreeSpheres(int branching);

// The tree every door queries for a tree read from a file or made by a user: the tree itself
// when the queries' rule holds (every used parent encloses its children: checkSphereTree) and it
// has two levels or more, else a query tree over its leaves. A file's parents need not enclose
// their children (a tree edited level by level in the view, another tool's tree): queried as
// they are, a point inside a leaf would be "outside". `slot_of`, when given, receives for each
// slot of the answer the slot of the same leaf in `tree` (left empty when the tree is used as it
// is: slots are the tree's own).
Expected<SphereTree> queryTreeOf(const SphereTree& tree, std::vector<int64_t>* slot_of = nullptr);

}  // namespace sphereset

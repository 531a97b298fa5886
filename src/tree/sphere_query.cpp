// Queries on sphere sets and trees. References: Wang et al. 2006, Sec. 7 "Proximity
// Application" (outside length of a segment from the union of the 1D intervals inside the
// spheres); Hubbard 1996 / Bradshaw-O'Sullivan 2004 for sphere-tree traversal.
//
// Every bound below rests on one fact: a parent P encloses each child C, so
// |x - c_C| - r_C >= |x - c_P| - r_P for any point x, and for two pairs of nested spheres
// |c_A - c_B| - r_A - r_B >= |c_PA - c_PB| - r_PA - r_PB. Nodes are examined best first (least
// bound first) and pruned once their bound cannot beat the best leaf found.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <span>
#include <string>

#include "cover/segment_cover.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/query.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/tree.hpp"
#include "tree/median_tree.hpp"
#include "tree/query_oracles.hpp"
#include "util/ray_sphere.hpp"

namespace sphereset {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double signedGap(const Sphere& s, const Vec3& p) { return (p - s.center).norm() - s.radius; }

bool isLeafSlot(const SphereTree& t, int64_t node) { return node >= t.levelBegin(t.depth); }

Sphere placed(const Sphere& s, const Pose& pose) { return {pose.apply(s.center), s.radius}; }

double pairGap(const Sphere& a, const Sphere& b) {
  return (a.center - b.center).norm() - a.radius - b.radius;
}

Status checkPoint(const char* what, const Vec3& p) {
  return limits::checkCoordinates(what, std::span<const double>(p.data(), 3));
}

}  // namespace

PointQuery pointDistanceBruteForce(const std::vector<Sphere>& spheres, const Vec3& p) {
  PointQuery q;
  q.distance = kInf;
  for (size_t i = 0; i < spheres.size(); ++i) {
    const double g = signedGap(spheres[i], p);
    ++q.visited;
    if (g < q.distance) {
      q.distance = g;
      q.sphere = static_cast<int64_t>(i);
    }
  }
  return q;
}

Expected<PointQuery> pointDistance(const SphereTree& t, const Vec3& p) {
  if (Status st = checkPoint("point", p); !st) return st.error();
  PointQuery q;
  q.distance = kInf;
  if (t.nodes.empty() || !t.used(0)) return q;
  using Item = std::pair<double, int64_t>;  // (bound, node)
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  open.push({signedGap(t.nodes[0], p), 0});
  while (!open.empty()) {
    const auto [bound, node] = open.top();
    open.pop();
    if (bound >= q.distance) break;
    ++q.visited;
    if (isLeafSlot(t, node)) {
      q.distance = bound;
      q.sphere = node;
      continue;
    }
    for (int i = 0; i < t.branching; ++i) {
      const int64_t c = t.child(node, i);
      if (!t.used(c)) continue;
      const double g = signedGap(t.nodes[c], p);
      if (g < q.distance) open.push({g, c});
    }
  }
  return q;
}

bool containsPointBruteForce(const std::vector<Sphere>& spheres, const Vec3& p) {
  for (const Sphere& s : spheres)
    if (s.contains(p)) return true;
  return false;
}

Expected<bool> containsPoint(const SphereTree& t, const Vec3& p) {
  if (Status st = checkPoint("point", p); !st) return st.error();
  if (t.nodes.empty() || !t.used(0)) return false;
  std::vector<int64_t> stack{0};
  while (!stack.empty()) {
    const int64_t node = stack.back();
    stack.pop_back();
    if (!t.nodes[node].contains(p)) continue;
    if (isLeafSlot(t, node)) return true;
    for (int i = 0; i < t.branching; ++i) {
      const int64_t c = t.child(node, i);
      if (t.used(c)) stack.push_back(c);
    }
  }
  return false;
}

double segmentOutsideLengthBruteForce(const std::vector<Sphere>& spheres, const Vec3& a,
                                      const Vec3& b) {
  return detail::segmentOutsideSpheres(spheres, a, b);
}

Expected<double> segmentOutsideLength(const SphereTree& t, const Vec3& a, const Vec3& b) {
  if (Status st = checkPoint("segment start", a); !st) return st.error();
  if (Status st = checkPoint("segment end", b); !st) return st.error();
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  if (!(dd > 0.0) || t.nodes.empty() || !t.used(0)) return std::sqrt(std::max(dd, 0.0));
  std::vector<std::pair<double, double>> in;
  std::vector<int64_t> stack{0};
  double t0, t1;
  while (!stack.empty()) {
    const int64_t node = stack.back();
    stack.pop_back();
    // A node the segment does not enter holds no leaf the segment enters.
    if (!detail::segmentInterval(t.nodes[node], a, d, &t0, &t1)) continue;
    if (isLeafSlot(t, node)) {
      in.emplace_back(t0, t1);
      continue;
    }
    for (int i = 0; i < t.branching; ++i) {
      const int64_t c = t.child(node, i);
      if (t.used(c)) stack.push_back(c);
    }
  }
  return detail::uncoveredLength(&in, std::sqrt(dd));
}

PairQuery separationBruteForce(const std::vector<Sphere>& a, const Pose& pose_a,
                               const std::vector<Sphere>& b, const Pose& pose_b) {
  PairQuery q;
  q.distance = kInf;
  std::vector<Sphere> wb(b.size());
  for (size_t j = 0; j < b.size(); ++j) wb[j] = placed(b[j], pose_b);
  for (size_t i = 0; i < a.size(); ++i) {
    const Sphere wa = placed(a[i], pose_a);
    for (size_t j = 0; j < b.size(); ++j) {
      ++q.visited;
      const double g = pairGap(wa, wb[j]);
      if (g < q.distance) {
        q.distance = g;
        q.sphere_a = static_cast<int64_t>(i);
        q.sphere_b = static_cast<int64_t>(j);
      }
    }
  }
  return q;
}

bool overlapsBruteForce(const std::vector<Sphere>& a, const Pose& pose_a,
                        const std::vector<Sphere>& b, const Pose& pose_b) {
  for (const Sphere& x : a) {
    const Sphere wa = placed(x, pose_a);
    for (const Sphere& y : b)
      if (pairGap(wa, placed(y, pose_b)) < 0.0) return true;
  }
  return false;
}

namespace {

// Children of a node in world coordinates (the node itself when it is a leaf, so that the
// other tree descends alone).
struct Side {
  const SphereTree* t;
  const Pose* pose;
  bool leaf(int64_t n) const { return isLeafSlot(*t, n); }
  Sphere world(int64_t n) const { return placed(t->nodes[n], *pose); }
};

// Best-first (separation) or depth-first with early exit (overlap) dual traversal.
PairQuery dualTraversal(const Side& sa, const Side& sb, bool stop_at_overlap, bool* found) {
  PairQuery q;
  q.distance = kInf;
  if (found) *found = false;
  if (sa.t->nodes.empty() || sb.t->nodes.empty() || !sa.t->used(0) || !sb.t->used(0)) return q;
  struct Item {
    double bound;
    int64_t na, nb;
    Sphere wa, wb;
  };
  auto cmp = [](const Item& x, const Item& y) { return x.bound > y.bound; };
  std::priority_queue<Item, std::vector<Item>, decltype(cmp)> open(cmp);
  std::vector<Item> stack;
  const Sphere ra = sa.world(0), rb = sb.world(0);
  const Item root{pairGap(ra, rb), 0, 0, ra, rb};
  if (stop_at_overlap)
    stack.push_back(root);
  else
    open.push(root);
  const double limit = stop_at_overlap ? 0.0 : kInf;
  while (stop_at_overlap ? !stack.empty() : !open.empty()) {
    Item it;
    if (stop_at_overlap) {
      it = stack.back();
      stack.pop_back();
    } else {
      it = open.top();
      open.pop();
    }
    if (it.bound >= std::min(q.distance, limit)) {
      if (stop_at_overlap) continue;
      break;
    }
    ++q.visited;
    const bool la = sa.leaf(it.na), lb = sb.leaf(it.nb);
    if (la && lb) {
      q.distance = it.bound;
      q.sphere_a = it.na;
      q.sphere_b = it.nb;
      if (stop_at_overlap) {
        if (found) *found = true;
        return q;
      }
      continue;
    }
    // Descend the side with the larger sphere (or the only one that is not a leaf).
    const bool split_a = !la && (lb || it.wa.radius >= it.wb.radius);
    const Side& s = split_a ? sa : sb;
    const int64_t n = split_a ? it.na : it.nb;
    for (int i = 0; i < s.t->branching; ++i) {
      const int64_t c = s.t->child(n, i);
      if (!s.t->used(c)) continue;
      const Sphere wc = s.world(c);
      Item child = split_a ? Item{pairGap(wc, it.wb), c, it.nb, wc, it.wb}
                           : Item{pairGap(it.wa, wc), it.na, c, it.wa, wc};
      if (child.bound >= std::min(q.distance, limit)) continue;
      if (stop_at_overlap)
        stack.push_back(child);
      else
        open.push(child);
    }
  }
  return q;
}

}  // namespace

Status checkPose(const std::string& what, const Pose& pose) {
  const Vec3& x = pose.translation;
  if (Status st =
          limits::checkCoordinates(what + " translation", std::span<const double>(x.data(), 3));
      !st)
    return st;
  const Eigen::Matrix3d& r = pose.rotation;
  const double err = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(err <= kPoseRotationTolerance) ||
      !(std::fabs(r.determinant() - 1.0) <= kPoseRotationTolerance))
    return Error{ErrorCode::kInvalidArgument,
                 what + " rotation is not a rotation (orthonormal with determinant +1)"};
  return {};
}

Expected<PairQuery> separation(const SphereTree& a, const Pose& pose_a, const SphereTree& b,
                               const Pose& pose_b) {
  if (Status st = checkPose("pose_a", pose_a); !st) return st.error();
  if (Status st = checkPose("pose_b", pose_b); !st) return st.error();
  return dualTraversal({&a, &pose_a}, {&b, &pose_b}, false, nullptr);
}

Expected<bool> overlaps(const SphereTree& a, const Pose& pose_a, const SphereTree& b,
                        const Pose& pose_b, PairQuery* pair) {
  if (Status st = checkPose("pose_a", pose_a); !st) return st.error();
  if (Status st = checkPose("pose_b", pose_b); !st) return st.error();
  bool found = false;
  const PairQuery q = dualTraversal({&a, &pose_a}, {&b, &pose_b}, true, &found);
  if (pair) *pair = q;
  return found;
}

int64_t maxQueryTreeSpheres(int branching) {
  int64_t leaves = 1;
  for (int depth = 1; SphereTree::slotCount(branching, depth) > 0; ++depth) leaves *= branching;
  return leaves;
}

Expected<SphereTree> queryTree(const std::vector<Sphere>& spheres, int branching,
                               std::vector<int64_t>* leaf_index) {
  if (Status st = limits::checkRange("branching", branching, 2, kMaxQueryBranching); !st)
    return st.error();
  for (size_t i = 0; i < spheres.size(); ++i)
    if (Status st =
            checkSphere("sphere " + std::to_string(i), spheres[i], ErrorCode::kInvalidArgument);
        !st)
      return st.error();
  if (leaf_index) leaf_index->clear();
  if (spheres.empty()) return SphereTree{};
  const auto n = static_cast<int64_t>(spheres.size());
  if (const int64_t most = maxQueryTreeSpheres(branching); n > most)
    return Error{ErrorCode::kInvalidArgument,
                 std::to_string(n) + " spheres: a query tree of branching " +
                     std::to_string(branching) + " holds at most " + std::to_string(most) +
                     " (SphereTree::kMaxSlots)"};
  detail::IndexedTree t = detail::medianTree(spheres, branching);
  if (leaf_index) *leaf_index = std::move(t.leaf_index);
  return std::move(t.tree);
}

Expected<SphereTree> queryTreeOf(const SphereTree& tree, std::vector<int64_t>* slot_of) {
  if (slot_of) slot_of->clear();
  if (tree.depth >= 2 && checkSphereTree(tree).ok()) return tree;
  if (tree.nodes.empty()) return SphereTree{};
  // The used slots of the last level, in slot order (the order of tree.leaves()).
  std::vector<int64_t> leaf_slots;
  const int64_t first = tree.levelBegin(tree.depth);
  for (int64_t s = first; s < first + tree.levelSize(tree.depth); ++s)
    if (s < static_cast<int64_t>(tree.nodes.size()) && tree.used(s)) leaf_slots.push_back(s);
  std::vector<int64_t> position;
  auto made = queryTree(tree.leaves(), 8, slot_of ? &position : nullptr);
  if (!made) return made.error();
  if (slot_of) {
    slot_of->assign(position.size(), -1);
    for (size_t k = 0; k < position.size(); ++k)
      if (position[k] >= 0) (*slot_of)[k] = leaf_slots[static_cast<size_t>(position[k])];
  }
  return made;
}

}  // namespace sphereset

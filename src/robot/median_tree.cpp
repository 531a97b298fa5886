// A sphere tree by median splits (a k-d tree's order in Bradshaw's flat layout). The leaves are
// ordered by recursive halving: a range that a subtree of capacity 2^k slots holds is split at
// 2^(k-1) items (the left half full first) by the median of the centres along the axis of the
// range's largest extent, so that every node of the 8-ary layout (three halvings) holds items
// that are close together. Parents are the minimal enclosing balls of their children, so every
// parent encloses its children, as the queries of query.hpp need.
#include "robot/median_tree.hpp"

#include <algorithm>
#include <numeric>

namespace sphereset::detail {
namespace {

constexpr int kMedianBranching = 8;

// Orders order[begin, end) for a subtree of `cap` leaf slots (a power of two).
void halve(std::span<const Sphere> s, std::vector<int64_t>* order, int64_t begin, int64_t end,
           int64_t cap) {
  while (end - begin > 1 && cap > 1) {
    const int64_t half = cap / 2;
    if (end - begin <= half) {  // all of it fits in the left half
      cap = half;
      continue;
    }
    Aabb box;
    for (int64_t i = begin; i < end; ++i) box.extend(s[(*order)[i]].center);
    int axis = 0;
    (box.max - box.min).maxCoeff(&axis);
    const auto first = order->begin();
    std::nth_element(first + begin, first + begin + half, first + end, [&](int64_t a, int64_t b) {
      const double ka = s[a].center[axis], kb = s[b].center[axis];
      return ka < kb || (ka == kb && a < b);
    });
    halve(s, order, begin + half, end, half);
    end = begin + half;
    cap = half;
  }
}

}  // namespace

IndexedTree medianTree(std::span<const Sphere> spheres) {
  const auto n = static_cast<int64_t>(spheres.size());
  IndexedTree out;
  SphereTree& t = out.tree;
  t.branching = kMedianBranching;
  t.depth = 1;
  int64_t cap = kMedianBranching;
  while (cap < n) {
    cap *= kMedianBranching;
    ++t.depth;
  }
  std::vector<int64_t> order(n);
  std::iota(order.begin(), order.end(), int64_t{0});
  halve(spheres, &order, 0, n, cap);

  const int64_t slots = SphereTree::slotCount(t.branching, t.depth);
  t.nodes.assign(slots, Sphere{Vec3::Zero(), -1.0});
  out.leaf_index.assign(slots, -1);
  const int64_t leaves = t.levelBegin(t.depth);
  for (int64_t i = 0; i < n; ++i) {
    t.nodes[leaves + i] = spheres[order[i]];
    out.leaf_index[leaves + i] = order[i];
  }
  std::vector<Sphere> kids;
  for (int level = t.depth - 1; level >= 0; --level) {
    const int64_t b = t.levelBegin(level), e = b + t.levelSize(level);
    for (int64_t node = b; node < e; ++node) {
      kids.clear();
      for (int i = 0; i < t.branching; ++i)
        if (t.used(t.child(node, i))) kids.push_back(t.nodes[t.child(node, i)]);
      if (!kids.empty()) t.nodes[node] = minimalEnclosingBall(kids);
    }
  }
  return out;
}

}  // namespace sphereset::detail

// A sphere tree by median splits (a k-d tree's order in Bradshaw's flat layout). The leaves of a
// subtree of `cap` slots are cut into `branching` consecutive blocks of cap / branching slots,
// the first full first, by recursive bisection of the blocks: each cut is a median of the
// centres along the axis of the range's largest extent (std::nth_element, linear), so the
// spheres of one node are close together and the whole build is O(n log n) for any set,
// identical spheres included. Parents are the minimal enclosing balls of their children, so
// every parent encloses its children, as the queries of query.hpp need.
#include "tree/median_tree.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>

namespace sphereset::detail {
namespace {

// Orders order[begin, end) into `blocks` consecutive blocks of `per` slots each, the left ones
// full first, by median cuts.
void cutBlocks(std::span<const Sphere> s, std::vector<int64_t>* order, int64_t begin, int64_t end,
               int64_t blocks, int64_t per) {
  while (blocks > 1 && end - begin > per) {
    const int64_t left = blocks / 2;
    const int64_t split = begin + left * per;
    if (end <= split) {  // all of it fits in the left blocks
      blocks = left;
      continue;
    }
    Aabb box;
    for (int64_t i = begin; i < end; ++i) box.extend(s[(*order)[i]].center);
    int axis = 0;
    (box.max - box.min).maxCoeff(&axis);
    const auto first = order->begin();
    std::nth_element(first + begin, first + split, first + end, [&](int64_t a, int64_t b) {
      const double ka = s[a].center[axis], kb = s[b].center[axis];
      return ka < kb || (ka == kb && a < b);
    });
    cutBlocks(s, order, split, end, blocks - left, per);
    end = split;
    blocks = left;
  }
}

// Orders order[begin, end) for a subtree of `cap` leaf slots (a power of `branching`).
void orderSubtree(std::span<const Sphere> s, std::vector<int64_t>* order, int64_t begin,
                  int64_t end, int64_t cap, int branching) {
  if (cap <= 1 || end - begin <= 1) return;
  const int64_t per = cap / branching;
  cutBlocks(s, order, begin, end, branching, per);
  for (int64_t b = begin; b < end; b += per)
    orderSubtree(s, order, b, std::min(end, b + per), per, branching);
}

}  // namespace

int medianTreeDepth(int64_t count, int branching) {
  int depth = 1;
  for (int64_t cap = branching; cap < count; cap *= branching) ++depth;
  return depth;
}

IndexedTree medianTree(std::span<const Sphere> spheres, int branching) {
  assert(branching >= 2 && !spheres.empty());
  const auto n = static_cast<int64_t>(spheres.size());
  IndexedTree out;
  SphereTree& t = out.tree;
  t.branching = branching;
  t.depth = medianTreeDepth(n, branching);
  const int64_t slots = SphereTree::slotCount(t.branching, t.depth);
  assert(slots > 0);
  std::vector<int64_t> order(n);
  std::iota(order.begin(), order.end(), int64_t{0});
  orderSubtree(spheres, &order, 0, n, t.levelSize(t.depth), branching);

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

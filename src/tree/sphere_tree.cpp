// Sphere trees as plain data: Bradshaw's flat layout (Bradshaw and O'Sullivan 2004, "Adaptive
// medial-axis approximation for sphere-tree construction", the .sph files of their toolkit),
// its invariants, and the one way a tree enters the library from a file or an array.
//
// Deviation: Bradshaw's trees may end a branch above the last level (a used node without used
// children is a leaf there). The queries and exports here take the leaves from the last level,
// so makeSphereTree copies such a node into its first child slot, level by level down to the
// last: the copy encloses itself, so every invariant still holds, and no leaf is lost.
#include "sphereset/sphere_tree.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace sphereset {
namespace {

double reach(const Vec3& centre, const Sphere& s) { return (s.center - centre).norm() + s.radius; }

// Copies each used node without used children above the last level into its first child slot.
void lowerLeaves(SphereTree* t) {
  for (int l = 0; l < t->depth; ++l) {
    const int64_t b = t->levelBegin(l), e = b + t->levelSize(l);
    for (int64_t n = b; n < e; ++n) {
      if (!t->used(n)) continue;
      bool has_child = false;
      for (int i = 0; i < t->branching && !has_child; ++i) has_child = t->used(t->child(n, i));
      if (!has_child) t->nodes[t->child(n, 0)] = t->nodes[n];
    }
  }
}

}  // namespace

int64_t SphereTree::slotCount(int b, int d) {
  int64_t total = 0, level = 1;
  for (int l = 0; l <= d; ++l) {
    total += level;
    if (total > kMaxSlots) return -1;
    if (l < d) level *= b;
  }
  return total;
}

int64_t SphereTree::levelSize(int l) const {
  int64_t s = 1;
  for (int i = 0; i < l; ++i) s *= branching;
  return s;
}

int64_t SphereTree::levelBegin(int l) const {
  int64_t begin = 0, s = 1;
  for (int i = 0; i < l; ++i) {
    begin += s;
    s *= branching;
  }
  return begin;
}

std::vector<Sphere> SphereTree::level(int l) const {
  std::vector<Sphere> out;
  const int64_t b = levelBegin(l), e = b + levelSize(l);
  for (int64_t i = b; i < e && i < static_cast<int64_t>(nodes.size()); ++i)
    if (used(i)) out.push_back(nodes[i]);
  return out;
}

Status checkSphereTree(const SphereTree& t, double tolerance) {
  if (t.branching < 1 || t.depth < 0)
    return Error{ErrorCode::kInvalidData, "sphere tree: bad branching or depth"};
  const int64_t slots = SphereTree::slotCount(t.branching, t.depth);
  if (slots < 0 || static_cast<int64_t>(t.nodes.size()) != slots)
    return Error{ErrorCode::kInvalidData, "sphere tree: " + std::to_string(t.nodes.size()) +
                                              " nodes, the layout needs " + std::to_string(slots)};
  for (int l = 0; l < t.depth; ++l) {
    const int64_t b = t.levelBegin(l), e = b + t.levelSize(l);
    for (int64_t n = b; n < e; ++n)
      for (int i = 0; i < t.branching; ++i) {
        const int64_t c = t.child(n, i);
        if (!t.used(c)) continue;
        if (!t.used(n))
          return Error{ErrorCode::kInvalidData, "sphere tree: node " + std::to_string(c) +
                                                    " is used but its parent " + std::to_string(n) +
                                                    " is not"};
        if (reach(t.nodes[n].center, t.nodes[c]) - t.nodes[n].radius > tolerance)
          return Error{ErrorCode::kInvalidData, "sphere tree: node " + std::to_string(c) +
                                                    " sticks out of its parent " +
                                                    std::to_string(n)};
      }
  }
  return {};
}

Expected<SphereTree> makeSphereTree(int branching, int depth, std::vector<Sphere> nodes,
                                    double tolerance) {
  if (branching < 1 || depth < 0 || SphereTree::slotCount(branching, depth) < 0)
    return Error{ErrorCode::kInvalidData, "sphere tree: branching " + std::to_string(branching) +
                                              " and depth " + std::to_string(depth) +
                                              " (branching at least 1, depth at least 0, at most " +
                                              std::to_string(SphereTree::kMaxSlots) + " slots)"};
  SphereTree t;
  t.branching = branching;
  t.depth = depth;
  t.nodes = std::move(nodes);
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const Sphere& s = t.nodes[i];
    // A NaN radius is neither used nor unused: refuse it with the centres.
    if (s.radius >= 0.0 || std::isnan(s.radius))
      if (Status st = checkSphere("sphere tree: node " + std::to_string(i), s); !st)
        return st.error();
  }
  if (Status st = checkSphereTree(t, tolerance); !st) return st.error();
  lowerLeaves(&t);
  return t;
}

}  // namespace sphereset

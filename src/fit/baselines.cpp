// Baselines for the fit. References: P. M. Hubbard, "Approximating polyhedra with spheres for
// time-critical collision detection", ACM TOG 15(3), 1996 (octree spheres, the first family
// of the paper's Sec. 2); S. Lloyd, "Least squares quantization in PCM", 1982 (k-means, which
// the paper's Sec. 5 suggests as a heuristic for large n).
//
// Deviations: Hubbard's spheres circumscribe the octree cells; ours are the minimal balls of
// the points inside each occupied cell (tighter, and the shared bounding step then covers the
// surface exactly, as for every method). The octree is refined greedily, largest ball first,
// so that it reaches exactly n leaves instead of jumping by powers of 8.
#include "fit/baselines.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <limits>

#include "sphereset/sphere.hpp"

namespace sphereset::detail {
namespace {

// Deepest octree level; cells below this size hold coincident points only.
constexpr int kMaxOctreeDepth = 24;

Sphere ballOf(const PointSet& ps, const std::vector<int32_t>& idx) {
  std::vector<Sphere> pts(idx.size());
  for (size_t i = 0; i < idx.size(); ++i) pts[i] = {ps.points[idx[i]], 0.0};
  return minimalEnclosingBall(pts);
}

}  // namespace

BaselineResult octreeSpheres(const PointSet& ps, int n) {
  struct Leaf {
    Vec3 lo;
    double size;
    int depth;
    bool splittable;
    std::vector<int32_t> pts;
    Sphere ball;
  };
  BaselineResult res;
  Aabb box;
  for (const Vec3& p : ps.points) box.extend(p);
  const double size = (box.max - box.min).maxCoeff() * (1.0 + 1e-9) + 1e-300;
  std::vector<Leaf> leaves(1);
  leaves[0].lo = box.min;
  leaves[0].size = size;
  leaves[0].depth = 0;
  leaves[0].splittable = true;
  leaves[0].pts.resize(ps.points.size());
  for (size_t i = 0; i < ps.points.size(); ++i) leaves[0].pts[i] = static_cast<int32_t>(i);
  leaves[0].ball = ballOf(ps, leaves[0].pts);
  while (true) {
    // The splittable leaf with the largest ball (ties: lowest index).
    int best = -1;
    for (int i = 0; i < static_cast<int>(leaves.size()); ++i)
      if (leaves[i].splittable && leaves[i].pts.size() > 1 &&
          (best < 0 || leaves[i].ball.radius > leaves[best].ball.radius))
        best = i;
    if (best < 0) break;
    Leaf parent = std::move(leaves[best]);
    const double half = 0.5 * parent.size;
    std::array<std::vector<int32_t>, 8> oct;
    for (int32_t p : parent.pts) {
      const Vec3 r = ps.points[p] - parent.lo;
      const int o = (r.x() >= half ? 1 : 0) | (r.y() >= half ? 2 : 0) | (r.z() >= half ? 4 : 0);
      oct[o].push_back(p);
    }
    std::vector<int> occupied;
    for (int o = 0; o < 8; ++o)
      if (!oct[o].empty()) occupied.push_back(o);
    const int budget = n - static_cast<int>(leaves.size()) + 1;  // leaves this split may make
    std::vector<Leaf> made;
    auto octLeaf = [&](int o) {
      Leaf c;
      c.lo = parent.lo + half * Vec3(o & 1, (o >> 1) & 1, (o >> 2) & 1);
      c.size = half;
      c.depth = parent.depth + 1;
      c.splittable = c.depth < kMaxOctreeDepth;
      c.pts = std::move(oct[o]);
      return c;
    };
    if (static_cast<int>(occupied.size()) <= budget) {
      for (int o : occupied) made.push_back(octLeaf(o));
    } else {
      // Keep the budget - 1 most populated octants; merge the rest into one final leaf.
      std::stable_sort(occupied.begin(), occupied.end(),
                       [&](int a, int b) { return oct[a].size() > oct[b].size(); });
      for (int k = 0; k + 1 < budget; ++k) made.push_back(octLeaf(occupied[k]));
      Leaf rest;
      rest.lo = parent.lo;
      rest.size = parent.size;
      rest.depth = parent.depth;
      rest.splittable = false;
      for (size_t k = std::max(0, budget - 1); k < occupied.size(); ++k)
        rest.pts.insert(rest.pts.end(), oct[occupied[k]].begin(), oct[occupied[k]].end());
      made.push_back(std::move(rest));
    }
    tbb::parallel_for(size_t{0}, made.size(),
                      [&](size_t k) { made[k].ball = ballOf(ps, made[k].pts); });
    leaves[best] = std::move(made[0]);
    for (size_t k = 1; k < made.size(); ++k) leaves.push_back(std::move(made[k]));
    ++res.iterations;
  }
  for (const Leaf& l : leaves) res.spheres.push_back(l.ball);
  res.converged = true;
  return res;
}

BaselineResult kmeansSpheres(const PointSet& ps, const std::vector<Vec3>& seeds,
                             int max_iterations) {
  BaselineResult res;
  const int k = static_cast<int>(seeds.size());
  const int64_t np = static_cast<int64_t>(ps.points.size());
  std::vector<Vec3> centre = seeds;
  std::vector<int32_t> label(np, -1), prev;
  for (int it = 0; it < std::max(1, max_iterations); ++it) {
    tbb::parallel_for(int64_t{0}, np, [&](int64_t p) {
      int32_t best = 0;
      double bd = std::numeric_limits<double>::infinity();
      for (int32_t c = 0; c < k; ++c) {
        const double d = (ps.points[p] - centre[c]).squaredNorm();
        if (d < bd) {
          bd = d;
          best = c;
        }
      }
      label[p] = best;
    });
    res.iterations = it + 1;
    if (label == prev) {
      res.converged = true;
      break;
    }
    prev = label;
    std::vector<Vec3> sum(k, Vec3::Zero());
    std::vector<int64_t> count(k, 0);
    for (int64_t p = 0; p < np; ++p) {
      sum[label[p]] += ps.points[p];
      ++count[label[p]];
    }
    for (int c = 0; c < k; ++c)
      if (count[c] > 0) centre[c] = sum[c] / static_cast<double>(count[c]);
    // An empty cluster restarts at the point farthest from its centre in the largest one.
    for (int c = 0; c < k; ++c) {
      if (count[c] > 0) continue;
      const int big =
          static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
      int64_t far = -1;
      double fd = -1.0;
      for (int64_t p = 0; p < np; ++p)
        if (label[p] == big && (ps.points[p] - centre[big]).squaredNorm() > fd) {
          fd = (ps.points[p] - centre[big]).squaredNorm();
          far = p;
        }
      if (far < 0) break;
      centre[c] = ps.points[far];
      label[far] = c;
      count[c] = 1;
      --count[big];
    }
  }
  std::vector<std::vector<int32_t>> members(k);
  for (int64_t p = 0; p < np; ++p) members[label[p]].push_back(static_cast<int32_t>(p));
  res.spheres.resize(k);
  tbb::parallel_for(0, k, [&](int c) {
    res.spheres[c] = members[c].empty() ? Sphere{centre[c], 0.0} : ballOf(ps, members[c]);
  });
  return res;
}

}  // namespace sphereset::detail

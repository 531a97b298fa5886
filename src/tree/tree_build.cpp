// Sphere hierarchies. Reference: Wang et al. 2006, Sec. 6 ("Sphere hierarchies can be built
// using a simple bottom-up approach..."): levels are built from the leaves up by Lloyd
// clustering of the spheres of the level below; each cluster's bounding sphere becomes the
// parent of its members.
//
// Deviations, each for a reason:
// - Clusters hold at most B children (the flat Bradshaw layout has B slots per node), so
//   the assignment is capacitated: (child, cluster) pairs are taken in increasing order of
//   reach, each child going to the nearest cluster that still has room.
// - The distance is the reach |c_child - C| + r_child (how far the parent must extend to hold
//   the child) rather than the distance between centres.
// - Parents are the exact minimal enclosing ball of the children's balls (the paper runs
//   Powell's method on the radius), or, as an option, the ball of least outside volume among
//   those enclosing the children, so that each level is itself a tight bounding set.
// - The number of parents per level follows a geometric progression from the leaf count to
//   the root (B^l per level for a full tree), clamped to what the layout allows.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "fit/sphere_update.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/tree.hpp"
#include "util/sampling.hpp"

namespace sphereset {
namespace {

double reach(const Vec3& centre, const Sphere& s) { return (s.center - centre).norm() + s.radius; }

struct Grouping {
  std::vector<std::vector<int32_t>> groups;  // indices into the child level, each non-empty
  int iterations = 0;
  bool converged = false;
};

// Capacitated Lloyd clustering of `kids` into at most k groups of at most `cap` members.
Grouping clusterLevel(const std::vector<Sphere>& kids, int64_t k, int cap, int max_iterations,
                      uint64_t seed) {
  const int64_t m = static_cast<int64_t>(kids.size());
  Grouping out;
  // Farthest-point seeds over the child centres, from a seeded random child.
  std::vector<Vec3> centre;
  {
    std::mt19937_64 rng(detail::mixSeed(seed, 31));
    std::vector<double> d2(m, std::numeric_limits<double>::infinity());
    int64_t next = static_cast<int64_t>(detail::uniform01(rng) * m) % m;
    for (int64_t c = 0; c < k; ++c) {
      centre.push_back(kids[next].center);
      int64_t far = 0;
      for (int64_t i = 0; i < m; ++i) {
        d2[i] = std::min(d2[i], (kids[i].center - centre.back()).squaredNorm());
        if (d2[i] > d2[far]) far = i;
      }
      next = far;
    }
  }
  std::vector<int64_t> label(m, -1), prev;
  struct Pair {
    double d;
    int32_t child, cluster;
  };
  std::vector<Pair> pairs;
  for (int it = 0; it < std::max(1, max_iterations); ++it) {
    // Assignment: pairs in increasing reach, each child to the nearest cluster with room.
    pairs.resize(static_cast<size_t>(m * k));
    tbb::parallel_for(int64_t{0}, m, [&](int64_t i) {
      for (int64_t c = 0; c < k; ++c)
        pairs[i * k + c] = {reach(centre[c], kids[i]), static_cast<int32_t>(i),
                            static_cast<int32_t>(c)};
    });
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
      return a.d < b.d ||
             (a.d == b.d && (a.child < b.child || (a.child == b.child && a.cluster < b.cluster)));
    });
    std::vector<int> fill(k, 0);
    std::fill(label.begin(), label.end(), -1);
    int64_t left = m;
    for (const Pair& p : pairs) {
      if (label[p.child] >= 0 || fill[p.cluster] >= cap) continue;
      label[p.child] = p.cluster;
      ++fill[p.cluster];
      if (--left == 0) break;
    }
    out.iterations = it + 1;
    // Update: each cluster's centre becomes its minimal enclosing ball's centre.
    std::vector<std::vector<Sphere>> members(k);
    for (int64_t i = 0; i < m; ++i) members[label[i]].push_back(kids[i]);
    std::vector<Sphere> ball(k);
    tbb::parallel_for(int64_t{0}, k, [&](int64_t c) {
      if (!members[c].empty()) ball[c] = minimalEnclosingBall(members[c]);
    });
    if (label == prev) {
      out.converged = true;
      break;
    }
    prev = label;
    // Empty clusters restart at the child reaching farthest out of the largest cluster.
    std::vector<char> donated(k, 0);
    for (int64_t c = 0; c < k; ++c) {
      if (!members[c].empty()) {
        centre[c] = ball[c].center;
        continue;
      }
      int64_t donor = -1;
      for (int64_t e = 0; e < k; ++e)
        if (!donated[e] && members[e].size() > 1 &&
            (donor < 0 || ball[e].radius > ball[donor].radius))
          donor = e;
      if (donor < 0) continue;
      const Sphere* far = &members[donor][0];
      for (const Sphere& s : members[donor])
        if (reach(ball[donor].center, s) > reach(ball[donor].center, *far)) far = &s;
      centre[c] = far->center;
      donated[donor] = 1;  // one restart per donor and round
    }
  }
  out.groups.assign(k, {});
  for (int64_t i = 0; i < m; ++i) out.groups[label[i]].push_back(static_cast<int32_t>(i));
  out.groups.erase(
      std::remove_if(out.groups.begin(), out.groups.end(), [](const auto& g) { return g.empty(); }),
      out.groups.end());
  return out;
}

// The parent of one group.
Sphere parentOf(const std::vector<Sphere>& kids, const TreeOptions& o, const SolidIndex* index) {
  Sphere ball = minimalEnclosingBall(kids);
  if (o.parents != TreeParents::kOutsideVolume || kids.size() < 2) return ball;
  const detail::EnclosingRadius radius_of = [&](const Vec3& c, Vec3* grad) {
    double r = 0.0;
    const Sphere* far = &kids[0];
    for (const Sphere& s : kids)
      if (reach(c, s) > r) {
        r = reach(c, s);
        far = &s;
      }
    if (grad) {
      const Vec3 d = c - far->center;
      *grad = d.norm() > 0.0 ? Vec3(d / d.norm()) : Vec3::Zero();
    }
    return r;
  };
  Aabb box;
  for (const Sphere& s : kids) box.extend(s.center);
  Sphere best = detail::minimiseOutsideVolume(*index, radius_of, ball.center, box,
                                              SphereOptimizer::kPowell, o.optimizer_evaluations)
                    .sphere;
  // Containment in floating point, as for the minimal ball.
  double r = best.radius;
  for (const Sphere& s : kids) r = std::max(r, reach(best.center, s));
  best.radius = std::nextafter(r, std::numeric_limits<double>::infinity());
  return best;
}

}  // namespace

Expected<TreeResult> buildSphereTree(std::span<const Sphere> leaves, const TreeOptions& o,
                                     const SolidIndex* index) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Status st = checkTreeOptions(o); !st) return st.error();
  SphereTree tree;
  tree.branching = o.branching;
  tree.depth = o.depth;
  const int64_t max_leaves = tree.levelSize(o.depth);
  const int64_t nl = static_cast<int64_t>(leaves.size());
  if (nl < 1) return Error{ErrorCode::kInvalidArgument, "a sphere tree needs at least one leaf"};
  if (nl > max_leaves)
    return Error{ErrorCode::kInvalidArgument,
                 std::to_string(nl) + " leaves do not fit a tree of branching " +
                     std::to_string(o.branching) + " and depth " + std::to_string(o.depth) +
                     " (at most " + std::to_string(max_leaves) + ")"};
  for (size_t i = 0; i < leaves.size(); ++i)
    if (Status st = checkSphere("leaf sphere " + std::to_string(i), leaves[i]); !st)
      return st.error();
  if (o.parents == TreeParents::kOutsideVolume && !index)
    return Error{ErrorCode::kInvalidArgument, "outside-volume parents need the mesh"};

  // Bottom-up: spheres per level and, per parent, the indices of its children.
  const int d = o.depth;
  std::vector<std::vector<Sphere>> lvl(d + 1);
  std::vector<std::vector<std::vector<int32_t>>> kids(d);
  lvl[d].assign(leaves.begin(), leaves.end());
  TreeResult res;
  res.levels.resize(d + 1);
  for (int l = d - 1; l >= 0; --l) {
    const int64_t m = static_cast<int64_t>(lvl[l + 1].size());
    const int64_t k_min = (m + o.branching - 1) / o.branching;
    const int64_t k_max = std::min(tree.levelSize(l), m);
    const int64_t k_geo =
        std::llround(std::pow(static_cast<double>(nl), static_cast<double>(l) / d));
    const int64_t k = std::clamp(k_geo, k_min, std::max(k_min, k_max));
    Grouping g = clusterLevel(lvl[l + 1], k, o.branching, o.max_iterations,
                              detail::mixSeed(o.seed, 1000 + l));
    res.levels[l].iterations = g.iterations;
    res.levels[l].converged = g.converged;
    lvl[l].resize(g.groups.size());
    tbb::parallel_for(size_t{0}, g.groups.size(), [&](size_t p) {
      std::vector<Sphere> members;
      for (int32_t c : g.groups[p]) members.push_back(lvl[l + 1][c]);
      lvl[l][p] = parentOf(members, o, index);
    });
    kids[l] = std::move(g.groups);
  }

  // Top-down layout: child j of the node in slot s goes to slot s·B + 1 + j.
  tree.nodes.assign(SphereTree::slotCount(o.branching, o.depth), Sphere{Vec3::Zero(), -1.0});
  std::vector<int64_t> slot_of{0};  // slots of the current level's spheres
  tree.nodes[0] = lvl[0][0];
  for (int l = 0; l < d; ++l) {
    std::vector<int64_t> next(lvl[l + 1].size(), -1);
    for (size_t p = 0; p < kids[l].size(); ++p)
      for (size_t j = 0; j < kids[l][p].size(); ++j) {
        const int64_t s = tree.child(slot_of[p], static_cast<int>(j));
        next[kids[l][p][j]] = s;
        tree.nodes[s] = lvl[l + 1][kids[l][p][j]];
      }
    slot_of = std::move(next);
  }
  for (int l = 0; l <= d; ++l) {
    res.levels[l].level = l;
    res.levels[l].nodes = static_cast<int64_t>(lvl[l].size());
    if (index) {
      std::vector<double> v(lvl[l].size());
      tbb::parallel_for(size_t{0}, lvl[l].size(),
                        [&](size_t i) { v[i] = index->outsideVolume(lvl[l][i]).volume; });
      for (double x : v) res.levels[l].outside_volume += x;
    }
  }
  res.tree = std::move(tree);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

namespace {

// The leaves fitted when no count is given: branching^depth, at most kMaxDefaultTreeLeaves.
Expected<int> defaultLeaves(const TreeOptions& options) {
  const int64_t leaves = SphereTree{options.branching, options.depth, {}}.levelSize(options.depth);
  if (leaves > kMaxDefaultTreeLeaves)
    return Error{ErrorCode::kInvalidArgument,
                 "branching^depth = " + std::to_string(leaves) + " leaves (more than " +
                     std::to_string(kMaxDefaultTreeLeaves) +
                     ") is too many to fit; give the number of spheres"};
  return static_cast<int>(leaves);
}

}  // namespace

Expected<FitRequest> treeFitRequest(FitRequest request, const TreeOptions& options) {
  if (Status st = checkTreeOptions(options); !st) return st.error();
  if (request.num_spheres == 0) {
    auto leaves = defaultLeaves(options);
    if (!leaves) return leaves.error();
    request.num_spheres = *leaves;
  }
  if (Status st = checkFitRequest(request); !st) return st.error();
  return request;
}

Expected<TreeFitResult> fitSphereTree(const SolidIndex& index, FitOptions fit,
                                      const TreeOptions& options) {
  if (Status st = checkTreeOptions(options); !st) return st.error();
  if (fit.num_spheres == 0) {
    auto leaves = defaultLeaves(options);
    if (!leaves) return leaves.error();
    fit.num_spheres = *leaves;
  }
  auto f = fitSpheres(index, fit);
  if (!f) return f.error();
  TreeFitResult out;
  out.fit = std::move(*f);
  auto t = buildSphereTree(out.fit.spheres, options, &index);
  if (!t) return t.error();
  out.tree = std::move(*t);
  return out;
}

}  // namespace sphereset

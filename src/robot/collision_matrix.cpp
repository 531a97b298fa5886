// The self-collision matrix of a robot by sampling its joint space, as MoveIt's setup assistant
// computes the disable_collisions entries of an SRDF (moveit_setup_srdf_plugins,
// compute_default_collisions.cpp): adjacent links first (joined by a joint, or through links
// without geometry), then the pairs in collision at the default pose, then those in collision in
// at least a fraction of random configurations ("Always", 95 % in MoveIt), then those in
// collision in none ("Never"). Collisions are measured on the sphere sets or, on request, on the
// link solids (link_contact.cpp).
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "robot/link_contact.hpp"
#include "sphereset/robot_collision.hpp"
#include "util/sampling.hpp"

namespace sphereset {
namespace {

using PosesByLink = std::map<std::string, Eigen::Isometry3d>;

// Pairs (by index into the robot's links, first < second) joined by a joint, or through links
// not in `has_geometry` (MoveIt's rule: a link without geometry joins its neighbours), and the
// description's own excluded pairs (Robot::excluded_pairs: an MJCF's filter).
std::set<std::pair<size_t, size_t>> adjacentPairs(const Robot& robot,
                                                  const std::map<std::string, size_t>& index,
                                                  const std::vector<bool>& has_geometry) {
  std::vector<std::set<size_t>> next(robot.links.size());
  for (const RobotJoint& j : robot.joints) {
    const auto p = index.find(j.parent);
    const auto c = index.find(j.child);
    if (p == index.end() || c == index.end() || p->second == c->second) continue;
    next[p->second].insert(c->second);
    next[c->second].insert(p->second);
  }
  for (size_t w = 0; w < robot.links.size(); ++w) {
    if (has_geometry[w]) continue;
    const std::vector<size_t> around(next[w].begin(), next[w].end());
    for (size_t x : around)
      for (size_t y : around)
        if (x != y) next[x].insert(y);
  }
  for (const auto& [x, y] : robot.excluded_pairs) {
    const auto a = index.find(x), b = index.find(y);
    if (a == index.end() || b == index.end() || a->second == b->second) continue;
    next[a->second].insert(b->second);
    next[b->second].insert(a->second);
  }
  std::set<std::pair<size_t, size_t>> out;
  for (size_t a = 0; a < next.size(); ++a)
    for (size_t b : next[a])
      if (a < b && has_geometry[a] && has_geometry[b]) out.emplace(a, b);
  return out;
}

// Configuration `i`: each movable joint that is not a mimic uniform within jointSampleRange
// (continuous joints, and revolute joints of a turn or more, over [-π, π]; limits of ±1e308
// once made every sample infinite), from a generator of its own.
std::map<std::string, double> sampledConfiguration(const std::vector<const RobotJoint*>& joints,
                                                   uint64_t seed, int64_t i) {
  std::mt19937_64 rng(detail::mixSeed(seed, static_cast<uint64_t>(i)));
  std::map<std::string, double> q;
  for (const RobotJoint* j : joints) {
    const double u = detail::uniform01(rng);
    const auto [lo, hi] = jointSampleRange(*j);
    q[j->name] = lo + u * (hi - lo);
  }
  return q;
}

std::vector<const RobotJoint*> sampledJoints(const Robot& robot) {
  std::vector<const RobotJoint*> joints;
  for (const RobotJoint& j : robot.joints)
    if (isMovable(j) && !j.mimic) joints.push_back(&j);
  return joints;
}

struct Participants {
  std::vector<size_t> links;              // robot link indices, in order
  std::vector<detail::LinkBody> bodies;   // one per entry of `links`
  std::vector<std::array<int, 2>> pairs;  // positions in `links`, not adjacent
};

// Each participant's pose at `poses`, in the order of `who.links` (one lookup per link, not
// two per pair), with its inverse; `out`'s storage is reused from one configuration to the next.
struct PlacedLinks {
  std::vector<Eigen::Isometry3d> pose, inverse;
};
void placeLinks(const Robot& robot, const Participants& who, const PosesByLink& poses,
                PlacedLinks* out) {
  out->pose.clear();
  out->inverse.clear();
  for (size_t link : who.links) {
    out->pose.push_back(poses.at(robot.links[link].name));
    out->inverse.push_back(out->pose.back().inverse());
  }
}

// Whether pair p of `who` is in collision with its links placed at `at`.
bool pairTouches(const Participants& who, const PlacedLinks& at, const std::array<int, 2>& p) {
  return detail::bodiesTouch(who.bodies[p[0]], who.bodies[p[1]], at.inverse[p[0]] * at.pose[p[1]]);
}

// Each pair's position in `who.pairs`, by its two participants (first < second): the broad
// phase finds pairs by their links and counts them here.
class PairIndex {
 public:
  explicit PairIndex(const Participants& who) : of_(who.links.size()) {
    for (size_t p = 0; p < who.pairs.size(); ++p)
      of_[who.pairs[p][0]].emplace_back(who.pairs[p][1], static_cast<int64_t>(p));
    for (auto& row : of_) std::sort(row.begin(), row.end());
  }
  // -1 when (a, b), a < b, is not a pair to count (adjacent, or touching at the default pose).
  int64_t find(int a, int b) const {
    const auto& row = of_[a];
    const auto it = std::lower_bound(row.begin(), row.end(), std::pair<int, int64_t>{b, -1});
    return it != row.end() && it->first == b ? it->second : -1;
  }

 private:
  std::vector<std::vector<std::pair<int, int64_t>>> of_;
};

// A relative slack on the broad phase's world-frame bounds, so that it never drops a pair the
// exact test (bodiesTouch, in one link's frame, with its own margin of 1e-12 on the squared
// reach) would keep: the two frames round differently by a few ulps of the coordinates.
constexpr double kBroadPhaseSlack = 1e-9;

// The pairs whose bounding spheres may meet with the links placed at `at`, by sweep and prune
// along x (Baraff 1992): O(n log n + pairs met) per configuration instead of every pair (a
// 1000-link chain has half a million pairs, of which a few thousand meet). Reuses `order`.
// A link's bounding sphere in the world at one configuration, and its interval's low end on x.
struct WorldBound {
  Vec3 centre;
  double radius = 0.0, low_x = 0.0;
};

template <class Visit>
void broadPhase(const Participants& who, const PlacedLinks& at, std::vector<int>* order,
                std::vector<WorldBound>* world, Visit&& visit) {
  const int n = static_cast<int>(who.links.size());
  world->resize(n);
  order->clear();
  for (int i = 0; i < n; ++i) {
    const Sphere& b = who.bodies[i].bound;
    if (b.radius < 0.0) continue;  // an empty body touches nothing
    const Vec3 c = at.pose[i] * b.center;
    const double r = b.radius + kBroadPhaseSlack * (b.radius + c.norm());
    (*world)[i] = {c, r, c.x() - r};
    order->push_back(i);
  }
  const std::vector<WorldBound>& w = *world;
  std::sort(order->begin(), order->end(), [&](int x, int y) {
    return w[x].low_x < w[y].low_x || (w[x].low_x == w[y].low_x && x < y);
  });
  for (size_t u = 0; u < order->size(); ++u) {
    const WorldBound& a = w[(*order)[u]];
    const double right = a.centre.x() + a.radius;
    for (size_t v = u + 1; v < order->size() && w[(*order)[v]].low_x <= right; ++v) {
      const WorldBound& b = w[(*order)[v]];
      const double reach = a.radius + b.radius;
      if ((a.centre - b.centre).squaredNorm() > reach * reach) continue;
      visit(std::min((*order)[u], (*order)[v]), std::max((*order)[u], (*order)[v]));
    }
  }
}

// Configurations checked per progress call: about a hundred calls in all, at least this many
// configurations each.
constexpr int64_t kMinProgressBlock = 256;

// Collisions per pair of `who` over the samples, in parallel (integer sums: the same on any
// number of threads), in blocks between progress calls. A sample that cannot be posed is an
// error naming the first such sample, never a sample skipped: a skipped sample would make pairs
// that collide "Never".
Expected<std::vector<int64_t>> countCollisions(
    const Robot& robot, const Participants& who, int samples, uint64_t seed,
    const std::function<void(const RobotProgress&)>& progress) {
  const std::vector<const RobotJoint*> joints = sampledJoints(robot);
  const PairIndex pair_index(who);
  tbb::enumerable_thread_specific<std::vector<int64_t>> local(
      std::vector<int64_t>(who.pairs.size(), 0));
  struct Scratch {
    PlacedLinks at;
    std::vector<int> order;
    std::vector<WorldBound> world;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  std::atomic<int64_t> first_failure{std::numeric_limits<int64_t>::max()};
  auto check = [&](const tbb::blocked_range<int64_t>& range) {
    std::vector<int64_t>& counts = local.local();
    Scratch& s = scratch.local();
    for (int64_t i = range.begin(); i != range.end(); ++i) {
      auto poses = linkPoses(robot, sampledConfiguration(joints, seed, i));
      if (!poses) {
        int64_t seen = first_failure.load();
        while (i < seen && !first_failure.compare_exchange_weak(seen, i)) {
        }
        continue;
      }
      placeLinks(robot, who, *poses, &s.at);
      broadPhase(who, s.at, &s.order, &s.world, [&](int a, int b) {
        const int64_t p = pair_index.find(a, b);
        if (p >= 0 && pairTouches(who, s.at, who.pairs[p])) ++counts[p];
      });
    }
  };
  const int64_t block = std::max<int64_t>(kMinProgressBlock, (samples + 99) / 100);
  for (int64_t begin = 0; begin < samples; begin += block) {
    const int64_t end = std::min<int64_t>(samples, begin + block);
    tbb::parallel_for(tbb::blocked_range<int64_t>(begin, end, 16), check);
    if (first_failure.load() != std::numeric_limits<int64_t>::max()) break;
    if (progress) progress(RobotProgress{"self-collision", end, samples, ""});
  }
  if (const int64_t bad = first_failure.load(); bad != std::numeric_limits<int64_t>::max()) {
    const auto poses = linkPoses(robot, sampledConfiguration(joints, seed, bad));
    return Error{ErrorCode::kInvalidData,
                 "sampled configuration " + std::to_string(bad) + " cannot be posed: " +
                     (poses ? std::string("unknown") : poses.error().message)};
  }
  std::vector<int64_t> total(who.pairs.size(), 0);
  for (const std::vector<int64_t>& c : local)
    for (size_t p = 0; p < c.size(); ++p) total[p] += c[p];
  return total;
}

}  // namespace

Expected<CollisionMatrix> sampleSelfCollisions(const Robot& robot,
                                               const std::vector<LinkSpheres>& spheres,
                                               const CollisionSamplingOptions& options,
                                               const std::vector<CollisionSolid>& solids) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Status st = checkCollisionSamplingOptions(options); !st) return st.error();
  auto defaults = linkPoses(robot, options.default_pose);
  if (!defaults) return Error{defaults.error().code, "default_pose: " + defaults.error().message};
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < robot.links.size(); ++i) index.emplace(robot.links[i].name, i);

  // Each link's spheres (a link named twice: one set), for the links the root reaches.
  std::map<size_t, std::vector<Sphere>> merged;
  for (const LinkSpheres& ls : spheres) {
    const auto i = index.find(ls.link);
    if (i == index.end() || defaults->count(ls.link) == 0 || ls.spheres.empty()) continue;
    auto& set = merged[i->second];
    set.insert(set.end(), ls.spheres.begin(), ls.spheres.end());
  }
  std::map<std::string, const CollisionSolid*> solid_of;
  for (const CollisionSolid& s : solids) solid_of.emplace(s.link, &s);
  Participants who;
  std::vector<bool> has_geometry(robot.links.size(), false);
  for (auto& [i, set] : merged) {
    has_geometry[i] = true;
    who.links.push_back(i);
    const auto solid = solid_of.find(robot.links[i].name);
    if (options.check == CollisionCheck::kMeshes && solid != solid_of.end())
      who.bodies.push_back(detail::makeLinkBody(solid->second->mesh, solid->second->primitives));
    else
      who.bodies.push_back(detail::makeLinkBody(Mesh{}, set));
  }

  CollisionMatrix out;
  out.check = options.check;
  out.samples = options.samples > 0 ? options.samples : defaultSampleCount(robot);
  const auto adjacent = adjacentPairs(robot, index, has_geometry);
  std::map<std::pair<size_t, size_t>, DisabledPair> disabled;
  auto disable = [&](size_t a, size_t b, DisableReason reason, int64_t collisions) {
    disabled[{a, b}] = DisabledPair{robot.links[a].name, robot.links[b].name, reason, collisions};
  };
  for (const auto& [a, b] : adjacent) disable(a, b, DisableReason::kAdjacent, 0);
  const int n = static_cast<int>(who.links.size());
  PlacedLinks at_default;
  placeLinks(robot, who, *defaults, &at_default);
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      ++out.pairs;
      if (adjacent.count({who.links[a], who.links[b]}) > 0) continue;
      if (pairTouches(who, at_default, {a, b}))
        disable(who.links[a], who.links[b], DisableReason::kDefault, 0);
      else
        who.pairs.push_back({a, b});
    }

  const auto sampled = countCollisions(robot, who, out.samples, options.seed, options.progress);
  if (!sampled) return sampled.error();
  const std::vector<int64_t>& counts = *sampled;
  const double always = options.always_fraction * out.samples;
  for (size_t p = 0; p < who.pairs.size(); ++p) {
    const size_t a = who.links[who.pairs[p][0]], b = who.links[who.pairs[p][1]];
    if (counts[p] == 0)
      disable(a, b, DisableReason::kNever, 0);
    else if (static_cast<double>(counts[p]) >= always)
      disable(a, b, DisableReason::kAlways, counts[p]);
    else
      ++out.enabled;
  }
  for (auto& [ab, pair] : disabled) {
    ++out.counts[static_cast<int>(pair.reason)];
    out.disabled.push_back(std::move(pair));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

std::map<std::string, double> collisionSampleConfiguration(const Robot& robot, uint64_t seed,
                                                           int64_t i) {
  return sampledConfiguration(sampledJoints(robot), seed, i);
}

std::vector<std::array<std::string, 2>> neverPairs(const CollisionMatrix& matrix) {
  std::vector<std::array<std::string, 2>> out;
  for (const DisabledPair& p : matrix.disabled)
    if (p.reason == DisableReason::kNever) out.push_back({p.link1, p.link2});
  return out;
}

SelfCollisionPairs ignoredPairs(const CollisionMatrix& matrix) {
  SelfCollisionPairs out;
  for (const DisabledPair& p : matrix.disabled)
    (p.reason == DisableReason::kAdjacent ? out.adjacent : out.overlapping)
        .push_back({p.link1, p.link2});
  return out;
}

}  // namespace sphereset

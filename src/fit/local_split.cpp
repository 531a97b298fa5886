// One sphere more by a single local split (beyond the paper). Reference: Wang et al. 2006,
// Sec. 5, "Sphere Teleportation", splits a cluster in two from "the two points farthest from each
// other" and refits both halves (Eq. 5); here that split, made on a bounded fit, is the whole step
// from n to n + 1 spheres. Deviation: what is split is not the sphere's cluster but what it alone
// covers (the surface pieces and interior points no other sphere holds, as the shrinking refits
// them: shrink.cpp), so that the halves together take over its share of the bound rather than
// its samples (splitting the clusters' points instead left steps that raised E_r: the halves
// lost the refinement's fit to the surface between the samples and grew back in the bound). The
// sphere whose split lowers the outside volume most (its bounded sphere's against the two
// refitted halves') is replaced by the halves, and only the solid within the old sphere's box is
// bounded again (bound_refit.cpp, bound.cpp, restricted to that box). Every other sphere keeps
// its radius or grows, so whatever lay outside the box stays covered.
//
// Deviation from a fit at n + 1 (fit.cpp, progressive.cpp): no rounds, teleports, shrinking or
// refinement, so a step costs a few sphere updates and a bound of one sphere's neighbourhood
// instead of a whole clustering and ending, and its set is looser than a fit's at the same count
// (docs/benchmarks.md, "Progressive fitting").
#include "fit/local_split.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "fit/bound_refit.hpp"
#include "fit/fit_common.hpp"
#include "fit/teleport.hpp"
#include "sphereset/cover.hpp"

namespace sphereset::detail {
namespace {

Aabb ballBox(const Sphere& s) {
  Aabb b;
  b.extend(s.center - Vec3::Constant(s.radius));
  b.extend(s.center + Vec3::Constant(s.radius));
  return b;
}

bool boxesMeet(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (a.max.array() >= b.min.array()).all();
}

// The triangles of `mesh` whose bounding box meets `box`, with all of its vertices.
Mesh trianglesMeeting(const Mesh& mesh, const Aabb& box) {
  Mesh out;
  out.vertices = mesh.vertices;
  for (const Triangle& t : mesh.triangles) {
    Aabb b;
    for (int k = 0; k < 3; ++k) b.extend(mesh.vertices[t[k]]);
    if (boxesMeet(b, box)) out.triangles.push_back(t);
  }
  return out;
}

// The spheres without their padding.
std::vector<Sphere> unpadded(const std::vector<Sphere>& spheres, double padding) {
  std::vector<Sphere> bare = spheres;
  for (Sphere& s : bare) s.radius = std::max(0.0, s.radius - padding);
  return bare;
}

// Measures the split of every sphere not yet measured (in parallel, deterministic per sphere):
// what it alone covers among the triangles near it and the interior points in it.
void measureChain(const SolidIndex& index, const PointSet& ps, const FitOptions& o, double min_edge,
                  SplitChain* c, FitResult* res) {
  const std::vector<Sphere> bare = unpadded(c->spheres, o.padding);
  std::vector<int64_t> queries(c->spheres.size(), 0);
  tbb::parallel_for(size_t{0}, c->spheres.size(), [&](size_t i) {
    if (c->measured[i]) return;
    pollCancel();
    const Sphere& s = bare[i];
    const Mesh near = trianglesMeeting(index.mesh(), ballBox(s));
    std::vector<Vec3> inside;
    for (int64_t k = 0; k < ps.interior; ++k)
      if ((ps.points[k] - s.center).norm() <= s.radius) inside.push_back(ps.points[k]);
    const auto owned = soleCover(index, bare, inside, min_edge, &near);
    c->splits[i] = splitPoints(index, owned[i], o);
    c->measured[i] = true;
    queries[i] = c->splits[i].ua.queries + c->splits[i].ub.queries;
  });
  for (int64_t q : queries) res->optimizer_queries += q;
}

}  // namespace

PointSplit splitPoints(const SolidIndex& index, const std::vector<Vec3>& points,
                       const FitOptions& o) {
  PointSplit s;
  if (points.size() < 2) return s;
  splitTwoMeans(points, &s.a, &s.b);
  if (s.a.empty() || s.b.empty()) return s;
  s.ua = updateSphere(index, s.a, centroid(s.a), o.optimizer, o.optimizer_evaluations);
  s.ub = updateSphere(index, s.b, centroid(s.b), o.optimizer, o.optimizer_evaluations);
  s.ok = true;
  return s;
}

SplitChain startChain(std::vector<Sphere> spheres, std::vector<double> sov) {
  SplitChain c;
  c.count = static_cast<int>(spheres.size());
  c.sov = std::move(sov);
  c.spheres = std::move(spheres);
  c.splits.assign(c.spheres.size(), {});
  c.measured.assign(c.spheres.size(), false);
  return c;
}

bool splitLocally(const SolidIndex& index, const PointSet& ps, const FitOptions& o,
                  SplitChain* chain, FitResult* res) {
  SplitChain& c = *chain;
  auto t = FitClock::now();
  const double min_edge = boundMinEdge(index, ps);
  measureChain(index, ps, o, min_edge, &c, res);
  int best = -1;
  double best_gain = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < c.spheres.size(); ++i) {
    if (!c.splits[i].ok) continue;
    const double gain = c.sov[i] - (c.splits[i].ua.sov + c.splits[i].ub.sov);
    if (gain > best_gain) best_gain = gain, best = static_cast<int>(i);
  }
  res->seconds.teleport += secondsSince(t);
  if (best < 0) return false;
  t = FitClock::now();
  const int n = static_cast<int>(c.spheres.size());
  const Sphere old = c.spheres[best];
  PointSplit split = std::move(c.splits[best]);
  // The bound works on the radii before padding; a sphere it does not grow keeps its padded one.
  std::vector<Sphere> bare = unpadded(c.spheres, o.padding);
  bare[best] = split.ua.sphere;
  bare.push_back(split.ub.sphere);
  const std::vector<Sphere> before = bare;
  std::vector<std::vector<Vec3>> members(n + 1);
  members[best] = std::move(split.a);
  members[n] = std::move(split.b);
  const Aabb region = ballBox(old);
  const Mesh surface = trianglesMeeting(index.mesh(), region);
  std::vector<bool> refittable(n + 1, false);
  refittable[best] = refittable[n] = true;
  boundWithRefits(index, &bare, &members, min_edge, true, o, res, &surface, &refittable);
  boundInteriorPasses(index, &bare, res, &region);
  if (o.original) {
    const Mesh original = trianglesMeeting(*o.original, region);
    const BoundStats ob = boundSurface(index, &bare, min_edge, nullptr, &original);
    res->bounding_pieces += ob.pieces;
    res->bounding_queries += ob.queries;
  }
  // The spheres that changed: the halves, and those the bound grew.
  c.spheres.push_back(Sphere{});
  c.sov.push_back(0.0);
  c.splits.emplace_back();
  c.measured.push_back(false);
  std::vector<int> changed;
  for (int i = 0; i <= n; ++i)
    if (i == best || i == n || bare[i].radius != before[i].radius) {
      changed.push_back(i);
      c.spheres[i] = bare[i];
      c.spheres[i].radius += o.padding;
    }
  // What a sphere near the old one alone covers may have changed: measured again when needed.
  for (int i = 0; i <= n; ++i)
    if (boxesMeet(ballBox(c.spheres[i]), region)) c.measured[i] = false;
  tbb::parallel_for(size_t{0}, changed.size(), [&](size_t k) {
    c.sov[changed[k]] = index.outsideVolume(c.spheres[changed[k]]).volume;
  });
  res->bounding_queries += static_cast<int64_t>(changed.size());
  c.count = n + 1;
  res->spheres = c.spheres;
  res->outside_volume = c.sov;
  res->energy = totalOf(c.sov);
  res->seconds.bound += secondsSince(t);
  return true;
}

}  // namespace sphereset::detail

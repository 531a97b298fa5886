// One sphere more or fewer by a single local split or removal (beyond the paper). Reference: Wang
// et al. 2006, Sec. 5, "Sphere Teleportation", splits a cluster in two from "the two points
// farthest from each other" and refits both halves (Eq. 5); here that split, made on a bounded fit,
// is the whole step from n to n + 1 spheres. Deviation: what is split is not the sphere's cluster
// but what it alone covers (the surface pieces and interior points no other sphere holds, as the
// shrinking refits them: shrink.cpp), so that the halves together take over its share of the bound
// rather than its samples (splitting the clusters' points instead left steps that raised E_r: the
// halves lost the refinement's fit to the surface between the samples and grew back in the bound).
// The sphere whose split lowers the outside volume most (its bounded sphere's against the two
// refitted halves') is replaced by the halves, and only the solid within the old sphere's box is
// bounded again (bound_refit.cpp, bound.cpp, restricted to that box). Every other sphere keeps
// its radius or grows, so whatever lay outside the box stays covered. One sphere fewer is the
// other half of the paper's teleport (Sec. 5: a sphere taken from where it costs least, its
// points left to its neighbours; teleport.cpp's removalCosts): the sphere whose removal adds
// least (what it alone covers taken by the neighbours that grow least, about fixed centres) is
// removed and its box bounded again by the others growing.
//
// The local bound splits pieces as finely as the refinement bounds its result (kRefineFineEdge of
// the fit's smallest pieces): the sets it starts from were bounded that finely, and the fit's
// coarser pieces made it grow many of their spheres (spot.obj 64 to 63: 24 spheres grew, 6 with
// the finer pieces, E_r 0.182 against 0.178).
//
// Deviation from a fit at n + 1 (fit.cpp, progressive.cpp): no rounds, teleports, shrinking or
// refinement, so a step costs a few sphere updates and a bound of one sphere's neighbourhood
// instead of a whole clustering and ending, and its set is looser than a fit's at the same count
// (docs/benchmarks.md, "Progressive fitting").
#include "fit/local_split.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "cover/sphere_grid.hpp"
#include "fit/bound_refit.hpp"
#include "fit/fit_common.hpp"
#include "fit/refine.hpp"
#include "fit/teleport.hpp"
#include "mesh/weld.hpp"
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

// The rounding allowance of ballsMeet, relative to the magnitudes of the centres and radii
// (a length per unit length): far above the rounding of the containment tests.
constexpr double kMeetRel = 1e-9;

// Whether two balls may share a point, allowing for rounding: false only when no point lies in
// both as Sphere::contains decides.
bool ballsMeet(const Sphere& a, const Sphere& b) {
  const double reach = a.radius + b.radius;
  const double scale = reach + a.center.cwiseAbs().maxCoeff() + b.center.cwiseAbs().maxCoeff();
  return (a.center - b.center).norm() <= reach + kMeetRel * scale;
}

// The triangles of `mesh` whose bounding box meets `box`, in their order, with only the vertices
// they use (a step near one sphere of a large mesh copied all of its vertices).
Mesh trianglesMeeting(const Mesh& mesh, const Aabb& box) {
  Mesh out;
  std::unordered_map<int32_t, int32_t> index_of;  // the mesh's vertex -> out's
  for (const Triangle& t : mesh.triangles) {
    Aabb b;
    for (int k = 0; k < 3; ++k) b.extend(mesh.vertices[t[k]]);
    if (!boxesMeet(b, box)) continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k) {
      const auto [it, fresh] =
          index_of.try_emplace(t[k], static_cast<int32_t>(out.vertices.size()));
      if (fresh) out.vertices.push_back(mesh.vertices[t[k]]);
      kept[k] = it->second;
    }
    out.triangles.push_back(kept);
  }
  return out;
}

// The spheres without their padding.
std::vector<Sphere> unpadded(const std::vector<Sphere>& spheres, double padding) {
  std::vector<Sphere> bare = spheres;
  for (Sphere& s : bare) s.radius = std::max(0.0, s.radius - padding);
  return bare;
}

// The outside volume sphere i's removal adds, to first order (as teleport.cpp's removalCosts):
// each point only it covers joins the other sphere that grows least to hold it, about its fixed
// centre; the grown spheres' outside volumes less sphere i's. `owned` lists each piece's vertices,
// so a vertex comes once per piece that has it (about six times inside a split triangle); the
// growths are maxima, so each point is taken once, in the order first met (weldVertices, exact):
// the same cost, and the removals' measures took 6 % of fr3_link1_collision.stl's curve (perf, one
// thread) instead of 12.
double removalCost(const SolidIndex& index, const SplitChain& c, const SphereGrid& grid,
                   const std::vector<Vec3>& owned, int i, int64_t* queries) {
  std::vector<std::pair<int32_t, double>> grown;
  std::vector<Vec3> points;
  weldVertices(owned, 0.0, &points);
  for (const Vec3& p : points) {
    std::pair<double, int32_t> least[2];
    const int m = leastGrowth(grid, &p, 1, 2, least);
    const int k = least[0].second == i ? 1 : 0;
    if (k >= m) return std::numeric_limits<double>::infinity();  // no other sphere
    auto it = std::find_if(grown.begin(), grown.end(),
                           [&](const auto& g) { return g.first == least[k].second; });
    if (it == grown.end())
      grown.emplace_back(least[k].second, least[k].first);
    else
      it->second = std::max(it->second, least[k].first);
  }
  double cost = -c.sov[i];
  for (const auto& [k, g] : grown) {
    const Sphere& s = c.spheres[k];
    cost += index.outsideVolume({s.center, s.radius + g}).volume - c.sov[k];
    ++*queries;
  }
  return cost;
}

// Measures, for every sphere not yet measured, its split (`split`) or its removal's cost (else),
// from what it alone covers among the triangles near it and the interior points in it (in
// parallel, deterministic per sphere).
void measureChain(const SolidIndex& index, const PointSet& ps, const FitOptions& o, double min_edge,
                  bool split, SplitChain* c, FitResult* res) {
  const std::vector<Sphere> bare = unpadded(c->spheres, o.padding);
  const SphereGrid grid(bare);
  std::vector<bool>& measured = split ? c->split_measured : c->removal_measured;
  std::vector<int64_t> queries(c->spheres.size(), 0);
  tbb::parallel_for(size_t{0}, c->spheres.size(), [&](size_t i) {
    if (measured[i]) return;
    pollCancel();
    const Sphere& s = bare[i];
    const Mesh near = trianglesMeeting(index.mesh(), ballBox(s));
    std::vector<Vec3> inside;
    for (int64_t k = 0; k < ps.interior; ++k)
      if ((ps.points[k] - s.center).norm() <= s.radius) inside.push_back(ps.points[k]);
    const auto owned = soleCover(index, bare, inside, min_edge, &near, static_cast<int>(i));
    if (split) {
      PointSplit& h = c->splits[i];
      h = splitPoints(index, owned[i], o);
      queries[i] = h.ua.queries + h.ub.queries;
      // The halves are bare; with padding they are compared padded, as the sphere they replace.
      double halves = h.ua.sov + h.ub.sov;
      if (h.ok && o.padding > 0.0) {
        halves = 0.0;
        for (const Sphere& b : {h.ua.sphere, h.ub.sphere})
          halves += index.outsideVolume({b.center, b.radius + o.padding}).volume;
        queries[i] += 2;
      }
      c->gain[i] = h.ok ? c->sov[i] - halves : -std::numeric_limits<double>::infinity();
    } else {
      c->removal[i] = removalCost(index, *c, grid, owned[i], static_cast<int>(i), &queries[i]);
    }
  });
  // vector<bool> is not safe to write from several threads: marked afterwards.
  measured.assign(measured.size(), true);
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
  c.gain.assign(c.spheres.size(), 0.0);
  c.removal.assign(c.spheres.size(), 0.0);
  c.split_measured.assign(c.spheres.size(), false);
  c.removal_measured.assign(c.spheres.size(), false);
  return c;
}

namespace {

// Bounds again the solid within `region` (nothing outside it lost its cover): the surface's
// triangles that meet it with refits of the `refittable` spheres (their points in `members`),
// the interior cubes that meet it, and the original's triangles.
void boundRegion(const SolidIndex& index, const FitOptions& o, double min_edge, const Aabb& region,
                 std::vector<Sphere>* bare, std::vector<std::vector<Vec3>>* members,
                 const std::vector<bool>& refittable, GeometryForest* cells, FitResult* res) {
  const Mesh surface = trianglesMeeting(index.mesh(), region);
  const bool refit = std::find(refittable.begin(), refittable.end(), true) != refittable.end();
  boundWithRefits(index, bare, members, min_edge, refit, o, res, &surface, &refittable);
  boundInteriorPasses(index, bare, res, &region, cells);
  if (o.original) {
    const Mesh original = trianglesMeeting(*o.original, region);
    const BoundStats ob = boundSurface(index, bare, min_edge, nullptr, &original);
    res->bounding_pieces += ob.pieces;
    res->bounding_queries += ob.queries;
  }
}

// Takes the bounded set into the chain: the spheres `moved` and those whose radius the bound
// changed from `before` get their padding and outside volume, and the spheres near them or
// `gone` (the padded sphere split or removed) a new measure; fills res.
void takeIntoChain(const SolidIndex& index, const FitOptions& o, const std::vector<Sphere>& bare,
                   const std::vector<Sphere>& before, const std::vector<int>& moved,
                   const Sphere& gone, SplitChain* chain, FitResult* res) {
  SplitChain& c = *chain;
  std::vector<int> changed;
  for (int i = 0; i < static_cast<int>(bare.size()); ++i)
    if (std::find(moved.begin(), moved.end(), i) != moved.end() ||
        bare[i].radius != before[i].radius) {
      changed.push_back(i);
      c.spheres[i] = bare[i];
      c.spheres[i].radius += o.padding;
    }
  // What a sphere alone covers changes only where its ball meets the gone sphere's or a changed
  // one's (a grown sphere's old ball lies in its new one, a moved one's is `gone`): a piece or
  // point it alone holds lies in its ball, and so does every piece a change could make held or
  // unheld above it. Its split is measured from that alone (measureChain), so a sphere whose
  // ball meets none of them keeps its split. Its removal's cost also depends on which neighbour
  // grows least to take its points, which a change beyond its ball can alter: it is measured
  // again when its box meets one of theirs, a heuristic.
  std::vector<Sphere> touched{gone};
  for (int i : changed) touched.push_back(c.spheres[i]);
  for (size_t i = 0; i < c.spheres.size(); ++i)
    for (const Sphere& b : touched) {
      if (ballsMeet(c.spheres[i], b)) c.split_measured[i] = false;
      if (boxesMeet(ballBox(c.spheres[i]), ballBox(b))) c.removal_measured[i] = false;
    }
  tbb::parallel_for(size_t{0}, changed.size(), [&](size_t k) {
    c.sov[changed[k]] = index.outsideVolume(c.spheres[changed[k]]).volume;
  });
  res->bounding_queries += static_cast<int64_t>(changed.size());
  c.count = static_cast<int>(c.spheres.size());
  res->spheres = c.spheres;
  res->outside_volume = c.sov;
  res->energy = totalOf(c.sov);
}

}  // namespace

bool splitLocally(const SolidIndex& index, const PointSet& ps, const FitOptions& o,
                  SplitChain* chain, FitResult* res, GeometryForest* cells) {
  SplitChain& c = *chain;
  auto t = FitClock::now();
  const double min_edge = kRefineFineEdge * boundMinEdge(index, ps);
  measureChain(index, ps, o, min_edge, true, &c, res);
  int best = -1;
  double best_gain = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < c.spheres.size(); ++i) {
    if (c.splits[i].ok && c.gain[i] > best_gain) best_gain = c.gain[i], best = static_cast<int>(i);
  }
  res->seconds.teleport += secondsSince(t);
  if (best < 0) return false;
  t = FitClock::now();
  const int n = static_cast<int>(c.spheres.size());
  const Sphere gone = c.spheres[best];
  const Aabb region = ballBox(gone);
  PointSplit split = std::move(c.splits[best]);
  // The bound works on the radii before padding; a sphere it does not grow keeps its padded one.
  std::vector<Sphere> bare = unpadded(c.spheres, o.padding);
  bare[best] = split.ua.sphere;
  bare.push_back(split.ub.sphere);
  const std::vector<Sphere> before = bare;
  std::vector<std::vector<Vec3>> members(n + 1);
  members[best] = std::move(split.a);
  members[n] = std::move(split.b);
  std::vector<bool> refittable(n + 1, false);
  refittable[best] = refittable[n] = true;
  boundRegion(index, o, min_edge, region, &bare, &members, refittable, cells, res);
  c.spheres.emplace_back();
  c.sov.push_back(0.0);
  c.splits.emplace_back();
  c.gain.push_back(0.0);
  c.removal.push_back(0.0);
  c.split_measured.push_back(false);
  c.removal_measured.push_back(false);
  takeIntoChain(index, o, bare, before, {best, n}, gone, &c, res);
  res->seconds.bound += secondsSince(t);
  return true;
}

bool removeLocally(const SolidIndex& index, const PointSet& ps, const FitOptions& o,
                   SplitChain* chain, FitResult* res, GeometryForest* cells) {
  SplitChain& c = *chain;
  const int n = static_cast<int>(c.spheres.size());
  if (n < 2) return false;
  auto t = FitClock::now();
  const double min_edge = kRefineFineEdge * boundMinEdge(index, ps);
  measureChain(index, ps, o, min_edge, false, &c, res);
  int worst = -1;
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i)
    if (c.removal[i] < least) least = c.removal[i], worst = i;
  res->seconds.teleport += secondsSince(t);
  if (worst < 0) return false;
  t = FitClock::now();
  const Sphere gone = c.spheres[worst];
  const Aabb region = ballBox(gone);
  // The last sphere takes the removed one's place, so that the others keep their indices.
  const auto drop = [&](auto& v) {
    v[worst] = std::move(v.back());
    v.pop_back();
  };
  drop(c.spheres);
  drop(c.sov);
  drop(c.splits);
  drop(c.gain);
  drop(c.removal);
  for (std::vector<bool>* m : {&c.split_measured, &c.removal_measured}) {
    (*m)[worst] = m->back();
    m->pop_back();
  }
  std::vector<Sphere> bare = unpadded(c.spheres, o.padding);
  const std::vector<Sphere> before = bare;
  std::vector<std::vector<Vec3>> members(bare.size());
  boundRegion(index, o, min_edge, region, &bare, &members, std::vector<bool>(bare.size(), false),
              cells, res);
  // The sphere moved into `worst` kept its padded radius and outside volume (drop), so only the
  // spheres the bound grew are taken again.
  takeIntoChain(index, o, bare, before, {}, gone, &c, res);
  res->seconds.bound += secondsSince(t);
  return true;
}

}  // namespace sphereset::detail

// Guaranteed bounding (beyond the paper, whose footnote 1 only enlarges spheres to contain
// sampled points, edge midpoints and triangle centres). Every triangle is covered exactly:
// a triangle lies in a ball as soon as its three vertices do, so each triangle is split
// until every piece has that property, and pieces too small to split further (edge below
// min_edge) make a sphere grow. Requests are collected in parallel against the radii before
// the step and then applied as per-sphere maxima; radii only grow, so every piece stays
// covered and the result does not depend on the order or the number of threads.
#include "fit/bound.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include "cover/cover_cells.hpp"
#include "fit/fit_common.hpp"
#include "sphereset/cover.hpp"

namespace sphereset::detail {
namespace {

constexpr int kCandidates = 3;  // spheres whose outside-volume growth is compared per piece

// A piece's request: its cheapest sphere and the radius that holds it. Kept per triangle, one
// per sphere (the largest radius), with the pieces only when the caller wants them.
struct Request {
  int32_t sphere = -1;
  double radius = 0.0;
};

struct TriangleRequests {
  std::vector<Request> grow;                                    // one per sphere
  std::vector<std::pair<int32_t, std::array<Vec3, 3>>> pieces;  // (sphere, piece) if wanted
  std::vector<std::pair<int32_t, Vec3>> centroids;              // or only their centroids
  int64_t count = 0;

  void add(const Request& r, const std::array<Vec3, 3>& piece, const SurfaceBoundOptions& o) {
    ++count;
    const bool keep = o.held && (!o.held_for || (*o.held_for)[r.sphere]);
    if (keep && o.held_centroids)
      centroids.emplace_back(r.sphere, (piece[0] + piece[1] + piece[2]) / 3.0);
    else if (keep)
      pieces.emplace_back(r.sphere, piece);
    for (Request& g : grow)
      if (g.sphere == r.sphere) {
        g.radius = std::max(g.radius, r.radius);
        return;
      }
    grow.push_back(r);
  }
};

// The sphere whose outside volume grows least, to first order (dSOV/dr times the radius
// increase), when enlarged to hold the points; among the kCandidates needing the least radius
// increase. Writes its index and new radius (-1 when there are no spheres).
// `near`, if given: the candidates of a nearby piece (-1: none yet), replaced by these. The
// largest increase they need for these points is a reach at which the search (leastGrowth)
// already holds kCandidates spheres, so it stops there instead of growing from one grid cell;
// the answer is the same.
void cheapestGrowth(const SphereGrid& grid, const std::vector<double>& sov_dr, const Vec3* pts,
                    int npts, double slack, int32_t* sphere, double* radius,
                    std::array<int32_t, kCandidates>* near = nullptr) {
  double reach = 0.0;
  if (near && (*near)[kCandidates - 1] >= 0)
    for (int32_t i : *near) {
      const Sphere& s = grid.spheres()[i];
      double need = 0.0;
      for (int k = 0; k < npts; ++k) need = std::max(need, (pts[k] - s.center).norm());
      reach = std::max(reach, need - s.radius);
    }
  std::array<std::pair<double, int32_t>, kCandidates> cand;
  const int m = leastGrowth(grid, pts, npts, kCandidates, cand.data(), reach);
  if (near) {
    near->fill(-1);
    for (int k = 0; k < m; ++k) (*near)[k] = cand[k].second;
  }
  double best_inc = std::numeric_limits<double>::infinity();
  *sphere = -1;
  // Candidates come in increasing order of radius growth, so a strict comparison breaks
  // ties (spheres with no surface outside the solid, dSOV/dr = 0) by the smaller growth.
  for (int k = 0; k < m; ++k) {
    const auto [grow, i] = cand[k];
    const double inc = sov_dr[i] * grow;
    if (inc < best_inc) {
      best_inc = inc;
      *sphere = i;
      *radius = grid.spheres()[i].radius + grow + slack;
    }
  }
}

// dSOV/dr of each sphere (its outside surface area): the growth of the outside volume for a
// small enlargement dr is dSOV/dr * dr to first order, which ranks the candidates without a
// query per piece (pieces are small, so the enlargements are).
std::vector<double> radiusRates(const SolidIndex& index, const std::vector<Sphere>& sp,
                                BoundStats* st) {
  std::vector<double> sov_dr(sp.size());
  tbb::parallel_for(size_t{0}, sp.size(), [&](size_t i) {
    pollCancel();
    sov_dr[i] = index.outsideVolume(sp[i]).d_radius;
  });
  st->queries += static_cast<int64_t>(sp.size());
  return sov_dr;
}

// Radii only grow: each sphere takes the largest radius requested for it.
void growTo(std::vector<Sphere>* sp, const std::vector<double>& radius, BoundStats* st) {
  for (size_t i = 0; i < sp->size(); ++i)
    if (radius[i] > (*sp)[i].radius) {
      (*sp)[i].radius = radius[i];
      ++st->enlarged;
    }
}

}  // namespace

double splitPieceCount(const Mesh& mesh, double edge) {
  double count = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    int depth = 0;
    for (double e = longest; e > edge && depth < kSurfaceSplitDepth; e *= 0.5) ++depth;
    count += std::pow(4.0, depth);
  }
  return count;
}

BoundStats boundSurface(const SolidIndex& index, std::vector<Sphere>* spheres,
                        const SurfaceBoundOptions& o) {
  BoundStats st;
  std::vector<Sphere>& sp = *spheres;
  const Mesh& mesh = o.surface ? *o.surface : index.mesh();
  const double slack = kBoundSlackRel * index.bounds().diagonal();
  const int64_t nt = static_cast<int64_t>(mesh.triangles.size());
  const std::vector<double> sov_dr = radiusRates(index, sp, &st);
  const SphereGrid grid(sp);
  assert(!o.held_for || o.held_for->size() == sp.size());
  std::vector<TriangleRequests> req(nt);
  tbb::parallel_for(int64_t{0}, nt, [&](int64_t t) {
    const auto& tri = mesh.triangles[t];
    std::array<int32_t, kCandidates> near;  // the last small piece's candidates
    near.fill(-1);
    splitPieces(
        mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], o.min_edge,
        [&](const std::array<Vec3, 3>& v) { return oneSphereHolds(grid, v.data(), 3); },
        [&](const std::array<Vec3, 3>& v) {
          Request r;
          cheapestGrowth(grid, sov_dr, v.data(), 3, slack, &r.sphere, &r.radius, &near);
          if (r.sphere >= 0) req[t].add(r, v, o);
        });
  });
  if (o.held) {
    // Each list sized once: a bound after a large change holds millions of pieces, and lists
    // grown by doubling would touch (and fault in) several times their final memory.
    std::vector<size_t> sizes(sp.size(), 0);
    for (const TriangleRequests& r : req) {
      for (const auto& piece : r.pieces) sizes[piece.first] += 3;
      for (const auto& c : r.centroids) ++sizes[c.first];
    }
    o.held->resize(sp.size());  // cleared, keeping the capacity of a list given again
    for (size_t i = 0; i < sp.size(); ++i) {
      (*o.held)[i].clear();
      (*o.held)[i].reserve(sizes[i]);
    }
  }
  std::vector<double> radius(sp.size());
  for (size_t i = 0; i < sp.size(); ++i) radius[i] = sp[i].radius;
  for (int64_t t = 0; t < nt; ++t) {
    st.pieces += req[t].count;
    for (const Request& r : req[t].grow) radius[r.sphere] = std::max(radius[r.sphere], r.radius);
    for (const auto& [i, v] : req[t].pieces)
      (*o.held)[i].insert((*o.held)[i].end(), v.begin(), v.end());
    for (const auto& [i, c] : req[t].centroids) (*o.held)[i].push_back(c);
  }
  growTo(&sp, radius, &st);
  return st;
}

BoundStats boundInterior(const SolidIndex& index, std::vector<Sphere>* spheres, int max_depth,
                         const Aabb* region, GeometryForest* cells) {
  if (cells) cells->trim();
  BoundStats st;
  std::vector<Sphere>& sp = *spheres;
  const double slack = kBoundSlackRel * index.bounds().diagonal();
  const std::vector<double> sov_dr = radiusRates(index, sp, &st);
  const SphereGrid grid(sp);
  // An uncovered centre found above max_depth goes to the cheapest sphere and the walk
  // descends; at max_depth the cheapest sphere takes the whole cube (its eight corners). Requests
  // per root cube, applied as maxima afterwards.
  std::vector<std::vector<std::pair<int32_t, double>>> req(kRootCells);
  tbb::parallel_for(0, kRootCells, [&](int k) {
    pollCancel();
    double size = 0.0;
    const Vec3 mn = rootCell(index.bounds(), k, &size);
    const WalkScope scope{.region = region, .tree = cells ? &cells->trees[k] : nullptr};
    walkSolidCells(
        index, grid, mn, size, 0, max_depth,
        [&](const Vec3& lo, double s, int depth, double) {
          pollCancel();
          if (cubeMisses(region, lo, s)) return false;  // the walk's region is widened
          int32_t i = -1;
          double r = 0.0;
          if (depth < max_depth) {
            // The centre itself (the walk tests it), then the cubes below.
            const Vec3 centre = lo + Vec3::Constant(0.5 * s);
            cheapestGrowth(grid, sov_dr, &centre, 1, slack, &i, &r);
            if (i >= 0) req[k].emplace_back(i, r);
            return true;
          }
          Vec3 corners[8];
          for (int c = 0; c < 8; ++c)
            corners[c] = lo + s * Vec3((c & 1) ? 1 : 0, (c & 2) ? 1 : 0, (c & 4) ? 1 : 0);
          cheapestGrowth(grid, sov_dr, corners, 8, slack, &i, &r);
          if (i >= 0) req[k].emplace_back(i, r);
          return false;
        },
        [](const Vec3&, double) {}, nullptr, scope);
  });
  std::vector<double> radius(sp.size());
  for (size_t i = 0; i < sp.size(); ++i) radius[i] = sp[i].radius;
  for (const auto& list : req)
    for (const auto& [i, r] : list) {
      ++st.pieces;
      radius[i] = std::max(radius[i], r);
    }
  growTo(&sp, radius, &st);
  return st;
}

std::vector<std::vector<Vec3>> soleCover(const SolidIndex& index, const std::vector<Sphere>& sp,
                                         const std::vector<Vec3>& interior, double min_edge,
                                         const Mesh* surface, int only) {
  const Mesh& mesh = surface ? *surface : index.mesh();
  const int64_t nt = static_cast<int64_t>(mesh.triangles.size());
  const int ns = static_cast<int>(sp.size());
  const SphereGrid grid(sp);
  // Whether a piece's box misses sphere `only` (then no part of it is that sphere's alone).
  const auto misses_only = [&](const std::array<Vec3, 3>& v) {
    if (only < 0) return false;
    const Vec3 lo = v[0].cwiseMin(v[1]).cwiseMin(v[2]), hi = v[0].cwiseMax(v[1]).cwiseMax(v[2]);
    const Sphere& s = sp[only];
    return (s.center.cwiseMax(lo).cwiseMin(hi) - s.center).squaredNorm() > s.radius * s.radius;
  };
  // Per triangle, the pieces one sphere alone holds, as (sphere, vertices).
  std::vector<std::vector<std::pair<int32_t, std::array<Vec3, 3>>>> own(nt);
  tbb::parallel_for(int64_t{0}, nt, [&](int64_t t) {
    const auto& tri = mesh.triangles[t];
    // Pieces held by no single sphere are split further (the spheres cover them together);
    // tiny ones are left to the bounding step that follows.
    splitPieces(
        mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], min_edge,
        [&](const std::array<Vec3, 3>& v) {
          if (misses_only(v)) return true;
          int32_t holder = -1;
          const int h = holders(grid, v.data(), 3, &holder);
          if (h == 1) own[t].push_back({holder, v});
          return h > 0;
        },
        [](const std::array<Vec3, 3>&) {});
  });
  std::vector<std::vector<Vec3>> out(ns);
  for (const auto& list : own)
    for (const auto& [i, v] : list) out[i].insert(out[i].end(), v.begin(), v.end());
  for (const Vec3& p : interior) {
    int32_t holder = -1;
    if (holders(grid, &p, 1, &holder) == 1) out[holder].push_back(p);
  }
  return out;
}

}  // namespace sphereset::detail

// Coverage-aware refinement after the bound (beyond the paper). Reference: Wang et al. 2006,
// Sec. 3 (the energy: the sum over the spheres of their outside volume, Eq. 2) and Sec. 5: the
// clustering minimises it over sampled points, and footnote 1 then only enlarges spheres to
// bound what lies between the samples, so the two stages optimise different things and the
// bound costs 20 to 50 %. Here all spheres move at once to minimise the energy of a set that
// covers a dense set of points: the vertices of the triangles split until their edges are at
// most the clustering's surface spacing, and the interior points. Coverage is a penalty,
// weight * gap^2 for each point in no sphere (gap: its distance to the nearest sphere),
// minimised by L-BFGS over the centres and radii with the exact gradients of the outside
// volume (docs/outside-volume.md) at weights growing by stages. The exact bound (bound.cpp)
// then makes the result cover the surface, with pieces finer than the fit's own bound (a piece
// joins a sphere whole, so pieces coarser than the points would undo what the points allow).
// The pieces that still made a sphere grow mark where the points were too sparse (where the
// spheres' rims meet on the surface): their centroids join the points and the last stage runs
// again from the bounded set, a few times. The best bounded set is kept if its energy is below
// the set's the refinement started from.
//
// Deviation from a fixed point of exact assignments: the first version of this stage alternated
// giving each surface piece and interior point to the sphere holding it most deeply with the
// sphere update (Eq. 5) of each sphere subject to holding exactly its own pieces. It stopped in
// one round with no gain (spot, n = 32: E_r 0.2813 -> 0.2813): the pieces that set a sphere's
// radius are held by that sphere alone, so moving one sphere at a time cannot move the border
// between two. Moving all spheres at once under the penalty does (0.2813 -> 0.224).
#include "fit/refine.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <utility>

#include "cover/sphere_grid.hpp"
#include "fit/bound.hpp"
#include "fit/fit_common.hpp"
#include "fit/guarded_optimize.hpp"

namespace sphereset::detail {
namespace {

// The penalty's schedule: the first weight makes a gap of the bound's smallest piece at every
// point cost kPenaltyStart times what shrinking every sphere by that length saves; it grows by
// kPenaltyGrowth at each of kPenaltyStages stages of at most kPenaltyEvaluations L-BFGS
// evaluations. A softer penalty does better: the exact bound closes the gaps it leaves more
// cheaply than a stiff penalty forbids them. Over spot, decimated-knight, fertility, fandisk,
// rocker-arm and ur5_upperarm at n = 16, 32, 64 (seed 1), E_r against a start of 100 was 0.94
// at 1 (0.95 at 0.3 and at 3, 0.99 at 0.1, 1.07 at 1000); 3 or 5 stages, growth 5, 30 or 100
// evaluations and 4 densifying rounds were no better than these (docs/benchmarks.md).
constexpr double kPenaltyStart = 1.0;
constexpr double kPenaltyGrowth = 10.0;
constexpr int kPenaltyStages = 4;
constexpr int kPenaltyEvaluations = 60;
// The exact bound of the result splits pieces down to kRefineFineEdge (refine.hpp) times the
// fit's `min_edge`; pieces still in no single sphere add their centroids to the points and the
// last stage runs again, at most kDensifyRounds times. The bound keeps only those centroids (a
// region the penalty left uncovered can split into a million pieces: 920 679 on ur5_upperarm at
// n = 32, 192 MB peak when each kept its vertices and its request, 90 MB now).
constexpr int kDensifyRounds = 2;
// The surface's points come from at most this many pieces per clustered point (the triangles
// are split coarser if needed), and the points with those the densification adds are at most
// as many: the points' cost stays in proportion to the clustering's.
constexpr double kMaxPiecesPerPoint = 10.0;

using PointList = std::vector<Vec3>;

bool lexLess(const Vec3& a, const Vec3& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

// The vertices of the triangles split until their edges are at most `spacing` (coarser if that
// would make more than `max_pieces` pieces, as slivers do), and the interior points, each once,
// in a fixed order.
PointList coveragePoints(const SolidIndex& index, const PointList& interior, double spacing,
                         double max_pieces) {
  const Mesh& mesh = index.mesh();
  // Unsplit triangles are the fewest pieces there can be.
  max_pieces = std::max(max_pieces, static_cast<double>(mesh.triangles.size()));
  while (splitPieceCount(mesh, spacing) > max_pieces) spacing *= 2.0;
  const int64_t nt = static_cast<int64_t>(mesh.triangles.size());
  std::vector<PointList> per(nt);
  tbb::parallel_for(int64_t{0}, nt, [&](int64_t t) {
    const auto& tri = mesh.triangles[t];
    splitPieces(
        mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], spacing,
        [](const std::array<Vec3, 3>&) { return false; },
        [&](const std::array<Vec3, 3>& v) { per[t].insert(per[t].end(), v.begin(), v.end()); });
  });
  PointList pts(interior);
  for (const PointList& list : per) pts.insert(pts.end(), list.begin(), list.end());
  std::sort(pts.begin(), pts.end(), lexLess);
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

// The centroids of the pieces in `held` added to *pts, evenly thinned to keep *pts within
// `max_points`. Returns whether any was added.
bool addCentroids(const std::vector<std::vector<Vec3>>& held, double max_points, PointList* pts) {
  size_t pieces = 0;
  for (const auto& list : held) pieces += list.size();
  const double room = max_points - static_cast<double>(pts->size());
  if (pieces == 0 || room < 1.0) return false;
  const size_t stride = static_cast<size_t>(std::ceil(static_cast<double>(pieces) / room));
  size_t k = 0;
  for (const auto& list : held)
    for (const Vec3& c : list)
      if (k++ % stride == 0) pts->push_back(c);
  return true;
}

std::vector<double> pack(const std::vector<Sphere>& sp) {
  std::vector<double> x(4 * sp.size());
  for (size_t i = 0; i < sp.size(); ++i) {
    for (int a = 0; a < 3; ++a) x[4 * i + a] = sp[i].center[a];
    x[4 * i + 3] = sp[i].radius;
  }
  return x;
}

std::vector<Sphere> unpack(const std::vector<double>& x) {
  std::vector<Sphere> sp(x.size() / 4);
  for (size_t i = 0; i < sp.size(); ++i)
    sp[i] = {Vec3(x[4 * i], x[4 * i + 1], x[4 * i + 2]), x[4 * i + 3]};
  return sp;
}

// A point's gap to the nearest sphere when it is in none (sphere -1 when it is in one).
struct PointState {
  int32_t sphere = -1;
  double gap = 0.0;
};

// `hint`: the sphere that held p at the previous evaluation, or was nearest to it (-1: none),
// tried first and updated. Neither changes the answer: only whether p is held matters, and the
// nearest sphere's search (leastGrowth) ends at the same sphere from any starting reach; the
// last nearest sphere's gap is a reach that holds the answer at once.
PointState pointState(const SphereGrid& grid, const Vec3& p, int32_t* hint) {
  PointState s;
  const auto& sp = grid.spheres();
  const int32_t last = *hint;
  if (last >= 0 && sp[last].contains(p)) return s;
  if (holders(grid, &p, 1, hint) > 0) return s;
  double reach = 0.0;
  if (last >= 0) reach = (p - sp[last].center).norm() - sp[last].radius;
  std::pair<double, int32_t> least{0.0, -1};
  if (leastGrowth(grid, &p, 1, 1, &least, reach) > 0 && least.first > 0.0) {
    s.sphere = least.second;
    s.gap = least.first;
  }
  *hint = least.second;
  return s;
}

// The penalised energy Σ_i SOV(c_i, r_i) + weight Σ_p gap(p)^2 over the active points, with
// its gradient; x = (c_0, r_0, c_1, r_1, ...). Keeps the least value evaluated and where.
class PenalisedEnergy {
 public:
  explicit PenalisedEnergy(const SolidIndex& index) : index_(index) {}

  double operator()(const double* x, double* grad, int nx) {
    pollCancel();
    const std::vector<Sphere> sp = unpack(std::vector<double>(x, x + nx));
    const int n = static_cast<int>(sp.size());
    std::vector<OutsideVolume> ov(n);
    tbb::parallel_for(0, n, [&](int i) { ov[i] = index_.outsideVolume(sp[i]); });
    queries += n;
    const SphereGrid grid(sp);
    std::vector<PointState> st(points.size());
    hints_.resize(points.size(), -1);
    tbb::parallel_for(size_t{0}, points.size(),
                      [&](size_t k) { st[k] = pointState(grid, points[k], &hints_[k]); });
    double f = 0.0;  // summed in a fixed order, whatever the threads
    for (int i = 0; i < n; ++i) {
      f += ov[i].volume;
      if (!grad) continue;
      for (int a = 0; a < 3; ++a) grad[4 * i + a] = ov[i].gradient[a];
      grad[4 * i + 3] = ov[i].d_radius;
    }
    for (size_t k = 0; k < points.size(); ++k) {
      const auto [i, g] = st[k];
      if (i < 0) continue;
      f += weight * g * g;
      if (!grad) continue;
      // gap = |p - c_i| - r_i: d/dc_i = (c_i - p) / |p - c_i|, d/dr_i = -1.
      const Vec3 d = sp[i].center - points[k];
      const double len = d.norm();
      const double w = 2.0 * weight * g;
      if (len > 0.0)
        for (int a = 0; a < 3; ++a) grad[4 * i + a] += w * d[a] / len;
      grad[4 * i + 3] -= w;
    }
    if (f < best_f) {
      best_f = f;
      best_x.assign(x, x + nx);
    }
    return f;
  }

  double weight = 0.0;
  PointList points;  // the points kept covered
  double best_f = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  int64_t queries = 0;
  ObjectiveGuard guard;  // carries the energy's exceptions out of NLopt

 private:
  const SolidIndex& index_;
  std::vector<int32_t> hints_;  // per point, the sphere that last held it
};

// L-BFGS from x at the energy's weight; x becomes the best point evaluated.
void runLbfgs(PenalisedEnergy* energy, const std::vector<double>& lo, const std::vector<double>& hi,
              std::vector<double>* x) {
  nlopt::opt opt(nlopt::LD_LBFGS, static_cast<unsigned>(x->size()));
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  opt.set_maxeval(kPenaltyEvaluations);
  opt.set_ftol_rel(1e-9);
  opt.set_min_objective(
      [](unsigned nx, const double* xx, double* g, void* data) {
        auto* e = static_cast<PenalisedEnergy*>(data);
        return e->guard.call([&] { return (*e)(xx, g, static_cast<int>(nx)); });
      },
      energy);
  energy->best_f = std::numeric_limits<double>::infinity();
  double f = 0.0;
  // Round-off or a forced stop ends it quietly (the best point evaluated is kept, below); a
  // cancellation or an allocation failure inside the energy is rethrown.
  energy->guard.optimize(&opt, x, &f);
  if (!energy->best_x.empty()) *x = energy->best_x;
}

}  // namespace

RefineStats refineCoverage(const SolidIndex& index, const std::vector<Vec3>& interior,
                           double spacing, double min_edge, int64_t clustered,
                           std::vector<Sphere>* sp) {
  RefineStats st;
  const std::vector<double> sov = outsideVolumes(index, *sp);
  st.queries += static_cast<int64_t>(sp->size());
  const double before = totalOf(sov);
  const int n = static_cast<int>(sp->size());
  std::vector<double> x(4 * n), lo(4 * n), hi(4 * n);
  const Aabb& b = index.bounds();
  const double reach = b.diagonal();
  double rate = 0.0;  // Σ dSOV/dr
  for (int i = 0; i < n; ++i) {
    const Sphere& s = (*sp)[i];
    for (int a = 0; a < 3; ++a) {
      x[4 * i + a] = s.center[a];
      lo[4 * i + a] = b.min[a] - reach;
      hi[4 * i + a] = b.max[a] + reach;
    }
    x[4 * i + 3] = s.radius;
    lo[4 * i + 3] = 0.0;
    hi[4 * i + 3] = 2.0 * reach;
    rate += index.outsideVolume(s).d_radius;
  }
  PenalisedEnergy energy(index);
  const double max_points = kMaxPiecesPerPoint * static_cast<double>(clustered);
  energy.points = coveragePoints(index, interior, spacing, max_points);
  energy.weight = kPenaltyStart * rate /
                  (static_cast<double>(std::max<size_t>(1, energy.points.size())) * min_edge);
  PointList& all = energy.points;
  for (int stage = 0; stage < kPenaltyStages; ++stage) {
    if (stage > 0) energy.weight *= kPenaltyGrowth;
    runLbfgs(&energy, lo, hi, &x);
  }
  // The exact bound of the result; its uncovered pieces densify the points for another stage.
  std::vector<Sphere> best_set;
  double after = std::numeric_limits<double>::infinity();
  for (int round = 0; round <= kDensifyRounds; ++round) {
    std::vector<Sphere> cand = unpack(x);
    std::vector<std::vector<Vec3>> held;
    SurfaceBoundOptions bo;
    bo.min_edge = kRefineFineEdge * min_edge;
    bo.held = &held;
    bo.held_centroids = true;
    const BoundStats bs = boundSurface(index, &cand, bo);
    const double e = totalOf(outsideVolumes(index, cand));
    st.queries += bs.queries + n;
    if (e < after) {
      after = e;
      best_set = std::move(cand);
    }
    if (round == kDensifyRounds || !addCentroids(held, max_points, &all)) break;
    x = pack(best_set);
    runLbfgs(&energy, lo, hi, &x);
  }
  st.points = static_cast<int64_t>(all.size());
  st.queries += energy.queries;
  st.energy = std::min(before, after);
  if (after < before) {
    *sp = std::move(best_set);
    st.kept = true;
  }
  return st;
}

}  // namespace sphereset::detail

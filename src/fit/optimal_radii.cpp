// Optimal radii for given centres (beyond the paper). Reference: Wang et al. 2006, Sec. 3 (the
// energy, Eq. 2: the sum over the spheres of their outside volume); the program is a covering
// integer program solved by branch and bound (COIN-OR CBC, Forrest and Lougee-Heimer 2005) in the
// incremental (staircase) form of facility location with nested service radii.
//
// With the centres fixed, a sphere's radius only has to reach the farthest vertex of the units
// it is given, so each radius is one of finitely many levels (the distances from its centre to
// the units it may take) and the outside volume of each level is exact (docs/outside-volume.md).
// Binary x[j][k] says "sphere j reaches level k"; x[j][k] <= x[j][k-1]; the cost of x[j][k] is
// SOV(c_j, L_jk) - SOV(c_j, L_j,k-1) >= 0, so Σ cost x is the energy; a unit u is covered when
// some candidate j has x[j][k(u, j)] = 1, k(u, j) the first level reaching u. Units: the
// surface's triangles split in four until one sphere holds each piece (down to `unit_edge`; the
// pieces follow the spheres' rims on the surface) and the interior points; candidates of a unit:
// up to kCandidates spheres needing the least radius increase to hold it (those holding it come
// first). The current set is a solution (its radii are levels), given to CBC as the start.
//
// Deviations from an exact optimum, each reported rather than hidden: a sphere's levels are
// quantised upwards (a requirement is rounded up to the next level, so a solution covers what it
// claims), branch and bound stops after kMaxNodes nodes, and the units only sample the surface
// between them (the solution is bounded exactly afterwards, bound.cpp, and kept only if its
// exact energy is lower). The program's objective and CBC's proven lower bound give the gap.
//
// Measured (docs/benchmarks.md, "Optimal radii"): after the coverage-aware refinement the
// program's optimum is within 0.01 % of the refined set's own radii (fr3_link1, n = 32:
// 0.000760437 against 0.000760499; ur5_upperarm 0.00193934 against 0.00194104), so the
// refinement already leaves the radii optimal for its centres; the program certifies it.
// Moving each centre to hold the units the solution gave it (the sphere update, Eq. 5) and
// solving again was worse (fr3_link1: 0.000784; ur5_upperarm: 0.00200) and is not done; in
// place of the refinement the program alone gave E_r 0.302 and 0.410 against the refinement's
// 0.256 and 0.387.
#include "fit/optimal_radii.hpp"

#include <Cbc_C_Interface.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "cover/sphere_grid.hpp"
#include "fit/bound.hpp"
#include "fit/cbc_settings.hpp"
#include "fit/fit_common.hpp"
#include "fit/refine.hpp"

namespace sphereset::detail {
namespace {

// Spheres that may take a unit.
constexpr int kCandidates = 4;
// Radius levels per sphere besides its current radius: quantiles of the requirements below it
// (how far it may shrink) and above it (how far it may grow).
constexpr int kShrinkLevels = 32;
constexpr int kGrowLevels = 16;
// A sphere is a candidate for a unit it does not hold only if it grows by at most this fraction
// of its radius to hold it (the least-growth sphere of each unit always is).
constexpr double kGrowWindow = 0.25;
// Branch-and-bound nodes at most per program (a node limit, not a time limit, keeps the result
// independent of the machine's speed).
constexpr int kMaxNodes = 2000;
// Coverage rows (after reduction) above which the program is not attempted: its linear
// relaxations would take longer than the fit (the selection's ILP stops at 200 000 classes).
constexpr size_t kMaxRows = 100000;
// A column above this is taken as set.
constexpr double kSetThreshold = 0.5;

// A unit: a surface piece, or an interior point (its three vertices equal).
using Unit = std::array<Vec3, 3>;

// The units of the set `sp`: each triangle split in four until one sphere holds each piece (as
// the bound splits) or its edge is at most `min_edge`, and the interior points. Pieces thus
// follow the rims of the spheres on the surface, and the set itself is a solution (a piece
// the set covers only jointly, at min_edge, is raised to its least-growth sphere).
std::vector<Unit> makeUnits(const SolidIndex& index, const std::vector<Sphere>& sp,
                            const std::vector<Vec3>& interior, double min_edge) {
  const Mesh& mesh = index.mesh();
  const SphereGrid grid(sp);
  const int64_t nt = static_cast<int64_t>(mesh.triangles.size());
  std::vector<std::vector<Unit>> per(nt);
  tbb::parallel_for(int64_t{0}, nt, [&](int64_t t) {
    const auto& tri = mesh.triangles[t];
    splitPieces(
        mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], min_edge,
        [&](const Unit& v) {
          if (!oneSphereHolds(grid, v.data(), 3)) return false;
          per[t].push_back(v);
          return true;
        },
        [&](const Unit& v) { per[t].push_back(v); });
  });
  std::vector<Unit> units;
  for (const Vec3& p : interior) units.push_back({p, p, p});
  for (const auto& list : per) units.insert(units.end(), list.begin(), list.end());
  return units;
}

// The program: per sphere its levels and their exact outside volumes; per unit its candidates
// as (sphere, level).
struct Program {
  std::vector<std::vector<double>> level, sov;                  // per sphere, ascending
  std::vector<std::vector<std::pair<int32_t, int32_t>>> cover;  // per unit
  std::vector<int> first;                                       // column of (j, 0)
  int columns = 0;
};

// Quantiles of the sorted values `v`: the largest value of each of `count` slices, so that
// every value has one at or above it and the largest is kept.
void appendQuantiles(const std::vector<double>& v, size_t from, size_t to, int count,
                     std::vector<double>* out) {
  const size_t m = to - from;
  if (m == 0) return;
  if (m <= static_cast<size_t>(count)) {
    out->insert(out->end(), v.begin() + from, v.begin() + to);
    return;
  }
  for (int k = 0; k < count; ++k) out->push_back(v[from + (k + 1) * m / count - 1]);
}

// A sphere's levels from the requirements of the units it may take: the current radius itself
// (so that what the sphere holds now stays held at its current radius, and the current set is a
// solution), kShrinkLevels quantiles of the requirements below it and kGrowLevels above it.
std::vector<double> sphereLevels(std::vector<double> v, double radius) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  const size_t below =
      static_cast<size_t>(std::lower_bound(v.begin(), v.end(), radius) - v.begin());
  std::vector<double> levels;
  appendQuantiles(v, 0, below, kShrinkLevels, &levels);
  levels.push_back(radius);
  size_t above = below;
  while (above < v.size() && v[above] <= radius) ++above;
  appendQuantiles(v, above, v.size(), kGrowLevels, &levels);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  return levels;
}

Program buildProgram(const SolidIndex& index, const std::vector<Sphere>& sp,
                     const std::vector<Unit>& units, RadiiStats* st) {
  const int n = static_cast<int>(sp.size());
  const double slack = kBoundSlackRel * index.bounds().diagonal();
  const SphereGrid grid(sp);
  const size_t nu = units.size();
  // Candidates and requirements per unit.
  std::vector<std::array<std::pair<int32_t, double>, kCandidates>> cand(nu);
  std::vector<int> ncand(nu);
  tbb::parallel_for(size_t{0}, nu, [&](size_t u) {
    std::array<std::pair<double, int32_t>, kCandidates> g;
    ncand[u] = leastGrowth(grid, units[u].data(), 3, kCandidates, g.data());
    int m = 0;
    for (int k = 0; k < ncand[u]; ++k) {
      const Sphere& s = sp[g[k].second];
      // Beyond the window only the least-growth candidate stays (every unit keeps one).
      if (k > 0 && g[k].first > kGrowWindow * s.radius) break;
      // A unit the sphere holds keeps a requirement within its radius (the bound's slack would
      // otherwise lift a piece it grew for just above it).
      const double need = s.radius + g[k].first;
      cand[u][m++] = {g[k].second, need <= s.radius ? need : need + slack};
    }
    ncand[u] = m;
  });
  Program p;
  p.level.assign(n, {});
  for (size_t u = 0; u < nu; ++u)
    for (int k = 0; k < ncand[u]; ++k) p.level[cand[u][k].first].push_back(cand[u][k].second);
  for (int j = 0; j < n; ++j) p.level[j] = sphereLevels(std::move(p.level[j]), sp[j].radius);
  p.first.resize(n);
  for (int j = 0; j < n; ++j) {
    p.first[j] = p.columns;
    p.columns += static_cast<int>(p.level[j].size());
  }
  p.sov.assign(n, {});
  for (int j = 0; j < n; ++j) p.sov[j].resize(p.level[j].size());
  tbb::parallel_for(0, p.columns, [&](int c) {
    const int j =
        static_cast<int>(std::upper_bound(p.first.begin(), p.first.end(), c) - p.first.begin()) - 1;
    const int k = c - p.first[j];
    p.sov[j][k] = index.outsideVolume(Sphere{sp[j].center, p.level[j][k]}).volume;
  });
  st->queries += p.columns;
  p.cover.resize(nu);
  for (size_t u = 0; u < nu; ++u)
    for (int k = 0; k < ncand[u]; ++k) {
      const auto [j, need] = cand[u][k];
      const auto& lv = p.level[j];
      const int32_t level =
          static_cast<int32_t>(std::lower_bound(lv.begin(), lv.end(), need) - lv.begin());
      p.cover[u].emplace_back(j, std::min<int32_t>(level, static_cast<int32_t>(lv.size()) - 1));
    }
  return p;
}

// Rows after reduction: a unit with one candidate forces that level (a lower bound of its
// columns); rows met by the forced levels are dropped; equal rows are kept once.
std::vector<std::vector<int>> coverRows(const Program& p, std::vector<int>* forced) {
  const int n = static_cast<int>(p.level.size());
  forced->assign(n, 0);
  for (const auto& c : p.cover)
    if (c.size() == 1) (*forced)[c[0].first] = std::max((*forced)[c[0].first], c[0].second);
  std::vector<std::vector<int>> rows;
  for (const auto& c : p.cover) {
    bool met = c.empty();
    std::vector<int> row;
    for (const auto& [j, k] : c) {
      met = met || k <= (*forced)[j];
      row.push_back(p.first[j] + k);
    }
    if (met) continue;
    std::sort(row.begin(), row.end());
    rows.push_back(std::move(row));
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

// Solves the program from the start `radii`; writes the radii of its best solution (the largest
// level set per sphere) and the objective and bound to *st. False when CBC found no solution or
// the program has more than kMaxRows rows.
bool solveProgram(const Program& p, const std::vector<double>& radii, std::vector<double>* out,
                  RadiiStats* st) {
  const int n = static_cast<int>(p.level.size());
  std::vector<int> forced;
  const std::vector<std::vector<int>> rows = coverRows(p, &forced);
  if (rows.size() > kMaxRows) return false;
  double max_cost = 0.0;
  for (int j = 0; j < n; ++j) max_cost = std::max(max_cost, p.sov[j].back());
  const double scale = max_cost > 0.0 ? 1.0 / max_cost : 1.0;  // costs of order 1 for CBC
  Cbc_Model* model = Cbc_newModel();
  for (int j = 0; j < n; ++j)
    for (size_t k = 0; k < p.level[j].size(); ++k) {
      const double cost = p.sov[j][k] - (k > 0 ? p.sov[j][k - 1] : 0.0);
      Cbc_addCol(model, "", static_cast<int>(k) <= forced[j] ? 1.0 : 0.0, 1.0,
                 std::max(cost, 0.0) * scale, 1, 0, nullptr, nullptr);
    }
  for (const auto& row : rows) {
    std::vector<double> ones(row.size(), 1.0);
    Cbc_addRow(model, "", static_cast<int>(row.size()), row.data(), ones.data(), 'G', 1.0);
  }
  for (int j = 0; j < n; ++j)  // x[j][k] <= x[j][k-1]
    for (size_t k = 1; k < p.level[j].size(); ++k) {
      const int cols[2] = {p.first[j] + static_cast<int>(k), p.first[j] + static_cast<int>(k) - 1};
      const double vals[2] = {1.0, -1.0};
      Cbc_addRow(model, "", 2, cols, vals, 'L', 0.0);
    }
  // The start: each sphere at the levels its current radius reaches, raised for the units no
  // sphere holds alone (pieces the current set covers only jointly) to their first candidate.
  std::vector<int> top(n, 0);
  for (int j = 0; j < n; ++j) {
    top[j] = forced[j];
    for (size_t k = 0; k < p.level[j].size(); ++k)
      if (p.level[j][k] <= radii[j]) top[j] = std::max(top[j], static_cast<int>(k));
  }
  for (const auto& c : p.cover) {
    bool met = c.empty();
    for (const auto& [j, k] : c) met = met || k <= top[j];
    if (!met) top[c[0].first] = std::max(top[c[0].first], c[0].second);
  }
  std::vector<int> start_cols;
  for (int j = 0; j < n; ++j)
    for (int k = 0; k <= top[j]; ++k) start_cols.push_back(p.first[j] + k);
  std::vector<double> ones(start_cols.size(), 1.0);
  Cbc_setMIPStartI(model, static_cast<int>(start_cols.size()), start_cols.data(), ones.data());
  Cbc_setLogLevel(model, 0);
  Cbc_setMaximumNodes(model, kMaxNodes);
  for (const auto& [key, setting] : kCbcSettings) Cbc_setParameter(model, key, setting);
  Cbc_solve(model);
  const double* x = Cbc_bestSolution(model);
  bool ok = x != nullptr;
  if (ok) {
    out->assign(n, 0.0);
    double objective = 0.0;
    for (int j = 0; j < n; ++j) {
      int highest = -1;
      for (size_t k = 0; k < p.level[j].size(); ++k)
        if (x[p.first[j] + static_cast<int>(k)] > kSetThreshold) highest = static_cast<int>(k);
      highest = std::max(highest, 0);  // a sphere nothing needs keeps its smallest level
      (*out)[j] = p.level[j][highest];
      objective += p.sov[j][highest];
    }
    st->objective = objective;
    st->lower_bound = std::min(objective, Cbc_getBestPossibleObjValue(model) / scale);
    st->proven = Cbc_isProvenOptimal(model) != 0;
    st->rows = static_cast<int64_t>(rows.size());
    st->columns = p.columns;
    st->units = static_cast<int64_t>(p.cover.size());
  }
  Cbc_deleteModel(model);
  return ok;
}

}  // namespace

RadiiStats optimalRadii(const SolidIndex& index, const std::vector<Vec3>& interior,
                        double unit_edge, double bound_edge, std::vector<Sphere>* sp) {
  RadiiStats st;
  const int n = static_cast<int>(sp->size());
  const double before = totalOf(outsideVolumes(index, *sp));
  st.queries += n;
  st.energy = st.start = before;
  const std::vector<Unit> units = makeUnits(index, *sp, interior, unit_edge);
  const Program p = buildProgram(index, *sp, units, &st);
  std::vector<double> radii(n), chosen;
  for (int j = 0; j < n; ++j) radii[j] = (*sp)[j].radius;
  pollCancel();
  if (!solveProgram(p, radii, &chosen, &st)) return st;
  st.solved = true;
  std::vector<Sphere> cand = *sp;
  for (int j = 0; j < n; ++j) cand[j].radius = chosen[j];
  const BoundStats bs = boundSurface(index, &cand, bound_edge);
  st.queries += bs.queries + n;
  const double e = totalOf(outsideVolumes(index, cand));
  if (e < before) {
    *sp = std::move(cand);
    st.kept = true;
    st.energy = e;
  }
  return st;
}

void runOptimalRadii(const SolidIndex& index, const std::vector<Vec3>& interior, double min_edge,
                     std::vector<Sphere>* sp, FitResult* res) {
  const auto t0 = FitClock::now();
  const double fine = kRefineFineEdge * min_edge;
  const RadiiStats rs = optimalRadii(index, interior, fine, fine, sp);
  res->bounding_queries += rs.queries;
  res->seconds.radii += secondsSince(t0);
  if (!rs.solved) return;
  RadiiCertificate& c = res->radii;
  c.objective = rs.objective;
  c.lower_bound = rs.lower_bound;
  c.gap = rs.objective > 0.0 ? (rs.objective - rs.lower_bound) / rs.objective : 0.0;
  c.start = rs.start;
  c.units = rs.units;
  c.rows = rs.rows;
  c.kept = rs.kept;
}

}  // namespace sphereset::detail

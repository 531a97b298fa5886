// Selection among candidate spheres (beyond the paper). Reference: the weighted set cover with a
// cardinality constraint, solved as an integer program (branch and cut: COIN-OR CBC, Forrest and
// Lougee-Heimer 2005) from a greedy start (Chvátal 1979, "A greedy heuristic for the
// set-covering problem", Math. Oper. Res. 4(3)) improved by single swaps. Wang et al. 2006
// minimise the outside volume of n spheres by clustering (Sec. 5); here n spheres are chosen
// among many candidates (the spheres of several fits) so that they cover the surface exactly
// (each triangle split, as the bound splits, until one candidate holds each piece) and the
// interior points, at least total outside volume (Eq. 2, summed over the chosen spheres).
#include "fit/select.hpp"

#include <Cbc_C_Interface.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

#include "cover/sphere_grid.hpp"
#include "fit/cbc_settings.hpp"
#include "sphereset/cover.hpp"
#include "util/poll.hpp"

namespace sphereset::detail {
namespace {

// A swap must lower the cost by this fraction of the largest candidate cost to count (so that
// rounding cannot make the search cycle).
constexpr double kSwapGainRel = 1e-12;
// The greedy divides by cost plus this fraction of the largest cost (a candidate entirely
// inside the solid costs nothing).
constexpr double kCostFloorRel = 1e-12;
// Rows at which the ILP is not attempted (the swap search's answer stands).
constexpr size_t kMaxIlpClasses = 200000;
// An ILP variable above this is taken as chosen.
constexpr double kChosenThreshold = 0.5;

// The candidates holding all three vertices of a piece, ascending.
void pieceHolders(const SphereGrid& grid, const std::array<Vec3, 3>& v, std::vector<int32_t>* out) {
  out->clear();
  grid.forEachNear(v[0], [&](int32_t i) {
    const Sphere& s = grid.spheres()[i];
    if (s.contains(v[0]) && s.contains(v[1]) && s.contains(v[2])) out->push_back(i);
  });
}

// The candidates' groups (each a set that covers the solid on its own, such as one fit's
// spheres): a unit is kept when every group has a holder of it, so that each group is itself a
// feasible choice. Without groups, one holder suffices.
struct Groups {
  const std::vector<int32_t>& of;  // per candidate; empty: no groups
  int count = 0;

  bool allHold(const std::vector<int32_t>& h, std::vector<char>* seen) const {
    if (of.empty()) return !h.empty();
    seen->assign(count, 0);
    int hit = 0;
    for (int32_t c : h)
      if (!(*seen)[of[c]]) (*seen)[of[c]] = 1, ++hit;
    return hit == count;
  }
};

// The holder lists of one triangle's pieces: split in four until every group holds a piece;
// a piece that some group does not hold at edge min_edge or at the bound's depth counts in
// *unheld.
void triangleUnits(const SphereGrid& grid, const Groups& groups, const Vec3& a, const Vec3& b,
                   const Vec3& c, double min_edge, std::vector<std::vector<int32_t>>* out,
                   int64_t* unheld) {
  struct Part {
    std::array<Vec3, 3> v;
    int depth;
  };
  std::vector<Part> todo{{{a, b, c}, 0}};
  std::vector<int32_t> h;
  std::vector<char> seen;
  while (!todo.empty()) {
    const Part pc = todo.back();
    todo.pop_back();
    pieceHolders(grid, pc.v, &h);
    if (groups.allHold(h, &seen)) {
      out->push_back(h);
      continue;
    }
    const auto& [p, q, r] = pc.v;
    const double edge = std::max({(q - p).norm(), (r - q).norm(), (p - r).norm()});
    if (edge <= min_edge || pc.depth >= kSurfaceSplitDepth) {
      ++*unheld;
      continue;
    }
    const Vec3 pq = 0.5 * (p + q), qr = 0.5 * (q + r), rp = 0.5 * (r + p);
    todo.push_back({{p, pq, rp}, pc.depth + 1});
    todo.push_back({{pq, q, qr}, pc.depth + 1});
    todo.push_back({{rp, qr, r}, pc.depth + 1});
    todo.push_back({{pq, qr, rp}, pc.depth + 1});
  }
}

// Coverage counts of a chosen set: for each class, how many chosen candidates hold it.
struct CoverState {
  const CoverProblem& p;
  const std::vector<std::vector<int32_t>>& classes_of;  // per candidate: the classes it holds
  std::vector<int32_t> count;
  std::vector<char> in;

  void add(int32_t c, int sign) {
    in[c] = sign > 0;
    for (int32_t k : classes_of[c]) count[k] += sign;
  }
};

// Candidate -> classes it holds (classes ascending).
std::vector<std::vector<int32_t>> classesOf(const CoverProblem& p) {
  std::vector<std::vector<int32_t>> out(p.cost.size());
  for (size_t k = 0; k < p.classes.size(); ++k)
    for (int32_t c : p.classes[k]) out[c].push_back(static_cast<int32_t>(k));
  return out;
}

bool coversAll(const CoverProblem& p, const std::vector<int32_t>& chosen) {
  std::vector<char> in(p.cost.size(), 0);
  for (int32_t c : chosen) in[c] = 1;
  for (const auto& cls : p.classes)
    if (std::none_of(cls.begin(), cls.end(), [&](int32_t c) { return in[c] != 0; })) return false;
  return true;
}

// Greedy weighted cover (most newly covered classes per unit cost), then the cheapest unused
// candidates up to n. Empty if the greedy needs more than n.
std::vector<int32_t> greedyCover(const CoverProblem& p, const std::vector<std::vector<int32_t>>& of,
                                 int n) {
  const int m = static_cast<int>(p.cost.size());
  const double cost_floor = kCostFloorRel * *std::max_element(p.cost.begin(), p.cost.end());
  std::vector<char> covered(p.classes.size(), 0), in(m, 0);
  size_t left = p.classes.size();
  std::vector<int32_t> chosen;
  while (left > 0 && static_cast<int>(chosen.size()) < n) {
    int best = -1;
    double best_ratio = -1.0;
    for (int c = 0; c < m; ++c) {
      if (in[c]) continue;
      int64_t fresh = 0;
      for (int32_t k : of[c]) fresh += covered[k] ? 0 : 1;
      const double ratio = static_cast<double>(fresh) / (p.cost[c] + cost_floor);
      if (fresh > 0 && ratio > best_ratio) best_ratio = ratio, best = c;
    }
    if (best < 0) break;
    in[best] = 1;
    chosen.push_back(best);
    for (int32_t k : of[best])
      if (!covered[k]) covered[k] = 1, --left;
  }
  if (left > 0) return {};
  std::vector<int32_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int32_t a, int32_t b) { return p.cost[a] < p.cost[b]; });
  for (int32_t c : order) {
    if (static_cast<int>(chosen.size()) >= n) break;
    if (!in[c]) in[c] = 1, chosen.push_back(c);
  }
  return chosen;
}

// Best-improvement single swaps (one chosen candidate out, one unchosen in) while the cover
// holds and the cost falls.
void swapSearch(const CoverProblem& p, const std::vector<std::vector<int32_t>>& of,
                std::vector<int32_t>* chosen) {
  const int m = static_cast<int>(p.cost.size());
  const double max_cost = *std::max_element(p.cost.begin(), p.cost.end());
  const double min_gain = kSwapGainRel * max_cost;
  CoverState st{p, of, std::vector<int32_t>(p.classes.size(), 0), std::vector<char>(m, 0)};
  for (int32_t c : *chosen) st.add(c, 1);
  std::vector<int32_t> hits(m);
  for (;;) {
    pollCancel();
    double best_gain = min_gain;
    int out = -1, in = -1;
    for (int32_t a : *chosen) {
      // The classes only a holds: a replacement must hold them all.
      int need = 0;
      std::fill(hits.begin(), hits.end(), 0);
      for (int32_t k : of[a]) {
        if (st.count[k] != 1) continue;
        ++need;
        for (int32_t b : p.classes[k]) ++hits[b];
      }
      for (int b = 0; b < m; ++b) {
        if (st.in[b] || hits[b] != need) continue;
        const double gain = p.cost[a] - p.cost[b];
        if (gain > best_gain) best_gain = gain, out = a, in = b;
      }
    }
    if (out < 0) break;
    st.add(out, -1);
    st.add(in, 1);
    std::replace(chosen->begin(), chosen->end(), static_cast<int32_t>(out), in);
  }
  std::sort(chosen->begin(), chosen->end());
}

double costOf(const CoverProblem& p, const std::vector<int32_t>& chosen) {
  double s = 0.0;
  for (int32_t c : chosen) s += p.cost[c];
  return s;
}

// The ILP by CBC from `start` (n candidates covering every class), at most max_nodes nodes.
// Writes a better cover, if it finds one, to *sel.
void solveIlp(const CoverProblem& p, const std::vector<std::vector<int32_t>>& of, int n,
              int max_nodes, Selection* sel) {
  const int m = static_cast<int>(p.cost.size());
  const int rows = static_cast<int>(p.classes.size()) + 1;  // the last: Σ x = n
  const double max_cost = *std::max_element(p.cost.begin(), p.cost.end());
  const double scale = max_cost > 0.0 ? 1.0 / max_cost : 1.0;  // costs of order 1 for CBC
  std::vector<CoinBigIndex> start(m + 1, 0);
  std::vector<int> index;
  std::vector<double> value, lb(m, 0.0), ub(m, 1.0), obj(m), row_lb(rows, 1.0),
      row_ub(rows, std::numeric_limits<double>::max());
  for (int c = 0; c < m; ++c) {
    for (int32_t k : of[c]) index.push_back(k), value.push_back(1.0);
    index.push_back(rows - 1), value.push_back(1.0);
    start[c + 1] = static_cast<CoinBigIndex>(index.size());
    obj[c] = p.cost[c] * scale;
  }
  row_lb[rows - 1] = row_ub[rows - 1] = n;
  Cbc_Model* model = Cbc_newModel();
  Cbc_loadProblem(model, m, rows, start.data(), index.data(), value.data(), lb.data(), ub.data(),
                  obj.data(), row_lb.data(), row_ub.data());
  for (int c = 0; c < m; ++c) Cbc_setInteger(model, c);
  std::vector<int> cols(sel->chosen.begin(), sel->chosen.end());
  std::vector<double> ones(cols.size(), 1.0);
  Cbc_setMIPStartI(model, static_cast<int>(cols.size()), cols.data(), ones.data());
  Cbc_setLogLevel(model, 0);
  Cbc_setMaximumNodes(model, max_nodes);
  for (const auto& [key, setting] : kCbcSettings) Cbc_setParameter(model, key, setting);
  const auto t0 = std::chrono::steady_clock::now();
  Cbc_solve(model);
  sel->ilp_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sel->nodes = Cbc_getNodeCount(model);
  const double* x = Cbc_bestSolution(model);
  if (x) {
    std::vector<int32_t> chosen;
    for (int c = 0; c < m; ++c)
      if (x[c] > kChosenThreshold) chosen.push_back(c);
    const double cost = costOf(p, chosen);
    if (static_cast<int>(chosen.size()) == n && coversAll(p, chosen) && cost <= sel->cost) {
      sel->chosen = std::move(chosen);
      sel->cost = cost;
      sel->proven = Cbc_isProvenOptimal(model) != 0;
    }
  }
  Cbc_deleteModel(model);
}

}  // namespace

CoverProblem coverProblem(const SolidIndex& index, const std::vector<Sphere>& candidates,
                          const std::vector<int32_t>& group_of, const std::vector<Vec3>& interior,
                          double min_edge) {
  CoverProblem p;
  Groups groups{group_of, 0};
  for (int32_t g : group_of) groups.count = std::max(groups.count, g + 1);
  const Mesh& mesh = index.mesh();
  const int64_t nt = static_cast<int64_t>(mesh.triangles.size());
  const SphereGrid grid(candidates);
  p.cost.resize(candidates.size());
  tbb::parallel_for(size_t{0}, candidates.size(), [&](size_t i) {
    pollCancel();
    p.cost[i] = index.outsideVolume(candidates[i]).volume;
  });
  std::vector<std::vector<std::vector<int32_t>>> per_tri(nt);
  std::vector<int64_t> unheld(nt, 0);
  tbb::parallel_for(int64_t{0}, nt, [&](int64_t t) {
    pollCancel();
    const auto& tri = mesh.triangles[t];
    triangleUnits(grid, groups, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]],
                  min_edge, &per_tri[t], &unheld[t]);
  });
  std::map<std::vector<int32_t>, int64_t> classes;
  for (int64_t t = 0; t < nt; ++t) {
    p.unheld += unheld[t];
    for (auto& h : per_tri[t]) {
      ++p.units;
      classes.emplace(std::move(h), 0).first->second++;
    }
  }
  std::vector<int32_t> h;
  std::vector<char> seen;
  for (const Vec3& q : interior) {
    h.clear();
    grid.forEachNear(q, [&](int32_t i) {
      if (candidates[i].contains(q)) h.push_back(i);
    });
    if (!groups.allHold(h, &seen)) {
      ++p.unheld;
      continue;
    }
    ++p.units;
    classes.emplace(h, 0).first->second++;
  }
  p.classes.reserve(classes.size());
  for (auto& [holders, count] : classes) p.classes.push_back(holders);
  return p;
}

Selection selectCover(const CoverProblem& problem, int n, const std::vector<int32_t>& start,
                      int max_nodes) {
  Selection sel;
  const int m = static_cast<int>(problem.cost.size());
  if (n <= 0 || n > m) return sel;
  const auto of = classesOf(problem);
  std::vector<int32_t> s = start;
  std::sort(s.begin(), s.end());
  const bool start_ok =
      static_cast<int>(s.size()) == n && std::adjacent_find(s.begin(), s.end()) == s.end() &&
      std::all_of(s.begin(), s.end(), [&](int32_t c) { return c >= 0 && c < m; }) &&
      coversAll(problem, s);
  if (!start_ok) s = greedyCover(problem, of, n);
  if (!s.empty()) {
    swapSearch(problem, of, &s);
    sel.chosen = s;
    sel.cost = costOf(problem, s);
  } else {
    sel.cost = std::numeric_limits<double>::infinity();
  }
  if (problem.classes.size() <= kMaxIlpClasses && max_nodes >= 0)
    solveIlp(problem, of, n, max_nodes, &sel);
  if (sel.chosen.empty()) sel.cost = 0.0;
  return sel;
}

}  // namespace sphereset::detail

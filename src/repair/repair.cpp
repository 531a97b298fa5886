// The repair ladder: from the mesh a user has to a solid the fit can run on (repair.hpp).
// Beyond the paper, which assumes a clean closed manifold. The solid of a mesh whose shells
// overlap is their union (non-zero winding); a mesh that is open, non-manifold, inconsistently
// oriented or self-intersecting gets a watertight wrap that contains every triangle (3D Alpha
// Wrapping: Portaneri, Rouxel-Labbé, Hemmer, Cohen-Steiner, Alliez 2022, "Alpha Wrapping with
// an Offset"). The cheaper exact steps (welding, capping, dropping nested shells) come first,
// since they keep the solid the user drew; the wrapping adds a thin layer and fills narrow
// concavities.
#include "sphereset/repair.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>

#include "repair/canonical_order.hpp"
#include "repair/cap_holes.hpp"
#include "repair/orient.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {
namespace {

// Weld tolerances tried automatically, relative to the bounding box diagonal: the smallest
// that closes the mesh is used (coordinates stored per corner in float differ by ~1e-7).
constexpr double kAutoWeldSteps[] = {1e-8, 1e-7, kAutoWeldRel};

// Automatic wrap parameters. CGAL 5.5's wrapping time grows with the number of triangles it
// outputs, about kWrapTrianglesPerArea * area / alpha^2 for an offset of alpha / 20 (measured on
// the benchmark meshes: spot gives 5.0k triangles at alpha = d/50), at a rate that falls with
// the input's size (about 10k triangles per second for small inputs, 3k at 86k input triangles).
// Alpha is the smallest that keeps the predicted output within what kWrapSeconds allows, so a
// mesh with little surface for its size (a compact link) is wrapped more tightly than one with
// much (a chair's thin legs), and a large input more coarsely; it stays between d/100 and d/50
// of the bounding box diagonal d. The offset is alpha / 20.
constexpr double kWrapTrianglesPerArea = 2.35;
constexpr double kWrapRate = 10000.0;           // output triangles per second, small inputs
constexpr double kWrapRateHalfInput = 37000.0;  // input triangles at which the rate halves
constexpr double kWrapSeconds = 0.5;
constexpr double kWrapAlphaMinRel = 1.0 / 100.0, kWrapAlphaMaxRel = 1.0 / 50.0;
constexpr double kWrapOffsetOfAlpha = 1.0 / 20.0;
// Limits of a wrap, checked before CGAL runs. Its exact arithmetic raises a floating-point
// signal in GMP (a double overflowing to infinity) when coordinates, alpha or offset are
// astronomically large (seen at 1e80 and at alpha 1e200), and its time grows with the output:
// alpha and offset at most kWrapMaxSizeRel times the diagonal, coordinates (units of the mesh)
// at most limits::kMaxCoordinate, and, for an alpha or offset the user chose, at most
// kWrapMaxTriangles predicted output triangles (about a minute: the wrap of a one-triangle mesh
// of diagonal 1.4 at offset 2 predicts 0.26M and took 20 s).
constexpr double kWrapMaxSizeRel = 100.0;
constexpr double kWrapMaxTriangles = 1e6;

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

Expected<Mesh> reweld(const Mesh& mesh, double tol, const std::string& name) {
  LoadOptions lo;
  lo.weld_tolerance = tol;
  auto w = cleanMesh(mesh.vertices, mesh.triangles, lo, name);
  if (!w) return w.error();
  return std::move(w->mesh);
}

Mesh flipped(Mesh m) {
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

Mesh concat(const std::vector<Mesh>& parts) {
  Mesh out;
  for (const Mesh& p : parts) {
    const auto base = static_cast<int32_t>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), p.vertices.begin(), p.vertices.end());
    for (Triangle t : p.triangles) out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return out;
}

// The shells' roles once each is clean and no two intersect: kept as they are (outward solids
// and kept cavities, each with the orientation its nesting gives it), or dropped.
struct ShellPlan {
  std::vector<Mesh> outward;   // solids, outward
  std::vector<Mesh> cavities;  // inward shells kept as cavities
  int64_t dropped = 0, filled = 0, flipped = 0;
};

// Nesting rules (non-zero winding): a shell inside a kept solid with the same orientation adds
// nothing (dropped); an inward shell inside a solid is a cavity (filled, i.e. dropped, or
// kept); a shell inside a kept cavity is an island when outward (kept) and redundant when
// inward; an inward shell inside nothing is inside out (flipped).
ShellPlan planShells(const Mesh& m, const ShellAnalysis& sa, bool fill_cavities) {
  ShellPlan plan;
  const size_t n = sa.shells.size();
  // Role per shell: +1 kept solid, -1 kept cavity, 0 dropped. Parents first (by depth).
  std::vector<int> role(n, 0);
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return sa.shells[a].depth < sa.shells[b].depth; });
  for (size_t i : order) {
    const Shell& s = sa.shells[i];
    const bool outward = s.volume > 0.0;
    int enclosing = 0;  // role of the nearest kept ancestor (0: none)
    for (int32_t p = s.parent; p >= 0; p = sa.shells[p].parent)
      if (role[p] != 0) {
        enclosing = role[p];
        break;
      }
    Mesh sub = submesh(m, s.triangles);
    if (enclosing == 0) {
      role[i] = 1;
      if (!outward) {
        sub = flipped(std::move(sub));
        ++plan.flipped;
      }
      plan.outward.push_back(std::move(sub));
    } else if (enclosing == 1 && !outward) {
      if (fill_cavities) {
        ++plan.filled;
      } else {
        role[i] = -1;
        plan.cavities.push_back(std::move(sub));
      }
    } else if (enclosing == -1 && outward) {
      role[i] = 1;
      plan.outward.push_back(std::move(sub));
    } else {
      ++plan.dropped;
    }
  }
  return plan;
}

// Every edge traversed as often in one direction as in the other (a closed oriented surface,
// possibly non-manifold or self-intersecting): its signed volume, the integral of its winding
// number, is defined.
bool balancedClosed(const Mesh& m) {
  // (lo, hi, +1 or -1) per directed edge, sorted by the undirected key.
  std::vector<std::tuple<int32_t, int32_t, int>> edges;
  edges.reserve(3 * m.triangles.size());
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b), a < b ? 1 : -1);
    }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    int balance = 0;
    size_t j = i;
    for (; j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
           std::get<1>(edges[j]) == std::get<1>(edges[i]);
         ++j)
      balance += std::get<2>(edges[j]);
    if (balance != 0) return false;
    i = j;
  }
  return true;
}

bool allClean(const ShellAnalysis& sa) {
  for (const Shell& s : sa.shells)
    if (!s.clean()) return false;
  return true;
}

bool allClosedOriented(const ShellAnalysis& sa) {
  for (const Shell& s : sa.shells)
    if (!(s.closed && s.oriented)) return false;
  return true;
}

std::string count(int64_t k, const char* one, const char* many) {
  return std::to_string(k) + " " + (k == 1 ? one : many);
}

// Applies the nesting plan to a mesh whose shells are clean and apart; records what it did.
Mesh applyPlan(const Mesh& m, const ShellAnalysis& sa, bool fill, RepairResult* res) {
  ShellPlan plan = planShells(m, sa, fill);
  res->shells_dropped = plan.dropped;
  res->cavities_filled = plan.filled;
  res->cavities_kept = static_cast<int64_t>(plan.cavities.size());
  if (plan.dropped > 0)
    res->notes.push_back("dropped " + count(plan.dropped, "shell", "shells") +
                         " nested inside another with the same orientation");
  if (plan.filled > 0) res->notes.push_back("filled " + count(plan.filled, "cavity", "cavities"));
  if (!plan.cavities.empty())
    res->notes.push_back("kept " + count(res->cavities_kept, "cavity", "cavities"));
  if (plan.flipped > 0)
    res->notes.push_back("turned " + count(plan.flipped, "inside-out shell", "inside-out shells") +
                         " outward");
  std::vector<Mesh> parts = std::move(plan.outward);
  for (Mesh& c : plan.cavities) parts.push_back(std::move(c));
  return concat(parts);
}

// Alpha and offset for the wrap: the options' or the automatic ones.
void wrapParameters(const Mesh& m, const RepairOptions& o, double* alpha, double* offset) {
  const double diag = boundingBox(m).diagonal();
  const double rate =
      kWrapRate / (1.0 + static_cast<double>(m.triangles.size()) / kWrapRateHalfInput);
  const double budget = rate * kWrapSeconds;  // output triangles
  const double fit = std::sqrt(kWrapTrianglesPerArea * surfaceArea(m) / budget);
  *alpha = o.wrap_alpha > 0.0 ? o.wrap_alpha
                              : std::clamp(fit, kWrapAlphaMinRel * diag, kWrapAlphaMaxRel * diag);
  *offset = o.wrap_offset > 0.0 ? o.wrap_offset : kWrapOffsetOfAlpha * *alpha;
}

// Whether a wrap of `m` with these parameters stays within the limits above. The output's area is
// at most about twice the input's (both sides of an open surface) plus the offset's sphere and
// band around it (Steiner's formula with the diagonal for the mean width).
Status checkWrap(const Mesh& m, const RepairOptions& o, double alpha, double offset,
                 const std::string& name) {
  const Aabb box = boundingBox(m);
  const double coordinate = std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
  if (!(coordinate <= limits::kMaxCoordinate))
    return Error{ErrorCode::kInvalidData, name + ": coordinates up to " + fmt("%.3g", coordinate) +
                                              " cannot be wrapped (the limit is " +
                                              fmt("%.3g", limits::kMaxCoordinate) + ")"};
  const double diag = box.diagonal();
  for (const auto& [what, value] : {std::pair{"wrap_alpha", alpha}, {"wrap_offset", offset}})
    if (!(value <= kWrapMaxSizeRel * diag))
      return Error{ErrorCode::kInvalidArgument,
                   name + ": " + what + " " + fmt("%.3g", value) + " is more than " +
                       fmt("%.3g", kWrapMaxSizeRel) + " times the mesh's diagonal " +
                       fmt("%.3g", diag)};
  if (o.wrap_alpha > 0.0 || o.wrap_offset > 0.0) {
    const double area = 2.0 * surfaceArea(m) + 4.0 * std::numbers::pi * offset * (offset + diag);
    const double predicted = kWrapTrianglesPerArea * area / (alpha * alpha);
    if (!(predicted <= kWrapMaxTriangles))
      return Error{ErrorCode::kInvalidArgument,
                   name + ": a wrap with alpha " + fmt("%.3g", alpha) + " and offset " +
                       fmt("%.3g", offset) + " would make about " + fmt("%.3g", predicted) +
                       " triangles (the limit is " + fmt("%.3g", kWrapMaxTriangles) +
                       "); give a larger wrap_alpha or a smaller wrap_offset"};
  }
  return {};
}

Error needs(const std::string& name, const std::string& what, const std::string& why) {
  return Error{ErrorCode::kNotSolid, name + ": " + why + "; " + what};
}

}  // namespace

const char* repairName(RepairKind k) {
  switch (k) {
    case RepairKind::kNone:
      return "none";
    case RepairKind::kWelded:
      return "welded";
    case RepairKind::kReoriented:
      return "reoriented";
    case RepairKind::kCapped:
      return "capped";
    case RepairKind::kUnion:
      return "union";
    case RepairKind::kWrapped:
      return "wrapped";
  }
  return "none";
}

Expected<RepairResult> repairMesh(const Mesh& mesh, const RepairOptions& o,
                                  const std::string& name) {
  const auto t0 = std::chrono::steady_clock::now();
  RepairResult res;
  res.original = mesh;
  res.diagnosis = diagnoseMesh(mesh);
  res.volume_ratio = std::numeric_limits<double>::quiet_NaN();
  if (Status st = checkRepairOptions(o); !st) return st.error();
  if (mesh.triangles.empty())
    return Error{ErrorCode::kInvalidData, name + ": the mesh has no triangles"};
  auto done = [&](Mesh solid, RepairKind kind) -> Expected<RepairResult> {
    res.solid = std::move(solid);
    res.kind = kind;
    if (res.kind == RepairKind::kNone && res.triangles_flipped > 0)
      res.kind = RepairKind::kReoriented;
    if (res.kind == RepairKind::kNone && res.weld_tolerance > 0.0) res.kind = RepairKind::kWelded;
    if (!(signedVolume(res.solid) > 0.0))
      return Error{ErrorCode::kNotSolid, name + ": the repaired mesh encloses no volume"};
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  };

  // 1. Welding: the given tolerance, or (repair on) the smallest automatic one that closes the
  // mesh.
  Mesh m = mesh;
  const double diag = res.diagnosis.bbox.diagonal();
  if (o.weld_tolerance > 0.0) {
    auto w = reweld(mesh, o.weld_tolerance, name);
    if (!w) return w.error();
    m = std::move(w).value();
    res.weld_tolerance = o.weld_tolerance;
  } else if (o.enabled && o.weld_tolerance < 0.0 && res.diagnosis.boundary_edges > 0) {
    // The largest tolerance first: when it does not close the mesh, the smaller ones are not
    // tried (a large mesh with a real hole pays for one weld, not three).
    auto closes = [&](double rel) -> bool {
      auto w = reweld(mesh, rel * diag, name);
      if (!w || !diagnoseMesh(*w).closed) return false;
      m = std::move(w).value();
      res.weld_tolerance = rel * diag;
      res.notes.clear();
      res.notes.push_back("welded vertices within " + fmt("%.3g", res.weld_tolerance) + " (" +
                          fmt("%.0e", rel) + " of the diagonal), which closes the mesh");
      return true;
    };
    constexpr size_t kSteps = std::size(kAutoWeldSteps);
    if (closes(kAutoWeldSteps[kSteps - 1]))
      for (size_t i = 0; i + 1 < kSteps; ++i)
        if (closes(kAutoWeldSteps[i])) break;
  }

  // Off: a closed oriented 2-manifold is taken as it is, anything else refused.
  if (!o.enabled) {
    const MeshDiagnosis d = diagnoseMesh(m);
    if (!d.isSolid()) return notSolidError(name, d);
    return done(std::move(m), RepairKind::kNone);
  }

  // Consistent orientation, where only the orientation is wrong (every edge of at most two
  // triangles): exact, so it comes before anything that changes the geometry.
  if (const MeshDiagnosis dw = diagnoseMesh(m);
      dw.misoriented_edges > 0 && dw.nonmanifold_edges == 0) {
    Mesh oriented = m;
    const int64_t flipped = detail::orientConsistently(&oriented);
    if (flipped > 0) {
      m = std::move(oriented);
      res.triangles_flipped = flipped;
      res.notes.push_back("flipped " + count(flipped, "triangle", "triangles") +
                          " to a consistent orientation");
    }
  }

  // 2. Shells: clean and apart, possibly nested.
  res.shells = analyzeShells(m);
  // The input's volume, where defined: with clean shells apart, the solid they bound (nested
  // shells by the plan); otherwise, for a closed surface whose edges are balanced, the magnitude
  // of its signed volume (regions it winds around twice count twice).
  double input_volume = std::numeric_limits<double>::quiet_NaN();
  if (allClosedOriented(res.shells) && !res.shells.intersections.any()) {
    ShellPlan plan = planShells(m, res.shells, o.fill_cavities);
    for (Mesh& c : plan.cavities) plan.outward.push_back(std::move(c));
    input_volume = signedVolume(concat(plan.outward));
  } else if (balancedClosed(m)) {
    input_volume = std::abs(signedVolume(m));
  }
  auto ratio = [&](const Mesh& solid) { return signedVolume(solid) / input_volume; };
  if (allClean(res.shells) && res.shells.intersecting.empty()) {
    Mesh solid = applyPlan(m, res.shells, o.fill_cavities, &res);
    res.volume_ratio = ratio(solid);
    // Dropping nested shells or filling cavities takes the union of the shells (non-zero
    // winding) without computing anything.
    const bool united = res.shells_dropped > 0 || res.cavities_filled > 0;
    return done(std::move(solid), united ? RepairKind::kUnion : RepairKind::kNone);
  }

  // 3. Capping: open but otherwise sound shells, their holes closed (holes are filled like
  // cavities, so not when cavities are kept).
  Mesh capped = m;
  if (o.fill_cavities && res.diagnosis.boundary_edges > 0) {
    res.holes_capped = detail::capHoles(&capped);
    // Caps only add triangles: crossings already there stay, and the capped mesh is then only
    // the wrap's input (with its holes closed), not worth analysing again.
    const bool may_be_clean = res.holes_capped > 0 && !res.shells.intersections.any();
    const ShellAnalysis sc = may_be_clean ? analyzeShells(capped) : ShellAnalysis{};
    if (may_be_clean && allClean(sc) && sc.intersecting.empty()) {
      res.notes.push_back("closed " + count(res.holes_capped, "hole", "holes") +
                          " (triangulated over their own vertices)");
      return done(applyPlan(capped, sc, o.fill_cavities, &res), RepairKind::kCapped);
    }
  }

  // 4. Union: every shell clean, some overlapping.
  const bool have_ops = o.operations.unite && o.operations.wrap;
  if (allClean(res.shells) && !res.shells.intersecting.empty()) {
    if (!o.operations.unite)
      return needs(name, "rebuild with SPHERESET_WITH_REPAIR=ON to fit their union",
                   count(static_cast<int64_t>(res.shells.intersecting.size()),
                         "pair of shells intersects", "pairs of shells intersect"));
    // Inward shells inside another are cavities: filled, or kept when they and what is
    // nested in them cross nothing (islands in a kept cavity stay apart from the union, which
    // would swallow them). Everything else, inside-out shells turned outward, is united.
    const size_t ns = res.shells.shells.size();
    std::vector<char> crosses(ns, 0);
    for (const auto& [a, b] : res.shells.intersecting) crosses[a] = crosses[b] = 1;
    std::vector<int> role(ns, 0);  // 0 united, 1 kept cavity, 2 island, 3 filled cavity
    std::vector<size_t> order(ns);
    for (size_t i = 0; i < ns; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return res.shells.shells[a].depth < res.shells.shells[b].depth;
    });
    for (size_t i : order) {
      const Shell& s = res.shells.shells[i];
      const int parent_role = s.parent >= 0 ? role[s.parent] : 0;
      if (s.volume < 0.0 && s.parent >= 0)
        role[i] = (!o.fill_cavities && !crosses[i] && parent_role == 0) ? 1 : 3;
      else if (s.volume > 0.0 && (parent_role == 1 || parent_role == 2) && !crosses[i])
        role[i] = 2;
      else if (parent_role == 3)
        role[i] = 3;  // inside a filled cavity: filled with it
    }
    std::vector<Mesh> outward, apart;
    int64_t flipped_shells = 0;
    for (size_t i = 0; i < ns; ++i) {
      const Shell& s = res.shells.shells[i];
      Mesh sub = submesh(m, s.triangles);
      if (role[i] == 3) {
        res.cavities_filled += s.volume < 0.0;
        continue;
      }
      if (role[i] == 1 || role[i] == 2) {
        res.cavities_kept += role[i] == 1;
        apart.push_back(std::move(sub));
        continue;
      }
      if (s.volume < 0.0) {
        sub = flipped(std::move(sub));
        ++flipped_shells;
      }
      outward.push_back(std::move(sub));
    }
    auto u = o.operations.unite(outward);
    if (u) {
      // The union is exact; rounding its vertices to doubles (by less than an ulp) can leave
      // slivers that touch or cross by about that much, which changes no volume that matters.
      // They are reported, not refused: a wrap instead would add far more.
      const SelfIntersections rounded = findSelfIntersections(*u);
      std::vector<Mesh> parts = {std::move(u).value()};
      for (Mesh& a : apart) parts.push_back(std::move(a));
      res.notes.push_back("united " +
                          count(static_cast<int64_t>(outward.size()), "shell", "shells") +
                          " that overlap (corefinement)");
      if (res.cavities_filled > 0)
        res.notes.push_back("filled " + count(res.cavities_filled, "cavity", "cavities"));
      if (res.cavities_kept > 0)
        res.notes.push_back("kept " + count(res.cavities_kept, "cavity", "cavities"));
      if (flipped_shells > 0)
        res.notes.push_back("turned " +
                            count(flipped_shells, "inside-out shell", "inside-out shells") +
                            " outward");
      if (rounded.any())
        res.notes.push_back(
            count(static_cast<int64_t>(rounded.pairs.size()), "triangle pair", "triangle pairs") +
            " of the union touch after rounding to doubles");
      return done(detail::canonicalOrder(concat(parts)), RepairKind::kUnion);
    }
    res.cavities_filled = res.cavities_kept = 0;
    res.notes.push_back("the union failed (" + u.error().message + "); wrapping instead");
  }

  // 5. Wrapping: everything else.
  const MeshDiagnosis& dg = res.diagnosis;
  std::string why;
  if (dg.boundary_edges > 0) why = count(dg.boundary_edges, "boundary edge", "boundary edges");
  auto add = [&](const std::string& s) { why += (why.empty() ? "" : ", ") + s; };
  if (dg.nonmanifold_edges > 0)
    add(count(dg.nonmanifold_edges, "non-manifold edge", "non-manifold edges"));
  if (dg.misoriented_edges > 0)
    add(count(dg.misoriented_edges, "inconsistently oriented edge",
              "inconsistently oriented edges"));
  if (res.shells.intersections.any())
    add(count(static_cast<int64_t>(res.shells.intersections.pairs.size()),
              "intersecting triangle pair", "intersecting triangle pairs"));
  if (why.empty()) why = "not a clean solid";
  if (!have_ops) return needs(name, "rebuild with SPHERESET_WITH_REPAIR=ON to wrap it", why);
  const Mesh& soup = res.holes_capped > 0 ? capped : m;
  wrapParameters(soup, o, &res.wrap_alpha, &res.wrap_offset);
  if (Status st = checkWrap(soup, o, res.wrap_alpha, res.wrap_offset, name); !st) return st.error();
  auto w = o.operations.wrap(soup, res.wrap_alpha, res.wrap_offset);
  if (!w) return Error{w.error().code, name + ": " + w.error().message};
  res.notes.push_back(why + ": wrapped (alpha " + fmt("%.3g", res.wrap_alpha) + ", offset " +
                      fmt("%.3g", res.wrap_offset) + ")");
  // The wrap is the outer envelope: whatever lies inside, cavities included, is filled.
  for (const Shell& s : res.shells.shells) res.cavities_filled += s.volume < 0.0 && s.parent >= 0;
  if (res.cavities_filled > 0 && !o.fill_cavities)
    res.notes.push_back("the wrap fills " + count(res.cavities_filled, "cavity", "cavities") +
                        " that were to be kept");
  res.volume_ratio = ratio(*w);
  return done(detail::canonicalOrder(std::move(w).value()), RepairKind::kWrapped);
}

}  // namespace sphereset

// The repair ladder: from the mesh a user has to a solid the fit can run on (repair.hpp).
// Beyond the paper, which assumes a clean closed manifold. The solid of a mesh whose shells
// overlap is their union (non-zero winding); a mesh that is open, non-manifold, inconsistently
// oriented or self-intersecting gets a watertight wrap that contains every triangle (3D Alpha
// Wrapping: Portaneri, Rouxel-Labbé, Hemmer, Cohen-Steiner, Alliez 2022, "Alpha Wrapping with
// an Offset"). The cheaper exact steps (welding, capping, dropping nested shells) come first,
// since they keep the solid the user drew; the wrapping adds a thin layer and fills narrow
// concavities. Each step is a function; repairMesh calls them in order, and the shells' nesting
// is planned once (nesting_plan.hpp) for the input's volume, the nested shells and the union.
#include "sphereset/repair.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "repair/canonical_order.hpp"
#include "repair/cap_holes.hpp"
#include "repair/envelope.hpp"
#include "repair/nesting_plan.hpp"
#include "repair/orient.hpp"
#include "repair/wrap_parameters.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {
namespace {

// Weld tolerances tried automatically, relative to the bounding box diagonal: the smallest
// that closes the mesh is used (coordinates stored per corner in float differ by ~1e-7).
constexpr double kAutoWeldSteps[] = {1e-8, 1e-7, kAutoWeldRel};

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

std::string count(int64_t k, const char* one, const char* many) {
  return std::to_string(k) + " " + (k == 1 ? one : many);
}

Error needs(const std::string& name, const std::string& what, const std::string& why) {
  return Error{ErrorCode::kNotSolid, name + ": " + why + "; " + what};
}

// What a step of the ladder ends with: a solid and the kind of repair that made it (the ladder
// stops), an error (it stops too), or neither (no kind: the next step is tried).
struct StepSolid {
  std::optional<RepairKind> kind;
  Mesh mesh;
};
using StepResult = Expected<StepSolid>;
StepResult nextStep() { return StepSolid{}; }
StepResult solidOf(Mesh mesh, RepairKind kind) { return StepSolid{kind, std::move(mesh)}; }
bool stops(const StepResult& step) { return !step || step->kind.has_value(); }

// The shells' roles, where planNesting plans them.
using OptionalPlan = std::optional<detail::NestingPlan>;

// The kept shells of a plan by the nested-shells rules, each facing the way its nesting gives
// it: the solids (outward; the inside-out ones turned) and then the kept cavities, each from the
// outermost in.
Mesh nestedSolid(const Mesh& m, const ShellAnalysis& sa, const detail::NestingPlan& plan) {
  std::vector<Mesh> solids, cavities;
  for (size_t i : plan.order) {
    Mesh sub = submesh(m, sa.shells[i].triangles);
    switch (plan.roles[i]) {
      case detail::ShellRole::kOuter:
      case detail::ShellRole::kIsland:
      case detail::ShellRole::kUnitedInside:  // not planned by these rules
        solids.push_back(std::move(sub));
        break;
      case detail::ShellRole::kInsideOut:
        solids.push_back(flipped(std::move(sub)));
        break;
      case detail::ShellRole::kCavity:
        cavities.push_back(std::move(sub));
        break;
      case detail::ShellRole::kFilledCavity:
      case detail::ShellRole::kDroppedInside:
        break;
    }
  }
  for (Mesh& c : cavities) solids.push_back(std::move(c));
  return concat(solids);
}

// The notes both nesting steps end with: cavities filled and kept, inside-out shells turned.
void noteCavitiesAndTurned(int64_t turned, RepairResult* res) {
  if (res->cavities_filled > 0)
    res->notes.push_back("filled " + count(res->cavities_filled, "cavity", "cavities"));
  if (res->cavities_kept > 0)
    res->notes.push_back("kept " + count(res->cavities_kept, "cavity", "cavities"));
  if (turned > 0)
    res->notes.push_back("turned " + count(turned, "inside-out shell", "inside-out shells") +
                         " outward");
}

// Records what the nested-shells step does with the shells of a plan: counts and notes.
void recordNested(const detail::NestingPlan& plan, RepairResult* res) {
  using detail::ShellRole;
  auto number = [&](ShellRole role) {
    return static_cast<int64_t>(std::count(plan.roles.begin(), plan.roles.end(), role));
  };
  const int64_t turned = number(ShellRole::kInsideOut);
  res->shells_dropped = number(ShellRole::kDroppedInside);
  res->cavities_filled = number(ShellRole::kFilledCavity);
  res->cavities_kept = number(ShellRole::kCavity);
  if (res->shells_dropped > 0)
    res->notes.push_back("dropped " + count(res->shells_dropped, "shell", "shells") +
                         " nested inside another with the same orientation");
  noteCavitiesAndTurned(turned, res);
}

// The input's volume, where defined: with shells closed, oriented and apart (planned by the
// nested-shells rules), the solid they bound; otherwise, for a closed surface whose edges are
// balanced, the magnitude of its signed volume (regions it winds around twice count twice).
double inputVolume(const Mesh& m, const ShellAnalysis& sa, const OptionalPlan& plan) {
  if (plan && !plan->union_rules) return signedVolume(nestedSolid(m, sa, *plan));
  if (balancedClosed(m)) return std::abs(signedVolume(m));
  return std::numeric_limits<double>::quiet_NaN();
}

// 1. Welding: the given tolerance, or (repair on) the smallest automatic one that closes the
// mesh. Records the tolerance used.
Expected<Mesh> weldVertices(const Mesh& mesh, const RepairOptions& o, const std::string& name,
                            RepairResult* res) {
  Mesh m = mesh;
  if (o.weld_tolerance > 0.0) {
    auto w = reweld(mesh, o.weld_tolerance, name);
    if (!w) return w.error();
    m = std::move(w).value();
    res->weld_tolerance = o.weld_tolerance;
  } else if (o.enabled && o.weld_tolerance < 0.0 && res->diagnosis.boundary_edges > 0) {
    const double diag = res->diagnosis.bbox.diagonal();
    // The largest tolerance first: when it does not close the mesh, the smaller ones are not
    // tried (a large mesh with a real hole pays for one weld, not three).
    auto closes = [&](double rel) -> bool {
      auto w = reweld(mesh, rel * diag, name);
      if (!w || !diagnoseMesh(*w).closed) return false;
      m = std::move(w).value();
      res->weld_tolerance = rel * diag;
      res->notes.clear();
      res->notes.push_back("welded vertices within " + fmt("%.3g", res->weld_tolerance) + " (" +
                           fmt("%.0e", rel) + " of the diagonal), which closes the mesh");
      return true;
    };
    constexpr size_t kSteps = std::size(kAutoWeldSteps);
    if (closes(kAutoWeldSteps[kSteps - 1]))
      for (size_t i = 0; i + 1 < kSteps; ++i)
        if (closes(kAutoWeldSteps[i])) break;
  }
  return m;
}

// Repair off: a closed oriented 2-manifold is taken as it is, anything else refused.
StepResult acceptAsIs(Mesh m, const std::string& name) {
  const MeshDiagnosis d = diagnoseMesh(m);
  if (!d.isSolid()) return notSolidError(name, d);
  return solidOf(std::move(m), RepairKind::kNone);
}

// Consistent orientation, where only the orientation is wrong (every edge of at most two
// triangles): exact, so it comes before anything that changes the geometry.
void orientTriangles(Mesh* m, RepairResult* res) {
  const MeshDiagnosis d = diagnoseMesh(*m);
  if (!(d.misoriented_edges > 0 && d.nonmanifold_edges == 0)) return;
  Mesh oriented = *m;
  const int64_t turned = detail::orientConsistently(&oriented);
  if (turned <= 0) return;
  *m = std::move(oriented);
  res->triangles_flipped = turned;
  res->notes.push_back("flipped " + count(turned, "triangle", "triangles") +
                       " to a consistent orientation");
}

// 2. Nested shells: every shell clean and none crossing another; the solid they bound by the
// plan (nested-shells rules). Dropping nested shells or filling cavities takes the union of the
// shells (non-zero winding) without computing anything.
StepResult keepNestedShells(const Mesh& m, const ShellAnalysis& sa, const OptionalPlan& plan,
                            double input_volume, RepairResult* res) {
  if (!(allClean(sa) && sa.intersecting.empty())) return nextStep();
  Mesh solid = nestedSolid(m, sa, *plan);
  recordNested(*plan, res);
  res->volume_ratio = signedVolume(solid) / input_volume;
  const bool united = res->shells_dropped > 0 || res->cavities_filled > 0;
  return solidOf(std::move(solid), united ? RepairKind::kUnion : RepairKind::kNone);
}

// 3. Capping: open but otherwise sound shells, their holes closed (holes are filled like
// cavities, so not when cavities are kept). *capped is the mesh with its holes closed when any
// were (RepairResult::holes_capped), the wrap's input then.
StepResult closeHoles(const Mesh& m, const RepairOptions& o, Mesh* capped, RepairResult* res) {
  if (!(o.fill_cavities && res->diagnosis.boundary_edges > 0)) return nextStep();
  *capped = m;
  res->holes_capped = detail::capHoles(capped);
  // Caps only add triangles: crossings already there stay, and the capped mesh is then only
  // the wrap's input (with its holes closed), not worth analysing again.
  if (!(res->holes_capped > 0 && !res->shells.intersections.any())) return nextStep();
  const ShellAnalysis sc = analyzeShells(*capped);
  if (!(allClean(sc) && sc.intersecting.empty())) return nextStep();
  res->notes.push_back("closed " + count(res->holes_capped, "hole", "holes") +
                       " (triangulated over their own vertices)");
  const OptionalPlan plan = detail::planNesting(sc, o.fill_cavities);
  recordNested(*plan, res);
  return solidOf(nestedSolid(*capped, sc, *plan), RepairKind::kCapped);
}

// 4. Union: every shell clean, some crossing. By the plan (union rules), the outward shells and
// the inside-out ones turned outward are united; kept cavities and their islands stay apart
// from the union, which would swallow them; filled cavities and what they hold are dropped.
StepResult uniteShells(const Mesh& m, const ShellAnalysis& sa, const OptionalPlan& plan,
                       const RepairOptions& o, const std::string& name, RepairResult* res) {
  if (!(allClean(sa) && !sa.intersecting.empty())) return nextStep();
  if (!o.operations.unite)
    return needs(name, "rebuild with SPHERESET_WITH_REPAIR=ON to fit their union",
                 count(static_cast<int64_t>(sa.intersecting.size()), "pair of shells intersects",
                       "pairs of shells intersect"));
  std::vector<Mesh> outward, apart;
  int64_t turned = 0;
  for (size_t i = 0; i < sa.shells.size(); ++i) {
    Mesh sub = submesh(m, sa.shells[i].triangles);
    switch (plan->roles[i]) {
      case detail::ShellRole::kFilledCavity:
        ++res->cavities_filled;
        break;
      case detail::ShellRole::kDroppedInside:
        break;
      case detail::ShellRole::kCavity:
        ++res->cavities_kept;
        apart.push_back(std::move(sub));
        break;
      case detail::ShellRole::kIsland:
        apart.push_back(std::move(sub));
        break;
      case detail::ShellRole::kInsideOut:
        ++turned;
        outward.push_back(flipped(std::move(sub)));
        break;
      case detail::ShellRole::kOuter:
      case detail::ShellRole::kUnitedInside:
        outward.push_back(std::move(sub));
        break;
    }
  }
  auto u = o.operations.unite(outward);
  if (!u) {
    res->cavities_filled = res->cavities_kept = 0;
    res->notes.push_back("the union failed (" + u.error().message + "); wrapping instead");
    return nextStep();
  }
  // The union is exact; rounding its vertices to doubles (by less than an ulp) can leave
  // slivers that touch or cross by about that much, which changes no volume that matters.
  // They are reported, not refused: a wrap instead would add far more.
  const SelfIntersections rounded = findSelfIntersections(*u);
  std::vector<Mesh> parts = {std::move(u).value()};
  for (Mesh& a : apart) parts.push_back(std::move(a));
  res->notes.push_back("united " + count(static_cast<int64_t>(outward.size()), "shell", "shells") +
                       " that overlap (corefinement)");
  noteCavitiesAndTurned(turned, res);
  if (rounded.any())
    res->notes.push_back(
        count(static_cast<int64_t>(rounded.pairs.size()), "triangle pair", "triangle pairs") +
        " of the union touch after rounding to doubles");
  return solidOf(detail::canonicalOrder(concat(parts)), RepairKind::kUnion);
}

// 5. Wrapping: everything else, `soup` being the mesh (with its holes closed when capping
// closed any).
StepResult wrapMesh(const Mesh& soup, const RepairOptions& o, double input_volume,
                    const std::string& name, RepairResult* res) {
  const MeshDiagnosis& dg = res->diagnosis;
  std::string why;
  if (dg.boundary_edges > 0) why = count(dg.boundary_edges, "boundary edge", "boundary edges");
  auto add = [&](const std::string& s) { why += (why.empty() ? "" : ", ") + s; };
  if (dg.nonmanifold_edges > 0)
    add(count(dg.nonmanifold_edges, "non-manifold edge", "non-manifold edges"));
  if (dg.misoriented_edges > 0)
    add(count(dg.misoriented_edges, "inconsistently oriented edge",
              "inconsistently oriented edges"));
  if (res->shells.intersections.any())
    add(count(static_cast<int64_t>(res->shells.intersections.pairs.size()),
              "intersecting triangle pair", "intersecting triangle pairs"));
  if (why.empty()) why = "not a clean solid";
  if (!(o.operations.unite && o.operations.wrap))
    return needs(name, "rebuild with SPHERESET_WITH_REPAIR=ON to wrap it", why);
  detail::wrapParameters(soup, o, &res->wrap_alpha, &res->wrap_offset);
  if (Status st = detail::checkWrap(soup, o.wrap_alpha > 0.0 || o.wrap_offset > 0.0,
                                    res->wrap_alpha, res->wrap_offset, name);
      !st)
    return st.error();
  auto w = o.operations.wrap(soup, res->wrap_alpha, res->wrap_offset);
  if (!w) return Error{w.error().code, name + ": " + w.error().message};
  res->notes.push_back(why + ": wrapped (alpha " + fmt("%.3g", res->wrap_alpha) + ", offset " +
                       fmt("%.3g", res->wrap_offset) + ")");
  // The wrap is the outer envelope: whatever lies inside, cavities included, is filled.
  for (const Shell& s : res->shells.shells) res->cavities_filled += s.volume < 0.0 && s.parent >= 0;
  if (res->cavities_filled > 0 && !o.fill_cavities)
    res->notes.push_back("the wrap fills " + count(res->cavities_filled, "cavity", "cavities") +
                         " that were to be kept");
  res->volume_ratio = signedVolume(*w) / input_volume;
  return solidOf(detail::canonicalOrder(std::move(w).value()), RepairKind::kWrapped);
}

// The result of the ladder: the step's solid, its kind (kNone becomes kReoriented or kWelded
// when those steps changed the mesh), and the time taken since t0.
Expected<RepairResult> finish(StepResult step, RepairResult res,
                              std::chrono::steady_clock::time_point t0, const std::string& name) {
  if (!step) return step.error();
  res.solid = std::move(step->mesh);
  res.kind = *step->kind;
  if (res.kind == RepairKind::kNone && res.triangles_flipped > 0)
    res.kind = RepairKind::kReoriented;
  if (res.kind == RepairKind::kNone && res.weld_tolerance > 0.0) res.kind = RepairKind::kWelded;
  if (!(signedVolume(res.solid) > 0.0))
    return Error{ErrorCode::kNotSolid, name + ": the repaired mesh encloses no volume"};
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
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

namespace {

// The ladder: the walls as a solid.
Expected<RepairResult> repairWalls(const Mesh& mesh, const RepairOptions& o,
                                   const std::string& name) {
  const auto t0 = std::chrono::steady_clock::now();
  RepairResult res;
  res.original = mesh;
  res.diagnosis = diagnoseMesh(mesh);
  res.volume_ratio = std::numeric_limits<double>::quiet_NaN();
  if (Status st = checkRepairOptions(o); !st) return st.error();
  if (mesh.triangles.empty())
    return Error{ErrorCode::kInvalidData, name + ": the mesh has no triangles"};
  auto done = [&](StepResult step) { return finish(std::move(step), std::move(res), t0, name); };

  Expected<Mesh> welded = weldVertices(mesh, o, name, &res);
  if (!welded) return welded.error();
  Mesh m = std::move(welded).value();
  if (!o.enabled) return done(acceptAsIs(std::move(m), name));
  orientTriangles(&m, &res);

  // The shells, clean and apart or not, and their roles by how they nest: planned once, for the
  // input's volume, the nested shells and the union.
  res.shells = analyzeShells(m);
  const OptionalPlan plan = detail::planNesting(res.shells, o.fill_cavities);
  const double input_volume = inputVolume(m, res.shells, plan);
  if (StepResult s = keepNestedShells(m, res.shells, plan, input_volume, &res); stops(s))
    return done(std::move(s));
  Mesh capped;
  if (StepResult s = closeHoles(m, o, &capped, &res); stops(s)) return done(std::move(s));
  if (StepResult s = uniteShells(m, res.shells, plan, o, name, &res); stops(s))
    return done(std::move(s));
  return done(wrapMesh(res.holes_capped > 0 ? capped : m, o, input_volume, name, &res));
}

}  // namespace

Expected<RepairResult> repairMesh(const Mesh& mesh, const RepairOptions& o,
                                  const std::string& name) {
  const auto t0 = std::chrono::steady_clock::now();
  auto res = repairWalls(mesh, o, name);
  if (!res || o.fill_openings == 0.0) return res;
  if (Status st = detail::closeOpenings(o, name, &*res); !st) return st.error();
  res->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

const Mesh* originalTriangles(const RepairResult& r) {
  const bool same = r.kind == RepairKind::kNone && r.shells_dropped == 0 &&
                    r.cavities_filled == 0 && r.fill_openings == 0.0;
  return same ? nullptr : &r.original;
}

const Mesh* envelopeWalls(const RepairResult& r) {
  return r.fill_openings > 0.0 ? &r.walls : nullptr;
}

}  // namespace sphereset

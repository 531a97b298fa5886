// The nesting plan of a mesh's shells (nesting_plan.hpp): under non-zero winding, what each
// shell adds to the solid given the shells around it. Shells are planned from the outermost in;
// a shell's role follows from its orientation (the sign of its volume), from what encloses it,
// and, when shells cross, from whether it crosses one.
//
// Two sets of rules, one for each step that uses the plan. When no shell crosses another, the
// nested-shells step assembles the solid from the shells as they are; when some cross, the union
// step unites the outward ones by corefinement and keeps cavities and their islands apart. The
// two decide differently in some nestings, and each keeps its own results. First, in what
// encloses a shell:
//   nested-shells rules: the nearest enclosing shell that is kept, the dropped and filled ones
//     looked through; kOuter, kInsideOut and kIsland enclose a solid, kCavity a cavity;
//   union rules: the shell's parent itself; kOuter, kInsideOut and kUnitedInside enclose a
//     solid, kCavity and kIsland a cavity, kFilledCavity and kDroppedInside something filled.
// Then in the role that follows ("flat": a signed volume of 0, neither outward nor inward):
//   encloser  shell     nested-shells rules        union rules
//   nothing   outward   kOuter                     kOuter
//   nothing   inward    kInsideOut                 kInsideOut
//   nothing   flat      kInsideOut                 kOuter
//   solid     inward    kCavity or kFilledCavity   the same; kFilledCavity if it crosses one
//   solid     flat      kCavity or kFilledCavity   kUnitedInside
//   solid     outward   kDroppedInside             kUnitedInside (the union absorbs it)
//   cavity    outward   kIsland                    the same; kUnitedInside if it crosses one
//   cavity    inward    kDroppedInside             kFilledCavity
//   cavity    flat      kDroppedInside             kUnitedInside
//   filled    inward    (looked through)           kFilledCavity
//   filled    outward   (looked through)           kDroppedInside
//   filled    flat      (looked through)           kDroppedInside
// So, among shells that cross nothing: an island's own cavities are kept or filled as
// fill_cavities says by the nested-shells rules and always filled by the union rules, and an
// island inside an island is dropped by the first and kept apart by the second; an outward shell
// inside a solid is dropped by the first and united by the second; an inward shell inside a
// kept cavity counts as a shell dropped by the first and as a cavity filled by the second, and
// the shells inside it are planned anew by the first and filled with it by the second; an
// outward shell inside a filled cavity counts as a shell dropped by the first and is dropped
// uncounted by the second.
#include "repair/nesting_plan.hpp"

#include <algorithm>
#include <numeric>

namespace sphereset::detail {
namespace {

// What encloses a shell, by the rules in force (above).
enum class Encloser { kNothing, kSolid, kCavity, kFilled };

// Nested-shells rules: the nearest enclosing shell that is kept.
Encloser nearestKept(const ShellAnalysis& sa, const std::vector<ShellRole>& roles, int32_t parent) {
  for (int32_t p = parent; p >= 0; p = sa.shells[p].parent) switch (roles[p]) {
      case ShellRole::kOuter:
      case ShellRole::kInsideOut:
      case ShellRole::kIsland:
        return Encloser::kSolid;
      case ShellRole::kCavity:
        return Encloser::kCavity;
      case ShellRole::kFilledCavity:
      case ShellRole::kDroppedInside:
      case ShellRole::kUnitedInside:
        break;
    }
  return Encloser::kNothing;
}

// Union rules: the parent itself.
Encloser parentEncloser(const std::vector<ShellRole>& roles, int32_t parent) {
  if (parent < 0) return Encloser::kNothing;
  switch (roles[parent]) {
    case ShellRole::kOuter:
    case ShellRole::kInsideOut:
    case ShellRole::kUnitedInside:
      return Encloser::kSolid;
    case ShellRole::kCavity:
    case ShellRole::kIsland:
      return Encloser::kCavity;
    case ShellRole::kFilledCavity:
    case ShellRole::kDroppedInside:
      return Encloser::kFilled;
  }
  return Encloser::kSolid;
}

ShellRole nestedShellsRole(Encloser e, double volume, bool fill_cavities) {
  const bool outward = volume > 0.0;  // flat counts as inward
  switch (e) {
    case Encloser::kNothing:
      return outward ? ShellRole::kOuter : ShellRole::kInsideOut;
    case Encloser::kSolid:
      if (outward) return ShellRole::kDroppedInside;
      return fill_cavities ? ShellRole::kFilledCavity : ShellRole::kCavity;
    case Encloser::kCavity:
      return outward ? ShellRole::kIsland : ShellRole::kDroppedInside;
    case Encloser::kFilled:  // not an encloser by these rules
      break;
  }
  return ShellRole::kDroppedInside;
}

ShellRole unionRole(Encloser e, double volume, bool crosses, bool fill_cavities) {
  const bool outward = volume > 0.0, inward = volume < 0.0;  // flat is neither
  switch (e) {
    case Encloser::kNothing:
      return inward ? ShellRole::kInsideOut : ShellRole::kOuter;
    case Encloser::kSolid:
      if (!inward) return ShellRole::kUnitedInside;
      return fill_cavities || crosses ? ShellRole::kFilledCavity : ShellRole::kCavity;
    case Encloser::kCavity:
      if (inward) return ShellRole::kFilledCavity;
      return outward && !crosses ? ShellRole::kIsland : ShellRole::kUnitedInside;
    case Encloser::kFilled:
      return inward ? ShellRole::kFilledCavity : ShellRole::kDroppedInside;
  }
  return ShellRole::kUnitedInside;
}

}  // namespace

std::optional<NestingPlan> planNesting(const ShellAnalysis& sa, bool fill_cavities) {
  bool closed_oriented = true, clean = true;
  for (const Shell& s : sa.shells) {
    closed_oriented = closed_oriented && s.closed && s.oriented;
    clean = clean && s.clean();
  }
  if (!closed_oriented || (sa.intersections.any() && !clean)) return std::nullopt;
  NestingPlan plan;
  const size_t n = sa.shells.size();
  plan.union_rules = !sa.intersecting.empty();
  std::vector<char> crosses(n, 0);
  for (const auto& [a, b] : sa.intersecting) crosses[a] = crosses[b] = 1;
  plan.order.resize(n);
  std::iota(plan.order.begin(), plan.order.end(), size_t{0});
  std::stable_sort(plan.order.begin(), plan.order.end(),
                   [&](size_t a, size_t b) { return sa.shells[a].depth < sa.shells[b].depth; });
  // A parent lies inside fewer shells than its child and is planned first, unless the
  // containment tests, each made at one point, disagree. A parent not planned yet is looked
  // through by the nested-shells rules and encloses a solid by the union rules.
  plan.roles.assign(n, plan.union_rules ? ShellRole::kUnitedInside : ShellRole::kDroppedInside);
  for (size_t i : plan.order) {
    const Shell& s = sa.shells[i];
    plan.roles[i] = plan.union_rules ? unionRole(parentEncloser(plan.roles, s.parent), s.volume,
                                                 crosses[i] != 0, fill_cavities)
                                     : nestedShellsRole(nearestKept(sa, plan.roles, s.parent),
                                                        s.volume, fill_cavities);
  }
  return plan;
}

}  // namespace sphereset::detail

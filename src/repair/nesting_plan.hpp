// Private: the role of each shell of a mesh by how it nests in the others (repair steps "nested
// shells" and "union"): which shells bound the solid, which are cavities, which are islands in a
// cavity, and which are dropped because the shell around them already holds them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sphereset/mesh_defects.hpp"

namespace sphereset::detail {

// What becomes of a shell. Where the two sets of rules (nesting_plan.cpp, which tables them)
// differ, the role says what the rules in force decided: an outward shell inside a solid is
// kDroppedInside by the nested-shells rules and kUnitedInside by the union rules, say.
enum class ShellRole : uint8_t {
  kOuter,          // outermost, facing outward: kept (or united) as it is
  kInsideOut,      // outermost, facing inward: turned outward, then as kOuter
  kCavity,         // inward, inside a solid: kept as a cavity (fill_cavities off)
  kFilledCavity,   // inward, inside a solid (union rules: inside anything): filled, i.e. dropped
                   // and counted as a cavity filled
  kIsland,         // outward, inside a kept cavity or (union rules) an island: kept, a solid of
                   // its own (apart from the union by the union rules)
  kDroppedInside,  // inside a shell that already holds it: dropped
  kUnitedInside,   // union rules only: enclosed, yet neither inward, nor an island, nor inside
                   // something filled: united with the others
};

// The roles of a mesh's shells, decided once from their ShellAnalysis.
struct NestingPlan {
  // Some shells cross: the plan follows the union rules (planNesting), otherwise the
  // nested-shells rules.
  bool union_rules = false;
  std::vector<ShellRole> roles;  // one per shell, indexed like ShellAnalysis::shells
  // The shells from the outermost in (by depth, ties by index): the order the roles were
  // decided in, and the order the nested-shells step lists the kept shells in.
  std::vector<size_t> order;
};

// The roles of the shells of `sa`; fill_cavities decides between kCavity and kFilledCavity.
// Made when every shell is closed and oriented and either nothing intersects (the nested-shells
// rules) or every shell is clean and some cross one another (the union rules): what the input's
// volume, the nested shells and the union need. Nothing otherwise: the nesting of open or
// self-intersecting shells means nothing to the repair (such shells may even seem to contain
// each other).
std::optional<NestingPlan> planNesting(const ShellAnalysis& sa, bool fill_cavities);

}  // namespace sphereset::detail

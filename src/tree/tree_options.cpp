// The tree's layout options as one table (tree.hpp): the command line's flags and the Python
// keywords are made from it, and the library parses and checks what users type through it. And
// a level's statistics as a field list.
#include <string>
#include <string_view>

#include "sphereset/sphere_tree.hpp"
#include "sphereset/tree.hpp"

namespace sphereset {
namespace {

constexpr const char* kParentNames[] = {"minimal", "outside"};

// Children per node beyond this make no tree worth the name (a flat set of that size is better
// queried as it is); 26 levels of 2 children reach the tree's slot limit.
constexpr int kMaxBranching = 1024;
constexpr int kMaxDepth = 26;

constexpr OptionSpec kTreeOptions[] = {
    {"branching",
     "--branch",
     OptionType::kInteger,
     2,
     kMaxBranching,
     {},
     "8",
     "Children per node at most (B)"},
    {"depth",
     "--depth",
     OptionType::kInteger,
     1,
     kMaxDepth,
     {},
     "2",
     "Levels below the root (D): D + 1 levels, at most B^D leaves"},
    {"parents", "--parents", OptionType::kChoice, 0, 0, kParentNames, "minimal",
     "minimal (smallest ball enclosing the children) or outside (least outside volume while "
     "enclosing them)"},
};

}  // namespace

std::span<const OptionSpec> treeOptionTable() { return kTreeOptions; }

Status setTreeOption(TreeOptions* o, const std::string& name, const std::string& text) {
  auto parsed = parseTableOption(kTreeOptions, "tree", name, text);
  if (!parsed) return parsed.error();
  const OptionValue* v = &parsed->value;
  const std::string_view n = parsed->spec->name;
  if (n == "branching") o->branching = static_cast<int>(v->integer);
  if (n == "depth") o->depth = static_cast<int>(v->integer);
  if (n == "parents")
    o->parents = v->choice == "outside" ? TreeParents::kOutsideVolume : TreeParents::kMinimal;
  return {};
}

const char* treeParentsName(TreeParents p) {
  return p == TreeParents::kOutsideVolume ? "outside" : "minimal";
}

Status checkTreeOptions(const TreeOptions& o) {
  // Each number as its text, through the same parser as every front door's.
  for (const auto& [name, value] : {std::pair<const char*, int>{"branching", o.branching},
                                    std::pair<const char*, int>{"depth", o.depth}})
    if (Status st = checkTableValue(kTreeOptions, "tree", name, value); !st) return st;
  if (o.max_iterations < 1 || o.optimizer_evaluations < 0)
    return Error{ErrorCode::kInvalidArgument,
                 "tree max_iterations must be at least 1 and optimizer_evaluations at least 0"};
  if (SphereTree::slotCount(o.branching, o.depth) < 0)
    return Error{ErrorCode::kInvalidArgument, "branching " + std::to_string(o.branching) +
                                                  " and depth " + std::to_string(o.depth) +
                                                  " make a tree of more than " +
                                                  std::to_string(SphereTree::kMaxSlots) + " nodes"};
  return {};
}

std::vector<ResultField> treeLevelFields(const TreeLevelStats& l, double volume) {
  return {
      {"level", int64_t{l.level}, "0 is the root"},
      {"spheres", l.nodes, "spheres of the level"},
      {"rounds", int64_t{l.iterations}, "Lloyd rounds run (0 for the leaves)"},
      {"converged", l.converged, "the assignment stopped changing before the cap"},
      {"outside_volume", l.outside_volume, "Σ outside volume of the level"},
      {"er_sum", volume > 0.0 ? l.outside_volume / volume : 0.0, "E_r of the level"},
  };
}

}  // namespace sphereset

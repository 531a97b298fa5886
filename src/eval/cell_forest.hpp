// Private: the interior certificate's octree kept between calls, for the incremental
// certificate (incremental_certificate.cpp). Each of the 8³ root cubes of cover_cells.hpp holds
// the tree its walk made: every cube's verdict (cellVerdict, the rule of the full evaluation),
// the largest gap and the undecided cells below it, and the solid's geometry at its centre,
// which does not depend on the spheres and is kept for when the walk meets the cube again.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cover/cover_cells.hpp"
#include "eval/coverage_pieces.hpp"

namespace sphereset::detail {

class CellForest {
 public:
  CellForest(const SolidIndex& index, int max_depth);

  // Walks every root cube against `grown` (the grown spheres), ignoring what is stored.
  // Returns the cubes judged.
  int64_t certifyAll(const SphereGrid& grown);
  // The set changed only in the balls `changed` (grown; each the old or the new ball of a
  // changed sphere): judges again the cubes that one of them comes within the cube's stored gap
  // of, keeps the others' verdicts. Returns the cubes judged.
  int64_t update(const SphereGrid& grown, std::span<const Sphere> changed);

  // Each root cube's largest gap (a length) and undecided finest cells, in root order.
  std::vector<PieceCover> roots() const;
  int64_t cellCount() const;  // cubes of the walk as it stands

 private:
  struct Node {
    double gap = 0.0;       // largest gap below (a length), 0 when none
    int64_t undecided = 0;  // undecided finest cubes below
    int64_t cells = 1;      // cubes of the walk below, this one included
    int64_t children = -1;  // the first of its eight children in the tree; -1 before any split
    CellVerdict verdict = CellVerdict::kSplit;
    CellGeometry geometry;
  };
  // One root cube's nodes, the root first, children eight in a row. The children of a cube
  // that stops splitting stay, with their geometry, for when it splits again, until they
  // outnumber the cubes of the walk (then compact drops them).
  struct Tree {
    std::vector<Node> nodes = std::vector<Node>(1);
  };
  struct Walk;
  // parent: the geometry of the cube this one splits (none at the roots), for cellVerdict.
  void walk(Tree* tree, int64_t node, const Vec3& mn, double size, int depth, bool force, Walk* w,
            const CellGeometry* parent = nullptr) const;
  static void compact(Tree* tree);

  const SolidIndex* index_;
  int max_depth_;
  std::vector<Tree> trees_;
};

// Whether ball b comes within `reach` of the box [lo, hi], allowing for the rounding of the
// tests that decide coverage (a margin relative to the magnitudes involved): false only when
// no point of the box (or within rounding of it) lies in b or within `reach` of it.
bool ballNearBox(const Sphere& b, const Vec3& lo, const Vec3& hi, double reach);

}  // namespace sphereset::detail

// The interior walk's cube geometry (cover/cover_cells.hpp): a cube's side of the surface taken
// from its parent's (sideNear) is the side classify() gives, on every cube of an octree over a
// robot link and a torus down to a depth where cubes meet the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "cover/cover_cells.hpp"
#include "test_meshes.hpp"

namespace sphereset::detail {
namespace {

// Every cube below the 8³ roots down to max_depth: sideNear from its parent against classify.
void compareSides(const SolidIndex& index, int max_depth, int64_t* cubes, int64_t* taken) {
  const std::function<void(const Vec3&, double, int, const CellGeometry*)> visit =
      [&](const Vec3& mn, double size, int depth, const CellGeometry* parent) {
        const Vec3 center = mn + Vec3::Constant(0.5 * size);
        const double half_diag = 0.5 * std::sqrt(3.0) * size;
        CellGeometry g;
        g.distance = index.distance(center);
        g.where =
            parent ? sideNear(index, center, g.distance, parent->where, parent->distance, half_diag)
                   : index.classify(center);
        g.known = true;
        const Containment truth = index.classify(center);
        ASSERT_EQ(g.where, truth) << "cube at depth " << depth;
        ++*cubes;
        *taken += parent && half_diag < parent->distance &&
                  parent->where != Containment::kBoundary && g.distance > index.boundaryTolerance();
        if (depth == max_depth) return;
        for (int k = 0; k < 8; ++k) visit(childCell(mn, 0.5 * size, k), 0.5 * size, depth + 1, &g);
      };
  for (int k = 0; k < kRootCells; ++k) {
    double size = 0.0;
    const Vec3 mn = rootCell(index.bounds(), k, &size);
    visit(mn, size, 0, nullptr);
  }
}

TEST(CoverCells, ACubeTakesItsParentsSideOnlyWhereClassifyAgrees) {
  for (const Mesh& mesh : {test::robotLink(), test::makeTorus(1.0, 0.3, 48, 24)}) {
    const SolidIndex index(mesh);
    int64_t cubes = 0, taken = 0;
    compareSides(index, 2, &cubes, &taken);
    EXPECT_EQ(cubes, kRootCells * (1 + 8 + 64));
    // Most cubes qualify for their parent's side, so the comparison covers the shortcut.
    EXPECT_GT(taken, cubes / 2);
  }
}

}  // namespace
}  // namespace sphereset::detail

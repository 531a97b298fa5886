// The interior walk's cube geometry (cover/cover_cells.hpp): a cube's side of the surface taken
// from its parent's (sideNear) is the side classify() gives, on every cube of an octree over a
// robot link and a torus down to a depth where cubes meet the surface; a walk with its cubes'
// geometry kept (GeometryTree) or within a region judges as the full walk does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <tuple>
#include <vector>

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

// What a walk reported: each gap (cube corner, side, depth, gap) and undecided cube, in order.
using Call = std::tuple<double, double, double, double, int, double>;

std::vector<Call> walkAll(const SolidIndex& index, const SphereGrid& grid, int max_depth,
                          const Aabb* region, GeometryForest* cells) {
  std::vector<Call> calls;
  for (int k = 0; k < kRootCells; ++k) {
    double size = 0.0;
    const Vec3 mn = rootCell(index.bounds(), k, &size);
    const WalkScope scope{.region = region, .tree = cells ? &cells->trees[k] : nullptr};
    walkSolidCells(
        index, grid, mn, size, 0, max_depth,
        [&](const Vec3& lo, double s, int depth, double gap) {
          calls.emplace_back(lo.x(), lo.y(), lo.z(), s, depth, gap);
          return true;  // as the fit's bound: look deeper
        },
        [&](const Vec3& lo, double s) { calls.emplace_back(lo.x(), lo.y(), lo.z(), s, -1, 0.0); },
        nullptr, scope);
  }
  return calls;
}

// Sets of a few spheres inside the solid's box that leave gaps, one after another through the
// same kept geometry (as a progressive run's bounds): every walk reports what the walk without
// it reports, and the one within a region what the full walk reports on the cubes that meet it.
TEST(CoverCells, AWalkWithKeptGeometryOrWithinARegionJudgesAsTheFullWalk) {
  const SolidIndex index(test::robotLink());
  const Aabb& b = index.bounds();
  const double diag = b.diagonal();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  GeometryForest cells;
  for (int set = 0; set < 3; ++set) {
    std::vector<Sphere> spheres;
    for (int i = 0; i < 6 + 4 * set; ++i) {
      const Vec3 t(u(rng), u(rng), u(rng));
      spheres.push_back({b.min + t.cwiseProduct(b.max - b.min), (0.1 + 0.1 * u(rng)) * diag});
    }
    const SphereGrid grid(spheres);
    const std::vector<Call> full = walkAll(index, grid, 3, nullptr, nullptr);
    ASSERT_FALSE(full.empty());
    EXPECT_EQ(walkAll(index, grid, 3, nullptr, &cells), full) << "set " << set;
    const auto held = [&] {
      size_t n = 0;
      for (const GeometryTree& tree : cells.trees) n += tree.nodes.size();
      return n;
    };
    const size_t kept = held();
    EXPECT_GT(kept, static_cast<size_t>(kRootCells));
    // The same set again meets only cubes it kept: the same report, nothing added.
    EXPECT_EQ(walkAll(index, grid, 3, nullptr, &cells), full) << "set " << set;
    EXPECT_EQ(held(), kept);
    // A region around one sphere, walked with the kept geometry.
    const Sphere& s = spheres[set];
    const Aabb region{s.center - Vec3::Constant(s.radius), s.center + Vec3::Constant(s.radius)};
    std::vector<Call> within;
    for (const Call& c : full) {
      const Vec3 lo(std::get<0>(c), std::get<1>(c), std::get<2>(c));
      if (!cubeMisses(&region, lo, std::get<3>(c), regionSlack(&region))) within.push_back(c);
    }
    EXPECT_FALSE(within.empty());
    EXPECT_LT(within.size(), full.size());
    EXPECT_EQ(walkAll(index, grid, 3, &region, &cells), within) << "set " << set;
  }
  // Trimmed below its cap the forest keeps its trees; cleared, a tree holds its root alone.
  GeometryTree& largest = *std::max_element(
      cells.trees.begin(), cells.trees.end(),
      [](const GeometryTree& x, const GeometryTree& y) { return x.nodes.size() < y.nodes.size(); });
  const size_t before = largest.nodes.size();
  ASSERT_GT(before, 1u);
  cells.trim();
  EXPECT_EQ(largest.nodes.size(), before);
  largest.clear();
  EXPECT_EQ(largest.nodes.size(), 1u);
  EXPECT_FALSE(largest.nodes[0].geometry.known);
}

}  // namespace
}  // namespace sphereset::detail

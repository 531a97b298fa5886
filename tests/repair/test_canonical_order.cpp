// The canonical order of a repair's output: the same triangles listed in any order, with the
// vertices numbered in any order and each triangle started at any corner, come out identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "repair/canonical_order.hpp"
#include "test_meshes.hpp"

namespace sphereset::test {
namespace {

// The same mesh with its vertices renumbered, its triangles shuffled and each rotated.
Mesh shuffled(const Mesh& m, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<int32_t> perm(m.vertices.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  Mesh out;
  out.vertices.resize(m.vertices.size());
  for (size_t i = 0; i < perm.size(); ++i) out.vertices[perm[i]] = m.vertices[i];
  for (const Triangle& t : m.triangles) {
    Triangle r = {perm[t[0]], perm[t[1]], perm[t[2]]};
    std::rotate(r.begin(), r.begin() + rng() % 3, r.end());
    out.triangles.push_back(r);
  }
  std::shuffle(out.triangles.begin(), out.triangles.end(), rng);
  return out;
}

TEST(CanonicalOrder, AnyListingOfTheSameMeshGivesOneResult) {
  const Mesh m = robotLink();
  const Mesh a = detail::canonicalOrder(m);
  for (uint32_t seed : {1u, 2u, 3u}) {
    const Mesh b = detail::canonicalOrder(shuffled(m, seed));
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.triangles, b.triangles);
  }
}

TEST(CanonicalOrder, KeepsTheGeometryAndTheOrientation) {
  const Mesh m = robotLink();
  const Mesh a = detail::canonicalOrder(m);
  ASSERT_EQ(a.vertices.size(), m.vertices.size());
  ASSERT_EQ(a.triangles.size(), m.triangles.size());
  EXPECT_NEAR(signedVolume(a), signedVolume(m), 1e-12 * std::abs(signedVolume(m)));
  EXPECT_NEAR(surfaceArea(a), surfaceArea(m), 1e-12 * surfaceArea(m));
  EXPECT_TRUE(std::is_sorted(a.triangles.begin(), a.triangles.end()));
  for (const Triangle& t : a.triangles) EXPECT_LT(t[0], std::min(t[1], t[2]));
  for (size_t i = 1; i < a.vertices.size(); ++i)
    EXPECT_FALSE(std::lexicographical_compare(a.vertices[i].begin(), a.vertices[i].end(),
                                              a.vertices[i - 1].begin(), a.vertices[i - 1].end()));
}

}  // namespace
}  // namespace sphereset::test

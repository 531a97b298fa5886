// Vertex welding with a tolerance at the ends of the double range.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mesh/weld.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

// Every vertex of the box twice: the second copy moved by `offset`.
Mesh doubledBox(const Vec3& lo, const Vec3& hi, const Vec3& offset) {
  Mesh m = test::makeBox(lo, hi);
  const int32_t n = static_cast<int32_t>(m.vertices.size());
  for (int32_t i = 0; i < n; ++i) m.vertices.push_back(m.vertices[i] + offset);
  for (Triangle& t : m.triangles)
    if (&t - m.triangles.data() >= 6)
      for (int32_t& k : t) k += n;
  return m;
}

// Coordinates of 1e300 with a tolerance of 1e-6 (cells 1e306 from the origin).
TEST(Weld, HugeCoordinatesWithASmallTolerance) {
  const Mesh m = doubledBox(Vec3::Constant(1e300), Vec3::Constant(2e300), Vec3::Zero());
  LoadOptions lo;
  lo.weld_tolerance = 1e-6;
  const auto r = cleanMesh(m.vertices, m.triangles, lo);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->report.welded_vertices, 8);
  EXPECT_EQ(r->mesh.vertices.size(), 8u);
}

// A tolerance of 1e-300 with coordinates near 1: only exact copies are within it.
TEST(Weld, TinyToleranceMergesExactCopiesOnly) {
  const Mesh same = doubledBox(Vec3::Zero(), Vec3(1.0, 2.0, 3.0), Vec3::Zero());
  const Mesh apart = doubledBox(Vec3::Zero(), Vec3(1.0, 2.0, 3.0), Vec3(0.0, 0.0, 1e-12));
  LoadOptions lo;
  lo.weld_tolerance = 1e-300;
  const auto r = cleanMesh(same.vertices, same.triangles, lo);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->report.welded_vertices, 8);
  const auto s = cleanMesh(apart.vertices, apart.triangles, lo);
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_EQ(s->report.welded_vertices, 0);
}

// Tolerances below the resolution of the coordinates still merge what lies within them:
// vertices one ulp apart just below 1e3 (1.1e-13) merge with a tolerance of 2e-13, not with
// 5e-14.
TEST(Weld, ToleranceBelowTheCoordinateResolution) {
  std::vector<Vec3> v;
  for (int i = 0; i < 100; ++i) {
    const Vec3 p(1000.0 - i, 1000.0 + i, 1000.0);
    v.push_back(p);
    v.emplace_back(std::nextafter(p.x(), 2e3), p.y(), p.z());
  }
  std::vector<Vec3> out;
  std::vector<int32_t> remap = detail::weldVertices(v, 2e-13, &out);
  EXPECT_EQ(out.size(), 100u);
  for (size_t i = 0; i < v.size(); ++i) EXPECT_EQ(remap[i], static_cast<int32_t>(i / 2));
  remap = detail::weldVertices(v, 5e-14, &out);
  EXPECT_EQ(out.size(), 200u);
}

}  // namespace
}  // namespace sphereset

// The interior grid of the fit's samples (fit/samples.cpp) against its brute-force twin: every
// cell of the same grid classified one by one. The blocks that take their centre's containment
// must find exactly the same points, in the same order, wherever the solid sits.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "fit/samples.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"
#include "util/cell_key.hpp"

namespace sphereset::detail {
namespace {

// The grid samplePoints uses at spacing h (samples.cpp), every cell classified.
std::vector<Vec3> interiorCellByCell(const SolidIndex& index, double h) {
  const Aabb& b = index.bounds();
  const Vec3 ext = b.max - b.min;
  int64_t n[3];
  for (int k = 0; k < 3; ++k) n[k] = std::max<int64_t>(1, ceilCells(ext[k] / h));
  const Vec3 origin = b.center() - 0.5 * h * Vec3(n[0] - 1, n[1] - 1, n[2] - 1);
  std::vector<Vec3> out;
  for (int64_t k = 0; k < n[2]; ++k)
    for (int64_t j = 0; j < n[1]; ++j)
      for (int64_t i = 0; i < n[0]; ++i) {
        const Vec3 p = origin + h * Vec3(i, j, k);
        if (index.classify(p) == Containment::kInside) out.push_back(p);
      }
  return out;
}

TEST(Samples, InteriorGridFindsTheCellsOfACellByCellClassification) {
  const Mesh torus = test::makeTorus(1.0, 0.3, 48, 24);
  for (const Vec3& offset : {Vec3(0, 0, 0), Vec3(1e6, -2e6, 3e5), Vec3(0.3, 0.1, 0.2)}) {
    SCOPED_TRACE(offset.transpose());
    Mesh m = torus;
    for (Vec3& v : m.vertices) v += offset;
    const SolidIndex index(m);
    const PointSet ps = samplePoints(index, 4000, 0.5, 1);
    const std::vector<Vec3> expected = interiorCellByCell(index, ps.spacing);
    ASSERT_GT(expected.size(), 500u);
    ASSERT_EQ(ps.interior, static_cast<int64_t>(expected.size()));
    for (size_t i = 0; i < expected.size(); ++i) ASSERT_EQ(ps.points[i], expected[i]) << i;
  }
}

}  // namespace
}  // namespace sphereset::detail

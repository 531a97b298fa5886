// The accelerated point assignment (lower-bound culling, cached tables, parallel preparation,
// grids of points and centres) against a plain fill that queries every cluster exactly, and
// the point grid's nearest-point query against a scan of all points.
#include <gtest/gtest.h>

#include <deque>
#include <limits>
#include <random>
#include <tuple>

#include "fit/cluster_assign.hpp"
#include "fit/samples.hpp"
#include "test_meshes.hpp"

namespace sphereset::detail {
namespace {

// The fill of the paper (Sec. 5, "Point Assignment") without any acceleration: seeds are the
// points nearest each centre, in cluster order; points are taken breadth first; a point some
// sphere already holds goes to the nearest such centre, any other to the cluster whose
// outside volume grows least (exact query for every cluster; ties: nearest centre, then
// lower index); points no centre reaches are taken in index order.
std::vector<int32_t> plainFill(const SolidIndex& index, const PointSet& ps,
                               const std::vector<Vec3>& centres) {
  const int32_t nc = static_cast<int32_t>(centres.size());
  const int64_t np = static_cast<int64_t>(ps.points.size());
  std::vector<double> radius(nc, 0.0), sov(nc, 0.0);
  std::vector<int32_t> label(np, -1);
  std::deque<int32_t> queue;
  auto place = [&](int64_t p, int32_t c, double d, double v) {
    label[p] = c;
    if (d > radius[c]) {
      radius[c] = d;
      sov[c] = v;
    }
    for (int32_t k = ps.adj_start[p]; k < ps.adj_start[p + 1]; ++k)
      if (label[ps.adj[k]] < 0) queue.push_back(ps.adj[k]);
  };
  for (int32_t c = 0; c < nc; ++c) {
    int64_t best = 0;
    for (int64_t p = 1; p < np; ++p)
      if ((ps.points[p] - centres[c]).squaredNorm() < (ps.points[best] - centres[c]).squaredNorm())
        best = p;
    if (label[best] >= 0) continue;
    const double d = (ps.points[best] - centres[c]).norm();
    place(best, c, d, index.outsideVolume({centres[c], d}).volume);
  }
  int64_t scan = 0;
  while (true) {
    int64_t p = -1;
    while (!queue.empty() && p < 0) {
      if (label[queue.front()] < 0) p = queue.front();
      queue.pop_front();
    }
    if (p < 0) {
      while (scan < np && label[scan] >= 0) ++scan;
      if (scan == np) break;
      p = scan;
    }
    const Vec3& x = ps.points[p];
    int32_t holder = -1;
    double holder_dist = 0.0;
    for (int32_t c = 0; c < nc; ++c) {
      const double d = (x - centres[c]).norm();
      if (d <= radius[c] && (holder < 0 || d < holder_dist)) {
        holder = c;
        holder_dist = d;
      }
    }
    if (holder >= 0) {
      place(p, holder, holder_dist, sov[holder]);
      continue;
    }
    std::tuple<double, double, int32_t> best{std::numeric_limits<double>::infinity(), 0.0, -1};
    double best_sov = 0.0;
    for (int32_t c = 0; c < nc; ++c) {
      const double d = (x - centres[c]).norm();
      const double v = index.outsideVolume({centres[c], d}).volume;
      if (std::tuple{v - sov[c], d, c} < best) {
        best = {v - sov[c], d, c};
        best_sov = v;
      }
    }
    place(p, std::get<2>(best), std::get<1>(best), best_sov);
  }
  return label;
}

// Runs the accelerated assignment twice from the same centres (the second run answers from
// the tables the first one left) and compares both with the plain fill.
void expectSameLabelsAsPlainFill(int num_clusters) {
  const SolidIndex index(test::makeTorus(1.0, 0.35, 32, 16));
  const PointSet ps = samplePoints(index, 1500, 0.5, 3);
  std::vector<Cluster> clusters(num_clusters);
  std::vector<Vec3> centres;
  std::mt19937_64 rng(5);
  for (Cluster& c : clusters) {
    c.center = ps.points[rng() % ps.points.size()];
    centres.push_back(c.center);
  }
  const std::vector<int32_t> expected = plainFill(index, ps, centres);
  for (int run = 0; run < 2; ++run) {
    std::vector<int32_t> labels;
    AssignStats stats;
    assignPoints(index, ps, &clusters, &labels, &stats);
    EXPECT_EQ(labels, expected) << "run " << run;
    EXPECT_GT(stats.culled, 0);
    if (run == 1) {
      EXPECT_GT(stats.reused, 0);
    }
  }
}

TEST(Assignment, FewClustersSameLabelsAsThePlainFill) { expectSameLabelsAsPlainFill(8); }

// Enough clusters for parallel preparation and the grid of centres.
TEST(Assignment, ManyClustersSameLabelsAsThePlainFill) { expectSameLabelsAsPlainFill(96); }

TEST(PointGrid, NearestMatchesAScanOfAllPoints) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  for (int i = 0; i < 2000; ++i) pts.emplace_back(u(rng), 0.3 * u(rng), 0.1 * u(rng));
  for (int i = 0; i < 50; ++i) pts.push_back(pts[i]);  // equally near twins: lower index wins
  const PointGrid grid(pts, 0.05);
  std::vector<Vec3> queries;
  for (int i = 0; i < 500; ++i) queries.emplace_back(1.2 * u(rng), u(rng), u(rng));
  for (int i = 0; i < 50; ++i) queries.push_back(pts[i]);
  queries.emplace_back(40.0, -3.0, 7.0);  // far outside every cell
  for (const Vec3& q : queries) {
    int64_t best = 0;
    for (int64_t i = 1; i < static_cast<int64_t>(pts.size()); ++i)
      if ((pts[i] - q).squaredNorm() < (pts[best] - q).squaredNorm()) best = i;
    EXPECT_EQ(grid.nearest(pts, q), best);
  }
  EXPECT_EQ(PointGrid({}, 1.0).nearest({}, Vec3::Zero()), -1);
}

}  // namespace
}  // namespace sphereset::detail

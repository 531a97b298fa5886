// Sphere-set queries per second, sphere tree against brute force, for sets of 64 to 4096
// spheres: point distance, segment outside length (paper Sec. 7), separation distance and
// overlap test between two sets under random rigid poses.
//
//   build/bench/bench_queries [google-benchmark flags]
//
// The sets are seeded: spheres with centres in an elongated Gaussian blob and radii shrinking
// with the count, so that the union keeps about the same size (as fitted sets do). Each
// benchmark cycles through 256 seeded queries; items/s is queries per second.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <random>

#include "sphereset/query.hpp"
#include "sphereset/sphere_tree.hpp"
#include "tree/query_oracles.hpp"

namespace {

using namespace sphereset;

struct Scene {
  std::vector<Sphere> a, b;
  SphereTree ta, tb;
  std::vector<Vec3> points, seg_a, seg_b;
  std::vector<Pose> poses;
};

std::vector<Sphere> blob(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  const double r = 0.6 / std::cbrt(static_cast<double>(n));
  std::uniform_real_distribution<double> u(0.5 * r, 1.5 * r);
  std::vector<Sphere> out(n);
  for (Sphere& s : out) s = {Vec3(2.0 * g(rng), g(rng), 0.5 * g(rng)), u(rng)};
  return out;
}

const Scene& scene(int n) {
  static std::map<int, Scene> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Scene s;
  s.a = blob(n, 1);
  s.b = blob(n, 2);
  s.ta = *queryTree(s.a);
  s.tb = *queryTree(s.b);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int k = 0; k < 256; ++k) {
    s.points.emplace_back(u(rng), u(rng), u(rng));
    s.seg_a.emplace_back(u(rng), u(rng), u(rng));
    s.seg_b.emplace_back(u(rng), u(rng), u(rng));
    Pose p;
    p.rotation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    // Half of the poses keep the sets apart, half bring them into contact.
    p.translation = (k % 2 ? 7.0 : 2.0) * Vec3(g(rng), g(rng), g(rng)).normalized();
    s.poses.push_back(p);
  }
  return cache.emplace(n, std::move(s)).first->second;
}

void BM_PointDistance(benchmark::State& st, bool tree) {
  const Scene& s = scene(static_cast<int>(st.range(0)));
  size_t k = 0;
  for (auto _ : st) {
    const Vec3& p = s.points[k++ % s.points.size()];
    benchmark::DoNotOptimize(tree ? pointDistance(s.ta, p)->distance
                                  : pointDistanceBruteForce(s.a, p).distance);
  }
  st.SetItemsProcessed(st.iterations());
}

void BM_SegmentOutside(benchmark::State& st, bool tree) {
  const Scene& s = scene(static_cast<int>(st.range(0)));
  size_t k = 0;
  for (auto _ : st) {
    const size_t i = k++ % s.seg_a.size();
    benchmark::DoNotOptimize(tree ? *segmentOutsideLength(s.ta, s.seg_a[i], s.seg_b[i])
                                  : segmentOutsideLengthBruteForce(s.a, s.seg_a[i], s.seg_b[i]));
  }
  st.SetItemsProcessed(st.iterations());
}

void BM_Separation(benchmark::State& st, bool tree) {
  const Scene& s = scene(static_cast<int>(st.range(0)));
  size_t k = 0;
  for (auto _ : st) {
    const Pose& p = s.poses[k++ % s.poses.size()];
    benchmark::DoNotOptimize(tree ? separation(s.ta, Pose{}, s.tb, p)->distance
                                  : separationBruteForce(s.a, Pose{}, s.b, p).distance);
  }
  st.SetItemsProcessed(st.iterations());
}

void BM_Overlap(benchmark::State& st, bool tree) {
  const Scene& s = scene(static_cast<int>(st.range(0)));
  size_t k = 0;
  for (auto _ : st) {
    const Pose& p = s.poses[k++ % s.poses.size()];
    benchmark::DoNotOptimize(tree ? *overlaps(s.ta, Pose{}, s.tb, p)
                                  : overlapsBruteForce(s.a, Pose{}, s.b, p));
  }
  st.SetItemsProcessed(st.iterations());
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {64, 256, 1024, 4096}) b->Arg(n);
}

}  // namespace

BENCHMARK_CAPTURE(BM_PointDistance, tree, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_PointDistance, brute, false)->Apply(sizes);
BENCHMARK_CAPTURE(BM_SegmentOutside, tree, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_SegmentOutside, brute, false)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Separation, tree, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Separation, brute, false)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Overlap, tree, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Overlap, brute, false)->Apply(sizes);

BENCHMARK_MAIN();

// Animated sphere sets: precomputing the centres' mean value coordinates, and moving the
// centres for one frame (weights × deformed vertices; and linear blend skinning of the centres
// with bone weights), for 128 and 1024 spheres on a closed mesh of 10 242 vertices (an
// icosphere subdivided 5 times, stretched into an ellipsoid).
//
//   build/bench/bench_animate [google-benchmark flags]
#include <benchmark/benchmark.h>

#include <random>

#include "sphereset/animate.hpp"
#include "sphereset/export.hpp"

namespace {

using namespace sphereset;

struct Scene {
  Mesh mesh;
  std::vector<Vec3> deformed;
};

const Scene& scene() {
  static const Scene s = [] {
    Scene sc;
    sc.mesh = sphereSetMesh({{Vec3::Zero(), 1.0}}, 5)->mesh;
    for (Vec3& v : sc.mesh.vertices) v = Vec3(2.0 * v.x(), v.y(), 0.6 * v.z());
    // A twist about x, as a stand-in for any deformation (the update does not depend on it).
    for (const Vec3& v : sc.mesh.vertices) {
      const double a = 0.4 * v.x();
      sc.deformed.emplace_back(v.x(), std::cos(a) * v.y() - std::sin(a) * v.z(),
                               std::sin(a) * v.y() + std::cos(a) * v.z());
    }
    return sc;
  }();
  return s;
}

// Seeded centres inside the ellipsoid.
std::vector<Vec3> centres(int n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  std::vector<Vec3> c;
  while (static_cast<int>(c.size()) < n) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (p.squaredNorm() < 0.81) c.emplace_back(2.0 * p.x(), p.y(), 0.6 * p.z());
  }
  return c;
}

void BM_MeanValueWeights(benchmark::State& st) {
  const Scene& s = scene();
  const auto c = centres(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(meanValueWeights(s.mesh, c).value().weights.data());
  st.counters["vertices"] = static_cast<double>(s.mesh.vertices.size());
}
BENCHMARK(BM_MeanValueWeights)->Arg(128)->Arg(1024)->Unit(benchmark::kMillisecond);

void BM_MeanValueFrame(benchmark::State& st) {
  const Scene& s = scene();
  const MeanValueWeights w =
      meanValueWeights(s.mesh, centres(static_cast<int>(st.range(0)))).value();
  for (auto _ : st) benchmark::DoNotOptimize(meanValuePoints(w, s.deformed).value().data());
}
BENCHMARK(BM_MeanValueFrame)->Arg(128)->Arg(1024)->Unit(benchmark::kMicrosecond);

// Bone weighting: 2 bones blended along x; the per-frame cost is skinning the centres.
void BM_BoneFrame(benchmark::State& st) {
  const Scene& s = scene();
  SkinWeights skin;
  skin.bones = 2;
  skin.vertex_weights.resize(static_cast<Eigen::Index>(s.mesh.vertices.size()), 2);
  for (size_t i = 0; i < s.mesh.vertices.size(); ++i) {
    const double w = std::clamp(0.5 + 0.5 * s.mesh.vertices[i].x(), 0.0, 1.0);
    skin.vertex_weights(static_cast<Eigen::Index>(i), 0) = 1.0 - w;
    skin.vertex_weights(static_cast<Eigen::Index>(i), 1) = w;
  }
  const auto c = centres(static_cast<int>(st.range(0)));
  const Eigen::MatrixXd bw = pointBoneWeights(s.mesh, skin, c, 8).value();
  const std::vector<Eigen::Affine3d> bones = {
      Eigen::Affine3d::Identity(), Eigen::Affine3d(Eigen::AngleAxisd(0.5, Vec3::UnitZ()))};
  for (auto _ : st) benchmark::DoNotOptimize(skinPoints(c, bw, bones).value().data());
}
BENCHMARK(BM_BoneFrame)->Arg(128)->Arg(1024)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

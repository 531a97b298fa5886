// The incremental coverage certificate (certificate.hpp) against the full evaluation's
// certificate, on a mesh made in code (so that it runs without ../shared): an icosphere
// subdivided 6 times (81 920 triangles) stretched into an ellipsoid, with 64 spheres fitted
// once (default fit options, seed 1). Edit: one sphere's centre moved by a tenth of its radius
// and back, two edits per iteration, each a different sphere in turn. Full: evaluateSpheres
// with the same depths and only the certificates. bench/incremental_certificate.sh measures
// the same on the benchmark meshes.
//
//   build/bench/bench_certificate [google-benchmark flags]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#include "sphereset/certificate.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/export.hpp"
#include "sphereset/fit.hpp"

namespace {

using namespace sphereset;

// The centre moves by this fraction of the radius along a fixed direction, and back.
constexpr double kMoveOfRadius = 0.1;

struct Scene {
  SolidIndex index;
  std::vector<Sphere> spheres;
};

const Scene& scene() {
  static const Scene s = [] {
    Mesh mesh = sphereSetMesh({{Vec3::Zero(), 1.0}}, 6)->mesh;
    for (Vec3& v : mesh.vertices) v = Vec3(2.0 * v.x(), v.y(), 0.6 * v.z());
    SolidIndex index(mesh);
    FitOptions fo;
    fo.num_spheres = 64;
    auto fit = fitSpheres(index, fo);
    if (!fit) {
      std::fprintf(stderr, "bench_certificate: %s\n", fit.error().message.c_str());
      std::exit(1);
    }
    return Scene{std::move(index), fit->spheres};
  }();
  return s;
}

void BM_IncrementalEdit(benchmark::State& state) {
  const Scene& sc = scene();
  auto cert = makeCoverageCertificate(sc.index, sc.spheres);
  if (!cert) return state.SkipWithError(cert.error().message.c_str());
  const int n = static_cast<int>(sc.spheres.size());
  int i = 0;
  for (auto _ : state) {
    Sphere moved = sc.spheres[i];
    moved.center += kMoveOfRadius * moved.radius * Vec3(0.6, -0.48, 0.64);
    if (!cert->setSphere(i, moved).ok() || !cert->setSphere(i, sc.spheres[i]).ok())
      return state.SkipWithError("edit refused");
    benchmark::DoNotOptimize(cert->summary().max_gap);
    i = (i + 1) % n;
  }
  state.counters["edits"] = benchmark::Counter(2.0 * static_cast<double>(state.iterations()));
}
BENCHMARK(BM_IncrementalEdit)->Unit(benchmark::kMillisecond);

void BM_FullCertificate(benchmark::State& state) {
  const Scene& sc = scene();
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  for (auto _ : state) {
    auto e = evaluateSpheres(sc.index, sc.spheres, eo);
    if (!e) return state.SkipWithError(e.error().message.c_str());
    benchmark::DoNotOptimize(e->max_surface_gap);
  }
}
BENCHMARK(BM_FullCertificate)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

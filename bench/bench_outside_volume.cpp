// SOV queries per second against mesh size and sphere radius, hierarchy vs brute force.
//
//   build/bench/bench_outside_volume [--mesh-dir DIR] [google-benchmark flags]
//
// Meshes (from DIR, default ../shared/meshes beside the source tree): the 86k-triangle
// armadillo and the 871k-triangle dragon, plus spot (5.9k) for the size series. The radius
// is a fixed fraction of the bounding-box diagonal. Two sets of 64 seeded centres: "SOV"
// centres are surface samples pushed in or out by up to one radius (every query meets the
// surface, half of the centres are outside: the hardest case); "SOV_interior" centres are
// uniform interior points, the kind of sphere the fit evaluates.
#include <benchmark/benchmark.h>

#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <random>

#include "index/oracles.hpp"
#include "sphereset/load.hpp"
#include "sphereset/solid_index.hpp"

namespace {

using namespace sphereset;

struct Loaded {
  std::unique_ptr<SolidIndex> index;
  std::vector<Sphere> queries_by_radius[8];   // centred near the surface
  std::vector<Sphere> interior_by_radius[8];  // centred at interior points, as in fitting
};

std::string g_mesh_dir = std::string(SPHERESET_SOURCE_DIR) + "/../shared/meshes";
const double kRadii[] = {0.005, 0.01, 0.02, 0.05, 0.1, 0.2};

Loaded* loadOnce(const std::string& rel) {
  static std::map<std::string, std::unique_ptr<Loaded>> cache;
  auto it = cache.find(rel);
  if (it != cache.end()) return it->second.get();
  auto m = loadMesh(g_mesh_dir + "/" + rel);
  if (!m) {
    std::cerr << m.error().message << '\n';
    cache[rel] = nullptr;
    return nullptr;
  }
  auto l = std::make_unique<Loaded>();
  l->index = std::make_unique<SolidIndex>(m->mesh);
  const Mesh& mesh = m->mesh;
  const double diag = l->index->bounds().diagonal();
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (size_t ri = 0; ri < std::size(kRadii); ++ri) {
    const double r = kRadii[ri] * diag;
    for (int k = 0; k < 64; ++k) {
      const Triangle& t = mesh.triangles[static_cast<size_t>(U(rng) * mesh.triangles.size())];
      const double a = U(rng), b = U(rng) * (1 - a);
      const Vec3 p = mesh.vertices[t[0]] + a * (mesh.vertices[t[1]] - mesh.vertices[t[0]]) +
                     b * (mesh.vertices[t[2]] - mesh.vertices[t[0]]);
      const Vec3 dir = Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5).normalized();
      l->queries_by_radius[ri].push_back({p + (U(rng) * r) * dir, r});
    }
    const Aabb box = l->index->bounds();
    while (l->interior_by_radius[ri].size() < 64) {
      const Vec3 c = box.min + (box.max - box.min).cwiseProduct(Vec3(U(rng), U(rng), U(rng)));
      if (l->index->classify(c) == Containment::kInside)
        l->interior_by_radius[ri].push_back({c, r});
    }
  }
  return (cache[rel] = std::move(l)).get();
}

void runQueries(benchmark::State& state, const std::string& mesh, bool brute, bool interior) {
  Loaded* l = loadOnce(mesh);
  if (!l) {
    state.SkipWithError("mesh not found (pass --mesh-dir)");
    return;
  }
  const auto& qs =
      interior ? l->interior_by_radius[state.range(0)] : l->queries_by_radius[state.range(0)];
  size_t i = 0;
  int64_t tested = 0;
  for (auto _ : state) {
    const Sphere& s = qs[i++ % qs.size()];
    const OutsideVolume ov =
        brute ? outsideVolumeBruteForce(*l->index, s) : l->index->outsideVolume(s);
    benchmark::DoNotOptimize(ov.volume);
    tested += ov.triangles_tested;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["radius_frac"] = kRadii[state.range(0)];
  state.counters["triangles"] = static_cast<double>(l->index->mesh().triangles.size());
  state.counters["tris_tested"] =
      benchmark::Counter(static_cast<double>(tested), benchmark::Counter::kAvgIterations);
}

void registerAll() {
  const std::pair<const char*, const char*> meshes[] = {
      {"spot", "organic/spot.obj"},
      {"armadillo", "organic/armadillo_libigl.obj"},
      {"dragon", "big/dragon_vrip_bin.ply"}};
  for (const auto& [name, rel] : meshes)
    for (int interior = 0; interior < 2; ++interior)
      for (int brute = 0; brute < 2; ++brute) {
        const std::string bname =
            std::string(interior ? "SOV_interior/" : "SOV/") + name + (brute ? "/brute" : "/bvh");
        const std::string path = rel;
        auto* b = benchmark::RegisterBenchmark(bname.c_str(),
                                               [path, brute, interior](benchmark::State& s) {
                                                 runQueries(s, path, brute != 0, interior != 0);
                                               });
        for (size_t ri = 0; ri < std::size(kRadii); ++ri) b->Arg(static_cast<int>(ri));
        if (brute) b->MinTime(0.2);
      }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--mesh-dir") == 0 && i + 1 < argc) {
      g_mesh_dir = argv[++i];
      continue;
    }
    rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  registerAll();
  benchmark::Initialize(&n, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// Progressive fitting (fit.hpp, ProgressiveFit) against independent fits: for one mesh (closed,
// or with --repair made a solid as `sphereset fit` makes it, its original triangles bounded too),
// the default fit (fitPreset) at each count of COUNTS, then one progressive run through the
// same counts with the options of the largest (--only-progressive: the run alone). One CSV row
// per (method, count), with the mesh and the seed: E_r (outside volume over the solid's volume),
// the certified protrusion over the bounding-box diagonal (with --protrusion; -1 without), the
// fit's seconds and, for the progressive run, the seconds since its start (sampling included, the
// checks not); er_clustering, the clustering's E_r before the bound (the fit's outside volume of
// the spheres that enclose its sample points, FitResult::energy_before_bounding, over the
// solid's volume).
//
//   progressive_curve MESH [--counts 8,16,32,64] [--seed 1] [--quality default] [--protrusion]
//                          [--only-progressive] [--repair]
//   progressive_curve --header
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "sphereset/repair_cgal.hpp"

using namespace sphereset;

namespace {

constexpr const char* kHeader =
    "mesh,seed,method,n,er_sum,protrusion_of_diagonal,fit_s,run_s,covered,er_clustering";

int die(const std::string& m) {
  std::fprintf(stderr, "progressive_curve: %s\n", m.c_str());
  return 1;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Row {
  double er = 0.0, protrusion = -1.0;
  bool covered = false;
};

// E_r, and the protrusion and coverage of eval's certificates (protrusion only if asked).
Row judge(const SolidIndex& index, const std::vector<Sphere>& sp, double energy, double volume,
          bool protrusion, const Mesh* original) {
  Row r;
  r.er = energy / volume;
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.original = original;
  if (!protrusion) eo.protrusion_tolerance = 0.0;
  auto e = evaluateSpheres(index, sp, eo);
  if (!e) return r;
  r.covered = e->surface_covered && e->interior_covered && e->original_covered;
  if (protrusion) r.protrusion = e->protrusion / boundingBox(index.mesh()).diagonal();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--header") == 0) {
    std::puts(kHeader);
    return 0;
  }
  if (argc < 2) return die("usage: progressive_curve MESH [--counts 8,16,32,64] [--seed S]");
  const std::string path = argv[1];
  std::vector<int> counts{8, 16, 32, 64};
  uint64_t seed = 1;
  FitQuality quality = FitQuality::kDefault;
  bool protrusion = false, only_progressive = false, repair = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--protrusion" || a == "--only-progressive" || a == "--repair") {
      (a == "--protrusion" ? protrusion : a == "--repair" ? repair : only_progressive) = true;
      continue;
    }
    if (i + 1 >= argc) return die(a + " needs a value");
    const std::string v = argv[++i];
    if (a == "--counts") {
      counts.clear();
      std::stringstream ss(v);
      std::string item;
      while (std::getline(ss, item, ',')) counts.push_back(std::atoi(item.c_str()));
    } else if (a == "--seed") {
      seed = std::strtoull(v.c_str(), nullptr, 10);
    } else if (a == "--quality") {
      auto q = fitQualityFromName(v);
      if (!q) return die(q.error().message);
      quality = *q;
    } else {
      return die("unknown option " + a);
    }
  }
  RepairOptions ro;
  if (repair)
    ro.operations = cgalSolidOperations();
  else
    ro.enabled = false;
  auto solid = loadSolid(path, ro);
  if (!solid) return die(solid.error().message);
  const SolidIndex index(solid->repair.solid);
  const double volume = signedVolume(solid->repair.solid);
  const Mesh* original = solid->original();
  const std::string name = path.substr(path.find_last_of('/') + 1);
  for (int n : counts) {
    if (only_progressive) break;
    FitOptions fo = fitPreset(n, quality);
    fo.seed = seed;
    fo.original = original;
    auto f = fitSpheres(index, fo);
    if (!f) return die(name + ": " + f.error().message);
    const Row r = judge(index, f->spheres, f->energy, volume, protrusion, original);
    std::printf("%s,%llu,independent,%d,%.6g,%.6g,%.4f,%.4f,%d,%.6g\n", name.c_str(),
                static_cast<unsigned long long>(seed), n, r.er, r.protrusion, f->seconds.total,
                f->seconds.total, r.covered ? 1 : 0, f->energy_before_bounding / volume);
    std::fflush(stdout);
  }
  const auto t0 = std::chrono::steady_clock::now();
  FitOptions po = fitPreset(counts.back(), quality);
  po.seed = seed;
  po.original = original;
  double judged = 0.0;  // seconds of the checks, not the run's
  auto run = ProgressiveFit::start(index, po);
  if (!run) return die(name + ": " + run.error().message);
  for (int n : counts) {
    auto f = run->fit(n);
    if (!f) return die(name + ": " + f.error().message);
    const double run_s = secondsSince(t0) - judged;
    const auto tj = std::chrono::steady_clock::now();
    const Row r = judge(index, f->spheres, f->energy, volume, protrusion, original);
    judged += secondsSince(tj);
    std::printf("%s,%llu,progressive,%d,%.6g,%.6g,%.4f,%.4f,%d,%.6g\n", name.c_str(),
                static_cast<unsigned long long>(seed), n, r.er, r.protrusion, f->seconds.total,
                run_s, r.covered ? 1 : 0, f->energy_before_bounding / volume);
    std::fflush(stdout);
  }
  return 0;
}

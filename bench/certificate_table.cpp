// The incremental coverage certificate (certificate.hpp) against the full evaluation's
// certificate on a set under hand edits: `edits` seeded single-sphere edits (the centre moved by
// up to a quarter of the radius, the radius scaled by 0.9 to 1.1, as a drag in the view does),
// each timed through CoverageCertificate::setSphere and through evaluateSpheres with the same
// depths and only the certificates (no union samples, proximity segments or shadows). The mesh
// is loaded and repaired as `sphereset fit` does; its original triangles are certified too.
// Prints one CSV row (kHeader) and, with --per-edit FILE, appends one row per edit to FILE
// (kEditHeader). Every edit's summary is compared with the evaluation's certificate fields:
// `equal` counts the edits where all of them agree.
//
//   certificate_table MESH SPHERES [--edits 30] [--seed 1] [--per-edit FILE]
//   certificate_table --header | --edit-header
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "sphereset/certificate.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/sphere_io.hpp"
#ifdef SPHERESET_BENCH_REPAIR
#include "sphereset/repair_cgal.hpp"
#endif

using namespace sphereset;

namespace {

constexpr const char* kHeader =
    "mesh,triangles,original_triangles,spheres,edits,make_s,median_edit_ms,p90_edit_ms,"
    "max_edit_ms,median_full_ms,full_over_incremental,median_triangles_rechecked,"
    "median_cells_rechecked,cells,covered_edits,equal";
constexpr const char* kEditHeader =
    "mesh,edit,sphere,incremental_ms,full_ms,triangles_rechecked,original_triangles_rechecked,"
    "cells_rechecked,covered";

// Edit sizes: the centre moves by up to this fraction of the radius in each coordinate, the
// radius is scaled by a factor within 1 ± kRadiusScale.
constexpr double kMoveOfRadius = 0.25;
constexpr double kRadiusScale = 0.1;

int die(const std::string& m) {
  std::fprintf(stderr, "certificate_table: %s\n", m.c_str());
  return 1;
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

// Whether the certificate's summary holds the evaluation's certificate fields.
bool sameAsFull(const CertificateSummary& s, const EvalResult& e) {
  return s.er_sum == e.er_sum && s.outside_volume == e.outside_volume &&
         s.surface_covered == e.surface_covered && s.max_surface_gap == e.max_surface_gap &&
         static_cast<int64_t>(s.uncovered_triangles.size()) == e.uncovered_triangles &&
         s.original_covered == e.original_covered && s.max_original_gap == e.max_original_gap &&
         static_cast<int64_t>(s.original_uncovered_triangles.size()) ==
             e.original_uncovered_triangles &&
         s.interior_covered == e.interior_covered && s.max_interior_gap == e.max_interior_gap &&
         s.interior_uncertified_cells == e.interior_uncertified_cells;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--header") == 0) return std::puts(kHeader) < 0;
  if (argc == 2 && std::strcmp(argv[1], "--edit-header") == 0) return std::puts(kEditHeader) < 0;
  if (argc < 3) return die("usage: certificate_table MESH SPHERES [--edits N] [--seed S]");
  const std::string mesh_path = argv[1], spheres_path = argv[2];
  int edits = 30;
  uint64_t seed = 1;
  std::string per_edit;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--edits") edits = std::max(1, std::atoi(argv[i + 1]));
    if (flag == "--seed") seed = std::strtoull(argv[i + 1], nullptr, 10);
    if (flag == "--per-edit") per_edit = argv[i + 1];
  }
  RepairOptions ro;
#ifdef SPHERESET_BENCH_REPAIR
  ro.operations = cgalSolidOperations();
#endif
  auto m = loadSolid(mesh_path, ro);
  if (!m) return die(m.error().message);
  auto spheres = readSpheres(spheres_path);
  if (!spheres) return die(spheres.error().message);
  const SolidIndex index(m->repair.solid);
  CertificateOptions co;
  co.original = m->original();
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.surface_max_depth = co.surface_max_depth;
  eo.interior_max_depth = co.interior_max_depth;
  eo.original = co.original;

  auto t0 = std::chrono::steady_clock::now();
  auto made = makeCoverageCertificate(index, *spheres, co);
  if (!made) return die(made.error().message);
  const double make_s = seconds(t0);
  CoverageCertificate& cert = *made;

  FILE* edit_rows = per_edit.empty() ? nullptr : std::fopen(per_edit.c_str(), "a");
  if (!per_edit.empty() && !edit_rows) return die("cannot write " + per_edit);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> inc_ms, full_ms, tri, cells;
  int equal = 0, covered = 0;
  for (int e = 0; e < edits; ++e) {
    const int i = static_cast<int>(rng() % cert.spheres().size());
    Sphere s = cert.spheres()[i];
    s.center += kMoveOfRadius * s.radius * Vec3(u(rng), u(rng), u(rng));
    s.radius *= 1.0 + kRadiusScale * u(rng);
    t0 = std::chrono::steady_clock::now();
    if (Status st = cert.setSphere(i, s); !st) return die(st.error().message);
    inc_ms.push_back(1e3 * seconds(t0));
    t0 = std::chrono::steady_clock::now();
    auto full = evaluateSpheres(index, cert.spheres(), eo);
    if (!full) return die(full.error().message);
    full_ms.push_back(1e3 * seconds(t0));
    const CertificateSummary& sum = cert.summary();
    tri.push_back(static_cast<double>(sum.triangles_rechecked));
    cells.push_back(static_cast<double>(sum.cells_rechecked));
    equal += sameAsFull(sum, *full) ? 1 : 0;
    covered += sum.covered ? 1 : 0;
    if (edit_rows)
      std::fprintf(edit_rows, "%s,%d,%d,%.3f,%.3f,%lld,%lld,%lld,%d\n", mesh_path.c_str(), e, i,
                   inc_ms.back(), full_ms.back(), static_cast<long long>(sum.triangles_rechecked),
                   static_cast<long long>(sum.original_triangles_rechecked),
                   static_cast<long long>(sum.cells_rechecked), sum.covered ? 1 : 0);
  }
  if (edit_rows) std::fclose(edit_rows);
  const CertificateSummary& sum = cert.summary();
  const double med_inc = quantile(inc_ms, 0.5), med_full = quantile(full_ms, 0.5);
  std::printf("%s,%lld,%lld,%zu,%d,%.3f,%.2f,%.2f,%.2f,%.1f,%.1f,%.0f,%.0f,%lld,%d,%d\n",
              mesh_path.c_str(), static_cast<long long>(sum.triangles),
              static_cast<long long>(sum.original_triangles), cert.spheres().size(), edits, make_s,
              med_inc, quantile(inc_ms, 0.9), quantile(inc_ms, 1.0), med_full, med_full / med_inc,
              quantile(tri, 0.5), quantile(cells, 0.5), static_cast<long long>(sum.cells), covered,
              equal);
  return equal == edits ? 0 : 1;
}

// Shared pieces of the sphereset subcommands: error mapping, mesh loading, fit options, the
// coverage check of a result.
#include "cli_common.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <tuple>

namespace sphereset::cli {

namespace {

// Relative weld tolerance tried when an exactly welded mesh is open: files that store each
// triangle's corners separately in float (STL, some DAE exports) often differ in the last bits.
constexpr double kSuggestedWeldRel = 1e-7;

}  // namespace

int exitFor(const Error& e) {
  switch (e.code) {
    case ErrorCode::kInvalidArgument:
      return kUsage;
    case ErrorCode::kUnreadable:
      return kUnreadable;
    case ErrorCode::kInvalidData:
      return kInvalid;
    case ErrorCode::kNotSolid:
      return kNotSolid;
    case ErrorCode::kWriteFailed:
      return kWrite;
  }
  return kInternal;
}

int fail(const Error& e) {
  std::cerr << "sphereset: " << e.message << '\n';
  return exitFor(e);
}

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

void addMeshArgs(CLI::App* cmd, MeshArgs* a) {
  cmd->add_option("mesh", a->path, "Mesh file (OBJ, PLY, STL, OFF, DAE, glTF/GLB, ...)")
      ->required();
  cmd->add_option("--weld-tolerance", a->weld,
                  "Merge vertices closer than this distance (default 0: exact duplicates only)")
      ->check(CLI::NonNegativeNumber);
}

std::string weldHint(const MeshArgs& a, const MeshDiagnosis& d) {
  if (a.weld > 0.0 || d.boundary_edges == 0) return {};
  LoadOptions lo;
  lo.weld_tolerance = kSuggestedWeldRel * d.bbox.diagonal();
  auto m = loadMesh(a.path, lo);
  if (!m || !diagnoseMesh(m->mesh).isSolid()) return {};
  char buf[64];
  std::snprintf(buf, sizeof buf, "--weld-tolerance %.2g", lo.weld_tolerance);
  return buf;
}

Expected<LoadedMesh> loadSolid(const MeshArgs& a) {
  LoadOptions lo;
  lo.weld_tolerance = a.weld;
  auto m = loadMesh(a.path, lo);
  if (!m) return m.error();
  const MeshDiagnosis d = diagnoseMesh(m->mesh);
  if (!d.isSolid()) {
    Error e = notSolidError(a.path, d);
    const std::string hint = weldHint(a, d);
    if (!hint.empty()) e.message += " (it closes with " + hint + ")";
    return e;
  }
  return m;
}

void addFitArgs(CLI::App* cmd, FitArgs* a, bool count_option) {
  addMeshArgs(cmd, &a->mesh);
  if (count_option)
    cmd->add_option("-n,--spheres", a->fit.num_spheres, "Number of spheres")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
  cmd->add_option("-o,--output", a->out_path,
                  count_option ? "Output file; the format follows the extension: .txt (x y z r), "
                                 ".json, .sph, .yaml (cuRobo collision_spheres)"
                               : "Output file: .sph (Bradshaw's layout) or .json (nodes with "
                                 "parent and children)")
      ->required();
  cmd->add_option("--seed", a->fit.seed, "Seed for sampling and initialisation")
      ->capture_default_str();
  cmd->add_option("--points", a->points,
                  "Points to cluster (default 0: max(5000, 100 n), scaled by --quality)")
      ->check(CLI::Range(int64_t{0}, int64_t{100000000}));
  cmd->add_option("--iterations", a->fit.max_iterations,
                  "Cap on assignment/update rounds (default 100; --quality fast: 30)")
      ->check(CLI::Range(0, 100000));
  cmd->add_option("--padding", a->fit.padding, "Distance added to every radius")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--quality", a->quality,
                  "fast, default or best (points, rounds, optimiser effort)")
      ->capture_default_str()
      ->check(CLI::IsMember({"fast", "default", "best"}));
  cmd->add_option("--restarts", a->fit.restarts,
                  "Independent fits from derived seeds, best kept (default 1; --quality best: 4)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--decimation", a->fit.decimation,
                  "Extra spheres to start with, as a fraction of N, removed cheapest first "
                  "(default 0; --quality best: 0.5)")
      ->check(CLI::Range(0.0, 16.0));
  cmd->add_option("--optimizer", a->optimizer,
                  "Sphere update: powell (derivative-free BOBYQA) or gradient (MMA with exact "
                  "derivatives)")
      ->capture_default_str()
      ->check(CLI::IsMember({"powell", "gradient"}));
  cmd->add_option("--init", a->init, "Seeding: fps (farthest point) or random (as in the paper)")
      ->capture_default_str()
      ->check(CLI::IsMember({"fps", "random"}));
  cmd->add_option("--method", a->method,
                  "variational (the paper's), or the baselines kmeans (L2 Lloyd clusters) and "
                  "octree (occupied octree leaves); all end with the same guaranteed bound")
      ->capture_default_str()
      ->check(CLI::IsMember({"variational", "kmeans", "octree"}));
  cmd->add_flag("-q,--quiet", a->quiet, "No progress on stderr");
}

FitOptions fitOptions(const FitArgs& a, const CLI::App* cmd) {
  FitOptions fo = a.fit;
  // Quality presets: (points factor, rounds, optimiser evaluations per sphere, failed
  // teleports before stopping, restarts, decimation).
  const std::map<std::string, std::tuple<double, int, int, int, int, double>> presets = {
      {"fast", {0.4, 30, 30, 2, 1, 0.0}},
      {"default", {1.0, 100, 60, 6, 1, 0.0}},
      {"best", {1.0, 100, 60, 6, 4, 0.5}}};
  const auto [pf, rounds, evals, failed, restarts, decimation] = presets.at(a.quality);
  if (cmd->count("--iterations") == 0) fo.max_iterations = rounds;
  if (cmd->count("--restarts") == 0) fo.restarts = restarts;
  if (cmd->count("--decimation") == 0) fo.decimation = decimation;
  fo.optimizer_evaluations = evals;
  fo.max_failed_teleports = failed;
  fo.target_points = a.points > 0
                         ? a.points
                         : static_cast<int64_t>(pf * std::max<int64_t>(5000, 100 * fo.num_spheres));
  fo.optimizer = a.optimizer == "gradient" ? SphereOptimizer::kGradient : SphereOptimizer::kPowell;
  fo.init = a.init == "random" ? FitInit::kRandom : FitInit::kFarthestPoint;
  fo.method = a.method == "kmeans"   ? FitMethod::kKMeans
              : a.method == "octree" ? FitMethod::kOctree
                                     : FitMethod::kVariational;
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (!a.quiet)
    fo.progress = [tty](const FitProgress& p) {
      if (tty)
        std::fprintf(stderr, "\r%-10s round %3d  outside volume %.6g  spheres %d  %.1f s   ",
                     p.phase.c_str(), p.iteration, p.energy, p.spheres, p.seconds);
      else
        std::fprintf(stderr, "%s round %d outside volume %.6g spheres %d %.1f s\n", p.phase.c_str(),
                     p.iteration, p.energy, p.spheres, p.seconds);
      if (tty && p.phase == "done") std::fprintf(stderr, "\n");
    };
  return fo;
}

std::string coverageGaps(const EvalResult& r) {
  char buf[160];
  std::string gaps;
  if (!r.surface_covered) {
    std::snprintf(buf, sizeof buf,
                  "surface not covered (max gap %.3g of the diagonal, %lld triangles not covered)",
                  r.max_surface_gap, static_cast<long long>(r.uncovered_triangles));
    gaps = buf;
  }
  // The interior counts as uncovered whenever the surface is; report it when it has a gap of its
  // own.
  if (!r.interior_covered && (r.surface_covered || r.max_interior_gap > 0.0)) {
    std::snprintf(buf, sizeof buf, "interior not covered (max gap %.3g of the diagonal)",
                  r.max_interior_gap);
    gaps += (gaps.empty() ? "" : ", ") + std::string(buf);
  }
  return gaps;
}

int coverageExit(const std::string& mesh, const std::string& what, const std::string& out,
                 const EvalResult& r, std::ostream& err) {
  const std::string gaps = coverageGaps(r);
  if (gaps.empty()) return kOk;
  err << "sphereset: " << mesh << ": " << what << " failed the coverage check: " << gaps
      << " (written to " << out << " anyway)\n";
  return kUncovered;
}

}  // namespace sphereset::cli

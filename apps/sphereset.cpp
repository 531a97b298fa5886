// sphereset: command-line front end. Library errors become one line on stderr and an exit
// code (see --help and the README):
//   0 success, 1 internal error, 2 bad options, 3 unreadable input, 4 invalid data,
//   5 the mesh is not a closed solid, 6 the output could not be written.
#include <tbb/global_control.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "sphereset/evaluate.hpp"
#include "sphereset/export.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/query.hpp"
#include "sphereset/render.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/tree.hpp"

namespace {

using namespace sphereset;

enum Exit {
  kOk = 0,
  kInternal = 1,
  kUsage = 2,
  kUnreadable = 3,
  kInvalid = 4,
  kNotSolid = 5,
  kWrite = 6
};

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

nlohmann::json checkJson(const LoadedMesh& m, const MeshDiagnosis& d) {
  const LoadReport& r = m.report;
  return {{"file", r.path},
          {"format", r.format},
          {"vertices", d.vertices},
          {"triangles", d.triangles},
          {"edges", d.edges},
          {"closed", d.closed},
          {"manifold", d.manifold},
          {"oriented", d.oriented},
          {"solid", d.isSolid()},
          {"components", d.components},
          {"boundary_edges", d.boundary_edges},
          {"nonmanifold_edges", d.nonmanifold_edges},
          {"nonmanifold_vertices", d.nonmanifold_vertices},
          {"misoriented_edges", d.misoriented_edges},
          {"volume", d.volume},
          {"area", d.area},
          {"bbox_min", vec(d.bbox.min)},
          {"bbox_max", vec(d.bbox.max)},
          {"bbox_diagonal", d.bbox.diagonal()},
          {"min_edge", d.min_edge},
          {"max_edge", d.max_edge},
          {"load",
           {{"scene_meshes", r.scene_meshes},
            {"file_vertices", r.file_vertices},
            {"file_triangles", r.file_faces},
            {"welded_vertices", r.welded_vertices},
            {"unused_vertices", r.unused_vertices},
            {"degenerate_dropped", r.degenerate_dropped},
            {"duplicate_dropped", r.duplicate_dropped},
            {"flipped", r.flipped}}}};
}

void printCheck(const LoadedMesh& m, const MeshDiagnosis& d) {
  const LoadReport& r = m.report;
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::printf("%s (%s, %lld scene mesh%s)\n", r.path.c_str(), r.format.c_str(),
              static_cast<long long>(r.scene_meshes), r.scene_meshes == 1 ? "" : "es");
  std::printf("  loaded      %lld vertices, %lld triangles in the file\n",
              static_cast<long long>(r.file_vertices), static_cast<long long>(r.file_faces));
  std::printf(
      "  clean-up    %lld vertices welded, %lld unused removed, %lld degenerate and %lld "
      "duplicate triangles dropped%s\n",
      static_cast<long long>(r.welded_vertices), static_cast<long long>(r.unused_vertices),
      static_cast<long long>(r.degenerate_dropped), static_cast<long long>(r.duplicate_dropped),
      r.flipped ? ", orientation flipped outward" : "");
  std::printf("  mesh        %lld vertices, %lld triangles, %lld edges, %lld component%s\n",
              static_cast<long long>(d.vertices), static_cast<long long>(d.triangles),
              static_cast<long long>(d.edges), static_cast<long long>(d.components),
              d.components == 1 ? "" : "s");
  std::printf("  closed      %s (%lld boundary edges)\n", yes(d.closed),
              static_cast<long long>(d.boundary_edges));
  std::printf("  manifold    %s (%lld non-manifold edges, %lld non-manifold vertices)\n",
              yes(d.manifold), static_cast<long long>(d.nonmanifold_edges),
              static_cast<long long>(d.nonmanifold_vertices));
  std::printf("  oriented    %s (%lld inconsistent edges)\n", yes(d.oriented),
              static_cast<long long>(d.misoriented_edges));
  std::printf("  volume      %.9g\n  area        %.9g\n", d.volume, d.area);
  std::printf("  bbox        [%.6g %.6g %.6g] .. [%.6g %.6g %.6g], diagonal %.6g\n", d.bbox.min.x(),
              d.bbox.min.y(), d.bbox.min.z(), d.bbox.max.x(), d.bbox.max.y(), d.bbox.max.z(),
              d.bbox.diagonal());
  std::printf("  edges       %.6g .. %.6g\n", d.min_edge, d.max_edge);
  std::printf("  solid       %s\n",
              d.isSolid() ? "yes: ready for fitting" : "no: fitting needs a closed manifold solid");
}

struct MeshArgs {
  std::string path;
  double weld = 0.0;
};

void addMeshArgs(CLI::App* cmd, MeshArgs* a) {
  cmd->add_option("mesh", a->path, "Mesh file (OBJ, PLY, STL, OFF, DAE, glTF/GLB, ...)")
      ->required();
  cmd->add_option("--weld-tolerance", a->weld,
                  "Merge vertices closer than this distance (default 0: exact duplicates only)")
      ->check(CLI::NonNegativeNumber);
}

// Relative weld tolerance tried when an exactly welded mesh is open: files that store each
// triangle's corners separately in float (STL, some DAE exports) often differ in the last bits.
constexpr double kSuggestedWeldRel = 1e-7;

// If the mesh is open and welding within kSuggestedWeldRel of the diagonal makes it a solid,
// the option to pass; empty otherwise.
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

// Loads and requires a closed solid.
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

// Fit options shared by `fit` and `tree`.
struct FitArgs {
  MeshArgs mesh;
  FitOptions fit;
  std::string out_path, link_name, quality = "default", optimizer = "powell", init = "fps",
                                   method = "variational";
  bool quiet = false;
  int64_t points = 0;
};

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

// Turns the parsed options into FitOptions: quality presets, optimiser, seeding, progress.
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

nlohmann::json evalJson(const EvalResult& r, size_t count) {
  return {{"spheres", count},
          {"mesh_volume", r.mesh_volume},
          {"bbox_diagonal", r.bbox_diagonal},
          {"er_sum", r.er_sum},
          {"er_union", r.er_union},
          {"er_union_stderr", r.er_union_stderr},
          {"surface_covered", r.surface_covered},
          {"max_surface_gap", r.max_surface_gap},
          {"uncovered_triangles", r.uncovered_triangles},
          {"surface_uncertified_area", r.surface_uncertified_area},
          {"interior_covered", r.interior_covered},
          {"max_interior_gap", r.max_interior_gap},
          {"proximity_error", r.proximity_error},
          {"shadow_error_sky", r.shadow_error_sky},
          {"shadow_error_lights", r.shadow_error_lights},
          {"seconds", r.seconds}};
}

void printEval(const EvalResult& r, const EvalOptions& eo) {
  std::printf("  E_r summed       %.6f   (exact: sum of outside volumes / mesh volume)\n",
              r.er_sum);
  std::printf("  E_r union        %.6f +- %.6f (Monte Carlo, %lld samples)\n", r.er_union,
              r.er_union_stderr, static_cast<long long>(eo.union_samples));
  std::printf("  surface covered  %s (max gap %.3g of the diagonal, %lld triangles not covered)\n",
              r.surface_covered ? "yes" : "no", r.max_surface_gap,
              static_cast<long long>(r.uncovered_triangles));
  std::printf("  interior covered %s (max gap %.3g of the diagonal)\n",
              r.interior_covered ? "yes" : "no", r.max_interior_gap);
  std::printf("  proximity error  %.6f of the diagonal (%d segments)\n", r.proximity_error,
              eo.proximity_segments);
  if (eo.shadow_resolution > 0)
    std::printf(
        "  shadow error     %.6f sky light, %.6f per light (RMS irradiance, %d² pixels, "
        "%d lights)\n",
        r.shadow_error_sky, r.shadow_error_lights, eo.shadow_resolution, eo.shadow_lights);
  std::printf("  time             %.2f s\n", r.seconds);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sphereset: tight bounding sphere sets for solid triangle meshes"};
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 internal error, 2 bad options, 3 unreadable input,\n"
      "4 invalid data, 5 mesh is not a closed solid, 6 output could not be written.");
  int threads = 0;
  app.add_option("--threads", threads, "Worker threads (default 0: all cores)")
      ->check(CLI::Range(0, 4096));

  bool json = false;
  MeshArgs check_args;
  CLI::App* check = app.add_subcommand("check", "Load a mesh and diagnose it as a solid");
  addMeshArgs(check, &check_args);
  check->add_flag("--json", json, "Print one JSON object");

  MeshArgs eval_args;
  std::string spheres_path;
  EvalOptions eo;
  CLI::App* eval = app.add_subcommand("eval", "Measure how tightly a sphere set bounds a mesh");
  addMeshArgs(eval, &eval_args);
  eval->add_option("spheres", spheres_path, "Sphere set (.txt, .json, .sph, .yaml)")->required();
  eval->add_flag("--json", json, "Print one JSON object");
  eval->add_option("--seed", eo.seed, "Seed for all sampling")->capture_default_str();
  eval->add_option("--samples", eo.union_samples, "Monte Carlo samples for the union's E_r")
      ->capture_default_str()
      ->check(CLI::Range(int64_t{0}, int64_t{1} << 34));
  eval->add_option("--segments", eo.proximity_segments, "Segments for the proximity error")
      ->capture_default_str()
      ->check(CLI::Range(0, 10000000));
  std::string up = "y";
  eval->add_option("--up", up, "Up axis for the ground plane of the shadow comparison")
      ->capture_default_str()
      ->check(CLI::IsMember({"x", "y", "z"}));
  eval->add_option("--shadow-resolution", eo.shadow_resolution,
                   "Ground-plane pixels per side for the shadow errors (0 skips them)")
      ->capture_default_str()
      ->check(CLI::Range(0, 4096));
  eval->add_option("--shadow-lights", eo.shadow_lights,
                   "Directional lights over the upper hemisphere for the shadow errors")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));

  FitArgs fit_args;
  CLI::App* fit = app.add_subcommand("fit", "Fit N spheres that bound the mesh");
  addFitArgs(fit, &fit_args, true);
  fit->add_option("--name", fit_args.link_name,
                  "Link name for .yaml output (default: the mesh's stem)");
  fit->add_flag("--json", json, "Print the summary as one JSON object on stdout");

  FitArgs tree_args;
  tree_args.fit.num_spheres = 0;  // B^D unless -n is given
  TreeOptions to;
  std::string parents = "minimal";
  CLI::App* tree = app.add_subcommand(
      "tree", "Fit a sphere set and build a sphere-tree over it (Bradshaw .sph or JSON)");
  addFitArgs(tree, &tree_args, false);
  tree->add_option("--branch", to.branching, "Children per node at most (B)")
      ->capture_default_str()
      ->check(CLI::Range(2, 1024));
  tree->add_option("--depth", to.depth,
                   "Levels below the root (D): D + 1 levels, at most B^D leaves")
      ->capture_default_str()
      ->check(CLI::Range(1, 26));
  tree->add_option("-n,--spheres", tree_args.fit.num_spheres, "Leaves to fit (default 0: B^D)")
      ->check(CLI::Range(0, 1000000));
  tree->add_option("--parents", parents,
                   "minimal (smallest ball enclosing the children) or outside (least outside "
                   "volume while enclosing them)")
      ->capture_default_str()
      ->check(CLI::IsMember({"minimal", "outside"}));
  tree->add_flag("--json", json, "Print the summary as one JSON object on stdout");

  MeshArgs render_args;
  std::string render_spheres, render_out,
      render_size = "1200x900", render_views = "front,side,top,three-quarter", render_up = "y";
  RenderOptions ro;
  CLI::App* render = app.add_subcommand(
      "render", "Draw the mesh with the spheres over it, from several views, to a PNG");
  render->add_option("mesh", render_args.path, "Mesh file")->required();
  render->add_option("--weld-tolerance", render_args.weld,
                     "Merge vertices closer than this (absolute units)");
  render->add_option("spheres", render_spheres, "Sphere set or tree (its leaves are drawn)");
  render->add_option("-o,--output", render_out, "PNG file")->required();
  render->add_option("--size", render_size, "Image size WxH")->capture_default_str();
  render
      ->add_option("--views", render_views,
                   "Up to four of front, side, top, three-quarter, comma-separated")
      ->capture_default_str();
  render->add_option("--up", render_up, "Up axis")
      ->capture_default_str()
      ->check(CLI::IsMember({"x", "y", "z"}));
  render->add_option("--opacity", ro.sphere_opacity, "Opacity of each sphere surface")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  bool no_ground = false;
  render->add_flag("--no-ground", no_ground, "No ground plane");

  std::string export_in, export_out;
  int export_subdiv = 2;
  CLI::App* exp = app.add_subcommand(
      "export",
      "Write a sphere set as a triangle mesh (.ply, .obj, .gltf, .glb), one colour "
      "per sphere");
  exp->add_option("spheres", export_in, "Sphere set or tree (its leaves are written)")->required();
  exp->add_option("-o,--output", export_out, "Mesh file: .ply, .obj, .gltf or .glb")->required();
  exp->add_option("--subdivisions", export_subdiv,
                  "Icosahedron subdivisions per sphere (20·4^s triangles)")
      ->capture_default_str()
      ->check(CLI::Range(0, 6));

  std::string query_path, other_path;
  std::vector<double> q_points, q_segments, other_pose;
  CLI::App* query =
      app.add_subcommand("query", "Point, segment and set-to-set queries on a sphere set or tree");
  query->add_option("spheres", query_path, "Sphere set or tree (.txt, .json, .sph, .yaml)")
      ->required();
  query->add_option("--point", q_points, "x,y,z: inside? and signed distance to the set")
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  query
      ->add_option("--segment", q_segments,
                   "ax,ay,az,bx,by,bz: length of the segment outside the spheres")
      ->delimiter(',')
      ->expected(6)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  query->add_option("--other", other_path, "A second set or tree: separation and overlap");
  query
      ->add_option("--pose", other_pose,
                   "tx,ty,tz,qw,qx,qy,qz: rigid pose of the second set (default identity)")
      ->delimiter(',')
      ->expected(7);
  query->add_flag("--json", json, "Print one JSON object");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "sphereset: " << e.what() << " (see sphereset --help)\n";
    return kUsage;
  }
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  threads);

  try {
    if (*fit) {
      auto format = sphereFormatFromPath(fit_args.out_path);
      if (!format) return fail(format.error());
      auto m = loadSolid(fit_args.mesh);
      if (!m) return fail(m.error());
      FitOptions fo = fitOptions(fit_args, fit);
      const SolidIndex index(m->mesh);
      auto r = fitSpheres(index, fo);
      if (!r) return fail(Error{r.error().code, fit_args.mesh.path + ": " + r.error().message});
      SphereFileMeta meta;
      meta.name = fit_args.link_name.empty()
                      ? std::filesystem::path(fit_args.mesh.path).stem().string()
                      : fit_args.link_name;
      meta.source_mesh = fit_args.mesh.path;
      Status st = writeSpheres(fit_args.out_path, r->spheres, meta);
      if (!st) return fail(st.error());
      EvalOptions eo2;
      eo2.seed = fo.seed;
      eo2.union_samples = 100000;
      eo2.proximity_segments = 0;
      const EvalResult ev = evaluateSpheres(index, r->spheres, eo2);
      if (json) {
        nlohmann::json j = {{"mesh", fit_args.mesh.path},
                            {"output", fit_args.out_path},
                            {"spheres", r->spheres.size()},
                            {"er_sum", r->energy / ev.mesh_volume},
                            {"er_sum_before_bounding", r->energy_before_bounding / ev.mesh_volume},
                            {"er_union", ev.er_union},
                            {"er_union_stderr", ev.er_union_stderr},
                            {"surface_covered", ev.surface_covered},
                            {"interior_covered", ev.interior_covered},
                            {"points", r->points},
                            {"interior_points", r->interior_points},
                            {"rounds", r->iterations},
                            {"converged", r->converged},
                            {"teleports", r->teleports},
                            {"teleports_kept", r->teleports_accepted},
                            {"sov_queries", r->sov_queries},
                            {"sov_queries_culled", r->sov_queries_culled},
                            {"optimizer_queries", r->optimizer_queries},
                            {"bounding_enlarged", r->bounding_enlarged},
                            {"bounding_pieces", r->bounding_pieces},
                            {"bounding_queries", r->bounding_queries},
                            {"bounding_interior_cells", r->bounding_interior_cells},
                            {"shrink_passes", r->shrink_passes},
                            {"idle_teleports", r->idle_teleports},
                            {"decimated", r->decimated},
                            {"restart", r->restart},
                            {"seconds",
                             {{"total", r->seconds.total},
                              {"sampling", r->seconds.sampling},
                              {"assignment", r->seconds.assignment},
                              {"update", r->seconds.update},
                              {"teleport", r->seconds.teleport},
                              {"bounding", r->seconds.bounding}}},
                            {"seed", fo.seed}};
        std::cout << j.dump() << '\n';
      }
      if (!fit_args.quiet) {
        std::fprintf(stderr,
                     "%s: %zu spheres -> %s\n"
                     "  E_r summed %.4f (%.4f before bounding), E_r union %.4f +- %.4f\n"
                     "  surface covered %s, interior covered %s\n"
                     "  %lld points (%lld interior), %d rounds%s, %d teleports (%d kept), %lld SOV "
                     "queries in assignment (%lld culled)\n"
                     "  time %.2f s (sampling %.2f, assignment %.2f, update %.2f, teleport %.2f, "
                     "bounding %.2f)\n",
                     fit_args.mesh.path.c_str(), r->spheres.size(), fit_args.out_path.c_str(),
                     r->energy / ev.mesh_volume, r->energy_before_bounding / ev.mesh_volume,
                     ev.er_union, ev.er_union_stderr, ev.surface_covered ? "yes" : "NO",
                     ev.interior_covered ? "yes" : "NO", static_cast<long long>(r->points),
                     static_cast<long long>(r->interior_points), r->iterations,
                     r->converged ? " (converged)" : "", r->teleports, r->teleports_accepted,
                     static_cast<long long>(r->sov_queries),
                     static_cast<long long>(r->sov_queries_culled), r->seconds.total,
                     r->seconds.sampling, r->seconds.assignment, r->seconds.update,
                     r->seconds.teleport, r->seconds.bounding);
      }
      return kOk;
    }
    if (*check) {
      LoadOptions lo;
      lo.weld_tolerance = check_args.weld;
      auto m = loadMesh(check_args.path, lo);
      if (!m) return fail(m.error());
      const MeshDiagnosis d = diagnoseMesh(m->mesh);
      const std::string hint = d.isSolid() ? std::string() : weldHint(check_args, d);
      if (json) {
        nlohmann::json j = checkJson(*m, d);
        if (!hint.empty()) j["hint"] = "closes with " + hint;
        std::cout << j.dump() << '\n';
      } else {
        printCheck(*m, d);
        if (!hint.empty()) std::printf("  hint        the mesh closes with %s\n", hint.c_str());
      }
      return d.isSolid() ? kOk : kNotSolid;
    }
    if (*eval) {
      eo.up_axis = up[0] - 'x';
      auto m = loadSolid(eval_args);
      if (!m) return fail(m.error());
      // A tree file gets one report per level (root first); a plain set one report.
      auto tree_in = readSphereTree(spheres_path);
      if (!tree_in) return fail(tree_in.error());
      // Plain sets read as two-level trees; a JSON tree file does not read as a plain set.
      const bool is_tree = tree_in->depth >= 2 || !readSpheres(spheres_path).ok();
      const SolidIndex index(m->mesh);
      nlohmann::json levels = nlohmann::json::array();
      const int first = is_tree ? 0 : tree_in->depth;
      for (int l = first; l <= tree_in->depth; ++l) {
        const std::vector<Sphere> spheres = tree_in->level(l);
        if (spheres.empty())
          return fail(Error{ErrorCode::kInvalidData, spheres_path + ": no spheres"});
        const EvalResult r = evaluateSpheres(index, spheres, eo);
        if (json) {
          nlohmann::json j = evalJson(r, spheres.size());
          if (is_tree) j["level"] = l;
          levels.push_back(j);
        } else {
          if (is_tree)
            std::printf("%s, level %d of %s: %zu spheres\n", eval_args.path.c_str(), l,
                        spheres_path.c_str(), spheres.size());
          else
            std::printf("%s with %zu spheres from %s\n", eval_args.path.c_str(), spheres.size(),
                        spheres_path.c_str());
          printEval(r, eo);
        }
      }
      if (json) {
        nlohmann::json j = is_tree ? nlohmann::json{{"levels", levels}} : levels[0];
        j["mesh"] = eval_args.path;
        j["spheres_file"] = spheres_path;
        j["seed"] = eo.seed;
        std::cout << j.dump() << '\n';
      }
      return kOk;
    }
    if (*tree) {
      auto format = sphereFormatFromPath(tree_args.out_path);
      if (!format) return fail(format.error());
      if (*format != SphereFormat::kSph && *format != SphereFormat::kJson)
        return fail(Error{ErrorCode::kInvalidArgument,
                          tree_args.out_path + ": a sphere tree is written as .sph or .json"});
      auto m = loadSolid(tree_args.mesh);
      if (!m) return fail(m.error());
      if (tree_args.fit.num_spheres == 0) {
        // B^D leaves, when that is a sensible count (otherwise the library says why not).
        int64_t leaves = 1;
        for (int l = 0; l < to.depth && leaves <= (int64_t{1} << 16); ++l) leaves *= to.branching;
        if (leaves <= (int64_t{1} << 16)) tree_args.fit.num_spheres = static_cast<int>(leaves);
      }
      FitOptions fo = fitOptions(tree_args, tree);
      to.parents = parents == "outside" ? TreeParents::kOutsideVolume : TreeParents::kMinimal;
      to.seed = fo.seed;
      const SolidIndex index(m->mesh);
      auto r = fitSphereTree(index, fo, to);
      if (!r) return fail(Error{r.error().code, tree_args.mesh.path + ": " + r.error().message});
      SphereFileMeta meta;
      meta.source_mesh = tree_args.mesh.path;
      Status st = writeSphereTree(tree_args.out_path, r->tree.tree, meta);
      if (!st) return fail(st.error());
      const double vol = signedVolume(m->mesh);
      nlohmann::json lv = nlohmann::json::array();
      for (const TreeLevelStats& l : r->tree.levels)
        lv.push_back({{"level", l.level},
                      {"spheres", l.nodes},
                      {"er_sum", l.outside_volume / vol},
                      {"rounds", l.iterations},
                      {"converged", l.converged}});
      if (json)
        std::cout << nlohmann::json{{"mesh", tree_args.mesh.path},
                                    {"output", tree_args.out_path},
                                    {"branching", to.branching},
                                    {"depth", to.depth},
                                    {"parents", parents},
                                    {"leaves", r->fit.spheres.size()},
                                    {"levels", lv},
                                    {"seconds",
                                     {{"fit", r->fit.seconds.total}, {"tree", r->tree.seconds}}},
                                    {"seed", fo.seed}}
                         .dump()
                  << '\n';
      if (!tree_args.quiet) {
        std::fprintf(stderr, "%s: tree of branching %d, depth %d (%s parents) -> %s\n",
                     tree_args.mesh.path.c_str(), to.branching, to.depth, parents.c_str(),
                     tree_args.out_path.c_str());
        for (const TreeLevelStats& l : r->tree.levels)
          std::fprintf(stderr, "  level %d: %4lld spheres, E_r summed %.4f\n", l.level,
                       static_cast<long long>(l.nodes), l.outside_volume / vol);
        std::fprintf(stderr, "  time %.2f s fit + %.2f s tree\n", r->fit.seconds.total,
                     r->tree.seconds);
      }
      return kOk;
    }
    if (*render) {
      int w = 0, h = 0;
      char x = 0, extra = 0;
      if (std::sscanf(render_size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 ||
          (x != 'x' && x != 'X'))
        return fail(
            Error{ErrorCode::kInvalidArgument, "--size: expected WxH, got '" + render_size + "'"});
      ro.width = w;
      ro.height = h;
      ro.up_axis = render_up[0] - 'x';
      ro.ground = !no_ground;
      ro.views.clear();
      std::stringstream vs(render_views);
      for (std::string v; std::getline(vs, v, ',');) {
        if (v == "front")
          ro.views.push_back(View::kFront);
        else if (v == "side")
          ro.views.push_back(View::kSide);
        else if (v == "top")
          ro.views.push_back(View::kTop);
        else if (v == "three-quarter")
          ro.views.push_back(View::kThreeQuarter);
        else
          return fail(Error{ErrorCode::kInvalidArgument, "--views: unknown view '" + v + "'"});
      }
      if (std::filesystem::path(render_out).extension().string() != ".png")
        return fail(Error{ErrorCode::kInvalidArgument, render_out + ": the output must be .png"});
      // The mesh is drawn even when it is not a closed solid.
      LoadOptions lo;
      lo.weld_tolerance = render_args.weld;
      auto m = loadMesh(render_args.path, lo);
      if (!m) return fail(m.error());
      std::vector<Sphere> spheres;
      if (!render_spheres.empty()) {
        auto t = readSphereTree(render_spheres);
        if (!t) return fail(t.error());
        spheres = t->leaves();
      }
      const SolidIndex index(m->mesh);
      auto img = renderScene(&index, spheres, ro);
      if (!img) return fail(img.error());
      Status st = writePng(render_out, *img);
      if (!st) return fail(st.error());
      return kOk;
    }
    if (*exp) {
      auto t = readSphereTree(export_in);
      if (!t) return fail(t.error());
      Status st = writeSphereSetMesh(export_out, t->leaves(), export_subdiv);
      if (!st) return fail(st.error());
      return kOk;
    }
    if (*query) {
      if (q_points.size() % 3 != 0 || q_segments.size() % 6 != 0)
        return fail(Error{ErrorCode::kInvalidArgument,
                          "--point takes x,y,z and --segment ax,ay,az,bx,by,bz"});
      auto ta = readSphereTree(query_path);
      if (!ta) return fail(ta.error());
      nlohmann::json out;
      // A file that holds a sphere tree is queried through it; a plain set gets one built.
      auto treeFor = [](const SphereTree& t) {
        return t.depth >= 2 && checkSphereTree(t).ok() ? t : queryTree(t.leaves());
      };
      const SphereTree qa = treeFor(*ta);
      for (size_t i = 0; i + 2 < q_points.size(); i += 3) {
        const Vec3 p(q_points[i], q_points[i + 1], q_points[i + 2]);
        const PointQuery pq = pointDistance(qa, p);
        const bool in = containsPoint(qa, p);
        if (json)
          out["points"].push_back({{"point", vec(p)}, {"inside", in}, {"distance", pq.distance}});
        else
          std::printf("point %g %g %g: %s, signed distance %.9g\n", p.x(), p.y(), p.z(),
                      in ? "inside" : "outside", pq.distance);
      }
      for (size_t i = 0; i + 5 < q_segments.size(); i += 6) {
        const Vec3 a(q_segments[i], q_segments[i + 1], q_segments[i + 2]);
        const Vec3 b(q_segments[i + 3], q_segments[i + 4], q_segments[i + 5]);
        const double len = segmentOutsideLength(qa, a, b);
        if (json)
          out["segments"].push_back({{"a", vec(a)}, {"b", vec(b)}, {"outside_length", len}});
        else
          std::printf("segment %g %g %g -> %g %g %g: %.9g of %.9g outside\n", a.x(), a.y(), a.z(),
                      b.x(), b.y(), b.z(), len, (b - a).norm());
      }
      if (!other_path.empty()) {
        auto tb = readSphereTree(other_path);
        if (!tb) return fail(tb.error());
        Pose pose;
        if (!other_pose.empty()) {
          Eigen::Quaterniond q(other_pose[3], other_pose[4], other_pose[5], other_pose[6]);
          if (!(q.norm() > 0.0) || !std::isfinite(q.norm()))
            return fail(Error{ErrorCode::kInvalidArgument, "--pose: the quaternion is zero"});
          pose.rotation = q.normalized().toRotationMatrix();
          pose.translation = Vec3(other_pose[0], other_pose[1], other_pose[2]);
        }
        const SphereTree qb = treeFor(*tb);
        const PairQuery pq = separation(qa, Pose{}, qb, pose);
        const bool hit = pq.distance < 0.0;
        if (json)
          out["other"] = {{"file", other_path},
                          {"overlap", hit},
                          {"distance", pq.distance},
                          {"closest_pair",
                           {{"a", vec(qa.nodes[pq.sphere_a].center)},
                            {"b", vec(pose.apply(qb.nodes[pq.sphere_b].center))}}}};
        else
          std::printf("against %s: %s, signed distance %.9g\n", other_path.c_str(),
                      hit ? "overlap" : "apart", pq.distance);
      }
      if (json) std::cout << out.dump() << '\n';
      return kOk;
    }
  } catch (const std::exception& e) {
    std::cerr << "sphereset: internal error: " << e.what() << '\n';
    return kInternal;
  }
  return kUsage;
}

// The view's scene (view.hpp): a mesh and its set or tree, or a robot's links and their sets,
// each solid made as `sphereset fit` (or `sphereset robot`) makes it, and its certificate.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/view.hpp"
#include "util/read_file.hpp"

namespace sphereset {
namespace {

using detail::extensionOf;

bool endsWithLower(const std::string& path, const std::string& tail) {
  std::string name = path;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name.size() >= tail.size() &&
         name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
}

// A solid from a loaded input: its index and the certificate of its set.
ViewSolid makeViewSolid(std::string name, std::string link, SolidInput input,
                        std::vector<std::vector<Sphere>> sets, int level) {
  ViewSolid s;
  s.name = std::move(name);
  s.link = std::move(link);
  auto shared = std::make_shared<const SolidInput>(std::move(input));
  s.index = std::make_shared<const SolidIndex>(shared->repair.solid);
  s.input = std::move(shared);
  s.sets = std::move(sets);
  s.level = level;
  certifyViewSolid(&s);
  return s;
}

// The save path and format of a mesh's scene: a tree goes back as a tree when the path is a
// tree file (.sph, .json), anything else as the shown level's set.
Status setMeshSave(ViewScene* scene, const std::string& spheres_path, bool is_tree,
                   const std::string& output) {
  const std::string path = output.empty() ? spheres_path : output;
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  scene->save_path = std::filesystem::absolute(path).lexically_normal().string();
  const bool tree_file = *format == SphereFormat::kSph || *format == SphereFormat::kJson;
  scene->save_format = is_tree && tree_file ? ViewSaveFormat::kTree : ViewSaveFormat::kSet;
  return {};
}

Expected<ViewScene> loadMeshScene(const std::string& mesh_path, const std::string& spheres_path,
                                  const ViewLoadOptions& o) {
  ViewScene scene;
  scene.kind = ViewKind::kMesh;
  scene.title = std::filesystem::path(mesh_path).stem().string();
  scene.repair = o.repair;
  auto solid = loadSolid(mesh_path, o.repair);
  if (!solid) return solid.error();
  auto tree = readSphereTree(spheres_path);
  if (!tree) return tree.error();
  // Plain sets read as two-level trees; a JSON tree file does not read as a plain set (as
  // `sphereset eval` tells them apart).
  auto plain = readSpheres(spheres_path);
  const bool is_tree = tree->depth >= 2 || !plain.ok();
  std::vector<std::vector<Sphere>> sets;
  int level = 0;
  if (is_tree) {
    for (int l = 0; l <= tree->depth; ++l) sets.push_back(tree->level(l));
    level = o.level < 0 ? tree->depth : o.level;
    if (level > tree->depth)
      return Error{ErrorCode::kInvalidArgument,
                   spheres_path + ": level " + std::to_string(o.level) +
                       " (the tree has levels 0 to " + std::to_string(tree->depth) + ")"};
  } else {
    if (o.level >= 0)
      return Error{ErrorCode::kInvalidArgument,
                   spheres_path + ": a sphere set has no levels (--level is for trees)"};
    sets.push_back(std::move(plain).value());
  }
  if (extensionOf(spheres_path) == ".yaml" || extensionOf(spheres_path) == ".yml") {
    // A one-link YAML keeps its link's name when saved.
    auto links = readLinkSpheres(spheres_path);
    if (links && links->size() == 1) scene.save_meta.name = (*links)[0].link;
  }
  scene.save_meta.source_mesh = mesh_path;
  if (!o.page_file) {  // a page file cannot save
    if (Status st = setMeshSave(&scene, spheres_path, is_tree, o.output); !st) return st.error();
    if (Status st = checkOutputPath(scene.save_path, {mesh_path}); !st) return st.error();
  }
  ViewSolid s = makeViewSolid(scene.title, "", std::move(solid).value(), std::move(sets), level);
  if (is_tree) s.tree = std::move(tree).value();
  scene.solids.push_back(std::move(s));
  scene.poses.assign(1, Eigen::Isometry3d::Identity());
  return scene;
}

// The links' spheres of a robot's sphere file: a YAML (cuRobo, Lula) or a URDF with sphere
// collisions (each link's sphere primitives).
Expected<std::vector<LinkSpheres>> robotSphereFile(const std::string& path,
                                                   const RobotLoadOptions& lo) {
  if (!isRobotDescriptionPath(path)) return readLinkSpheres(path);
  auto with_spheres = loadRobot(path, lo);
  if (!with_spheres) return with_spheres.error();
  // The links whose collisions are all spheres: those `sphereset robot` wrote (a link of
  // other geometry keeps it, and a save must not replace it with nothing).
  std::vector<LinkSpheres> links;
  for (const RobotLink& l : with_spheres->links) {
    const bool spheres_only =
        !l.geometry.empty() && !l.from_visual &&
        std::all_of(l.geometry.begin(), l.geometry.end(),
                    [](const LinkGeometry& g) { return g.kind == LinkGeometry::Kind::kSphere; });
    if (spheres_only) links.push_back({l.name, linkSpheres(l)});
  }
  return links;
}

// The pairs a planner never checks: the SRDF's, or the adjacent ones.
Status setAllowedPairs(ViewScene* scene, const Robot& robot, const std::string& srdf) {
  if (!srdf.empty()) {
    auto pairs = readSrdfDisabledPairs(srdf, robot);
    if (!pairs) return pairs.error();
    for (const DisabledPair& p : *pairs) scene->allowed_pairs.push_back({p.link1, p.link2});
    scene->allowed_source = "srdf";
    return {};
  }
  auto pairs = selfCollisionPairs(robot, {});
  if (!pairs) return pairs.error();
  scene->allowed_pairs = pairs->adjacent;
  scene->allowed_source = "adjacent";
  return {};
}

// A robot's scene without its save: one solid per link with geometry and spheres, posed at the
// robot's zero (or clamped) joint values. `source` names the sphere file in messages.
Expected<ViewScene> robotSceneOf(Robot robot, const std::string& urdf,
                                 std::vector<LinkSpheres> links, const std::string& source,
                                 const ViewLoadOptions& o) {
  ViewScene scene;
  scene.kind = ViewKind::kRobot;
  scene.title = robot.name;
  scene.urdf_path = urdf;
  scene.robot_load = o.robot_load;
  scene.repair = o.repair;
  scene.link_solid = o.link_solid;
  scene.link_solid_for = o.link_solid_for;
  if (o.level >= 0)
    return Error{ErrorCode::kInvalidArgument,
                 source + ": a robot's sets have no levels (--level is for trees)"};
  if (Status st = checkLinkSolids(robot, o.repair, o.link_solid, o.link_solid_for, urdf); !st)
    return st.error();
  for (const LinkSpheres& ls : links) {
    const auto it = std::find_if(robot.links.begin(), robot.links.end(),
                                 [&](const RobotLink& l) { return l.name == ls.link; });
    if (it == robot.links.end())
      return Error{ErrorCode::kInvalidData,
                   source + ": link '" + ls.link + "' is not a link of " + robot.name};
    // A link drawn needs geometry other than sphere primitives (those are spheres already).
    const bool has_solid = std::any_of(it->geometry.begin(), it->geometry.end(), [](const auto& g) {
      return g.kind != LinkGeometry::Kind::kSphere;
    });
    if (!has_solid || ls.spheres.empty()) continue;
    auto solid =
        linkSolid(*it, linkRepairOptions(o.repair, o.link_solid, o.link_solid_for, ls.link),
                  urdf + ": link '" + ls.link + "'");
    if (!solid) return solid.error();
    scene.solids.push_back(
        makeViewSolid(ls.link, ls.link, std::move(solid).value(), {ls.spheres}, 0));
  }
  if (scene.solids.empty())
    return Error{ErrorCode::kInvalidData,
                 source + ": no link with both geometry and spheres in " + robot.name};
  scene.file_links = std::move(links);
  if (Status st = setAllowedPairs(&scene, robot, o.srdf); !st) return st.error();
  scene.robot = std::make_shared<const Robot>(std::move(robot));
  if (Status st = setViewJoints(&scene, {}); !st) return st.error();
  scene.version = 0;
  return scene;
}

Expected<ViewScene> loadRobotScene(const std::string& urdf, const std::string& spheres_path,
                                   const ViewLoadOptions& o) {
  const RobotLoadOptions& lo = o.robot_load;
  auto robot = loadRobot(urdf, lo);
  if (!robot) return robot.error();
  auto links = robotSphereFile(spheres_path, lo);
  if (!links) return links.error();
  auto scene =
      robotSceneOf(std::move(robot).value(), urdf, std::move(links).value(), spheres_path, o);
  if (!scene) return scene.error();
  // A robot's JSON report is read, not written: without --output its scene has nothing to
  // save to (a save says so).
  if (o.page_file || (o.output.empty() && extensionOf(spheres_path) == ".json")) return scene;
  const std::string path = o.output.empty() ? spheres_path : o.output;
  if (endsWithLower(path, ".urdf")) {
    scene->save_format = ViewSaveFormat::kRobotUrdf;
  } else if (endsWithLower(path, ".xml")) {
    scene->save_format = ViewSaveFormat::kRobotMjcf;
  } else if (endsWithLower(path, ".yml") || endsWithLower(path, ".yaml")) {
    // A save keeps the YAML file's own layout and other keys (rewriteLinkSpheres); Lula's file
    // comes only from a Lula file.
    const auto lula = [](const std::string& p) {
      return endsWithLower(p, ".lula.yml") || endsWithLower(p, ".lula.yaml");
    };
    if (lula(path) && !lula(spheres_path))
      return Error{ErrorCode::kInvalidArgument,
                   path + ": a Lula robot description is saved from one (" + spheres_path +
                       " is not); give --output ROBOT.yml"};
    scene->save_format = ViewSaveFormat::kRobotYaml;
    const std::string in = extensionOf(spheres_path);
    if (in == ".yml" || in == ".yaml")
      scene->save_source = std::filesystem::absolute(spheres_path).lexically_normal().string();
  } else {
    return Error{
        ErrorCode::kInvalidArgument,
        path + ": a robot's spheres are saved as .yml/.yaml (cuRobo), .urdf or .xml (MJCF)"};
  }
  scene->save_path = std::filesystem::absolute(path).lexically_normal().string();
  if (Status st = checkOutputPath(scene->save_path, {urdf}); !st) return st.error();
  return scene;
}

}  // namespace

const Mesh& ViewSolid::displayed() const {
  const Mesh* original = originalTriangles(input->repair);
  return original ? *original : input->repair.solid;
}

bool viewSolidRepaired(const ViewSolid& solid) {
  return originalTriangles(solid.input->repair) != nullptr;
}

void certifyViewSolid(ViewSolid* solid) {
  solid->engine.reset();
  if (!solid->spheres().empty()) {
    CertificateOptions co;
    co.original = solid->input->original();
    auto engine = makeCoverageCertificate(*solid->index, solid->spheres(), co);
    // The sets are checked before they are stored, so the certificate takes them; were one
    // refused, the solid would show as uncovered with no gap known.
    if (engine) solid->engine = std::make_shared<CoverageCertificate>(std::move(engine).value());
  }
  solid->certificate = viewCertificate(*solid);
}

void replaceViewSet(ViewSolid* solid, std::vector<Sphere> spheres) {
  solid->sets[static_cast<size_t>(solid->level)] = std::move(spheres);
  certifyViewSolid(solid);
}

ViewCertificate viewCertificate(const ViewSolid& solid) {
  ViewCertificate c;
  c.spheres = static_cast<int64_t>(solid.spheres().size());
  c.volume = signedVolume(solid.input->repair.solid);
  if (!solid.engine) return c;  // an empty set: nothing covered, no gap to measure
  const CertificateSummary& e = solid.engine->summary();
  c.er_sum = e.er_sum;
  c.outside_volume = e.outside_volume;
  c.volume = e.volume;
  c.surface_covered = e.surface_covered;
  c.interior_covered = e.interior_covered;
  c.original_covered = e.original_covered;
  c.covered = e.covered;
  c.max_gap = e.max_gap;
  // The page draws the original triangles when the repair changed them (displayed()).
  c.uncovered_triangles =
      solid.input->original() ? e.original_uncovered_triangles : e.uncovered_triangles;
  c.seconds = e.seconds;
  // Every edit certifies again, so the view's protrusion is looser than eval's: within
  // kViewProtrusionTolerance of the diagonal, at most kViewProtrusionCells cells per ball (a
  // bound still valid past it). A ball much larger than the solid would otherwise take seconds
  // (found by fuzz_view_request).
  constexpr double kViewProtrusionTolerance = 1e-2;  // of the bounding-box diagonal
  constexpr int64_t kViewProtrusionCells = 5000;
  ProtrusionOptions po;
  po.tolerance = kViewProtrusionTolerance * solid.index->bounds().diagonal();
  po.max_cells = kViewProtrusionCells;
  if (po.tolerance > 0.0) {
    const auto t0 = std::chrono::steady_clock::now();
    auto p = sphereProtrusion(*solid.index, solid.spheres(), po);
    if (p) {
      c.protrusion = p->upper;
      c.protrusion_witness = p->witness;
      for (const SphereProtrusionBound& b : p->spheres) c.sphere_protrusion.push_back(b.upper);
    }
    c.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return c;
}

Expected<ViewScene> robotViewScene(const Robot& robot, const std::string& urdf,
                                   std::vector<LinkSpheres> links, const ViewLoadOptions& options) {
  return robotSceneOf(robot, urdf, std::move(links), urdf, options);
}

Expected<ViewScene> loadOneScene(const std::string& mesh_or_urdf, const std::string& spheres,
                                 const ViewLoadOptions& options) {
  if (isRobotDescriptionPath(mesh_or_urdf)) return loadRobotScene(mesh_or_urdf, spheres, options);
  if (!options.srdf.empty())
    return Error{ErrorCode::kInvalidArgument,
                 options.srdf + ": an SRDF is for robots (" + mesh_or_urdf + " is a mesh)"};
  return loadMeshScene(mesh_or_urdf, spheres, options);
}

Expected<ViewScene> loadViewScene(const std::string& mesh_or_urdf, const std::string& spheres,
                                  const ViewLoadOptions& options) {
  auto scene = loadOneScene(mesh_or_urdf, spheres, options);
  if (!scene) return scene.error();
  const auto name = [](const std::string& p) {
    return std::filesystem::path(p).filename().string();
  };
  scene->set_names = {name(spheres)};
  scene->inputs = {mesh_or_urdf, spheres};
  if (options.compare.empty()) return scene;
  scene->inputs.push_back(options.compare);
  ViewLoadOptions second = options;
  second.compare.clear();
  second.srdf.clear();
  second.output.clear();
  second.page_file = true;  // the compared set is never saved
  auto other = loadOneScene(mesh_or_urdf, options.compare, second);
  if (!other) return other.error();
  if (!scene->save_path.empty())
    if (Status st = checkOutputPath(scene->save_path, {options.compare}); !st) return st.error();
  for (size_t i = 0; i < other->solids.size(); ++i) {
    other->solids[i].set = 1;
    scene->solids.push_back(std::move(other->solids[i]));
    scene->poses.push_back(other->poses[i]);
  }
  scene->set_names.push_back(name(options.compare));
  return scene;
}

std::vector<LinkSpheres> viewLinkSpheres(const ViewScene& scene) {
  std::vector<LinkSpheres> links = scene.file_links;
  for (LinkSpheres& l : links)
    for (const ViewSolid& s : scene.solids)
      if (s.set == 0 && s.link == l.link) l.spheres = s.spheres();
  return links;
}

std::vector<std::array<std::string, 2>> viewContactPairs(const ViewScene& scene) {
  if (!scene.robot) return {};
  auto pairs = selfCollisionPairs(*scene.robot, viewLinkSpheres(scene), scene.joint_values);
  if (!pairs) return {};  // the joint values were checked when they were set
  std::vector<std::array<std::string, 2>> contact;
  for (const auto& p : pairs->overlapping) {
    const bool allowed =
        std::any_of(scene.allowed_pairs.begin(), scene.allowed_pairs.end(), [&](const auto& a) {
          return (a[0] == p[0] && a[1] == p[1]) || (a[0] == p[1] && a[1] == p[0]);
        });
    if (!allowed) contact.push_back(p);
  }
  return contact;
}

}  // namespace sphereset

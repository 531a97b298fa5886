// `sphereset view` (docs/view.md, the contract): a scene of solids with their sphere sets, the
// edits a page makes to it, the certificate after each, and the HTTP API as a pure function of
// the scene and a request, so that it is tested without sockets. ViewServer binds it to a port.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sphereset/certificate.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// One solid's certificate (the CERTIFICATE object of docs/view.md).
struct ViewCertificate {
  int64_t spheres = 0;
  double er_sum = 0.0;
  std::vector<double> outside_volume;  // per sphere, exact
  double volume = 0.0;                 // of the solid
  bool surface_covered = false, interior_covered = false, original_covered = false;
  bool covered = false;  // all three
  // Largest gap (surface, original or interior) over the bounding-box diagonal; unknown (no
  // value) for an empty set.
  std::optional<double> max_gap;
  std::vector<int64_t> uncovered_triangles;  // indices into the displayed mesh
  // The certified protrusion of the set from the solid (evaluate.hpp, sphereProtrusion, within
  // 0.01 of the diagonal, looser than eval's 0.001 as every edit computes it; length units), a
  // witness point, and each sphere's bound; unknown for an empty set.
  std::optional<double> protrusion;
  Vec3 protrusion_witness = Vec3::Zero();
  std::vector<double> sphere_protrusion;
  double seconds = 0.0;
};

// One solid of a scene and its set.
struct ViewSolid {
  std::string name;
  std::string link;  // the robot's link, empty for a mesh
  // The solid and the triangles it was made from (load.hpp), shared so that scenes copy cheaply.
  std::shared_ptr<const SolidInput> input;
  std::shared_ptr<const SolidIndex> index;
  // The sets of a tree's levels, root first, or one set; `level` is the one shown and edited.
  std::vector<std::vector<Sphere>> sets;
  int level = 0;
  std::optional<SphereTree> tree;  // the tree file's layout, for trees
  ViewCertificate certificate;
  // The incremental certificate of the shown set (certificate.hpp), which an edit updates where
  // the changed spheres reach; null for an empty set. Copies of a scene share it until one of
  // them changes its set, which then certifies a fresh one in full (copy on write).
  std::shared_ptr<CoverageCertificate> engine;
  // 0: the set the page edits and saves; 1: the set it is compared with (ViewLoadOptions::
  // compare), shown and certified, never edited, fitted or saved.
  int set = 0;
  const std::vector<Sphere>& spheres() const { return sets[static_cast<size_t>(level)]; }
  // The mesh the page draws: the original triangles when the repair changed them, else the
  // solid.
  const Mesh& displayed() const;
};

enum class ViewKind { kMesh, kRobot };
struct ViewFitJob;  // a fit the page started (view_fit.cpp)
// How a save writes: a sphere set, a tree (its levels back in their slots), a robot's links as
// cuRobo's YAML, the URDF with sphere collisions, or the robot as an MJCF with sphere geoms.
// (kRobotLula: Isaac Sim's robot description, a save as only: a Lula file read keeps its own
// layout as kRobotYaml.)
enum class ViewSaveFormat { kSet, kTree, kRobotYaml, kRobotUrdf, kRobotMjcf, kRobotLula };

struct ViewScene {
  ViewKind kind = ViewKind::kMesh;
  std::string title;
  int64_t version = 0;  // grows by one with every change
  std::vector<ViewSolid> solids;
  // Robots: the robot, the joint values a user set (jointState completes them), every joint's
  // value, and the links of the sphere file in its order (saved with the solids' sets).
  std::shared_ptr<const Robot> robot;
  std::string urdf_path;        // the robot's description (URDF or MJCF)
  RobotLoadOptions robot_load;  // how it was read (an MJCF save reads it again)
  std::map<std::string, double> joint_input;
  std::map<std::string, double> joint_values;
  std::vector<LinkSpheres> file_links;
  std::vector<Eigen::Isometry3d> poses;  // per solid: solid frame -> world
  // Where and how a save writes, fixed when the scene is loaded.
  std::string save_path;
  ViewSaveFormat save_format = ViewSaveFormat::kSet;
  // A robot's YAML sphere file read at the start, whose layout and other keys (cuRobo's
  // self_collision_ignore, Lula's description) a YAML save keeps; empty: written afresh.
  std::string save_source;
  SphereFileMeta save_meta;
  // The names of the sets shown: one, or two when a second set is compared with the first.
  std::vector<std::string> set_names;
  // The files the scene was read from (mesh or robot, sphere files): no save may write one.
  std::vector<std::string> inputs;
  // How the solids were made (ViewLoadOptions), for the fits the page starts.
  RepairOptions repair;
  LinkSolid link_solid = LinkSolid::kEnvelope;
  std::map<std::string, LinkSolid> link_solid_for;
  // Robots: the link pairs a planner never checks, link order first: an SRDF's
  // <disable_collisions> (ViewLoadOptions::srdf), else the adjacent pairs (selfCollisionPairs);
  // `allowed_source` says which ("srdf" or "adjacent").
  std::vector<std::array<std::string, 2>> allowed_pairs;
  std::string allowed_source;
  // The fit the page started last (startViewFit), running or finished; null before the first.
  // Copies of the scene share it: only the scene a server serves asks for its status.
  std::shared_ptr<ViewFitJob> fit;
};

struct ViewLoadOptions {
  RepairOptions repair;                         // how a mesh (or a link's geometry) is made a solid
  LinkSolid link_solid = LinkSolid::kEnvelope;  // a link's solid, as the robot command fits it
  std::map<std::string, LinkSolid> link_solid_for;  // link -> its solid instead of link_solid
  RobotLoadOptions robot_load;  // a URDF's package:// folders, an MJCF's collision group
  int level = -1;               // a tree's level shown first; -1: the leaves
  std::string output;           // where saves go; empty: the sphere file itself
  // For a page file (--html): no save path is set up or checked (a save is refused).
  bool page_file = false;
  // Robots: an SRDF whose <disable_collisions> pairs are the allowed ones (empty: the adjacent
  // pairs).
  std::string srdf;
  // A second sphere file of the same mesh or robot, shown beside or over the first with its own
  // certificates (ViewSolid::set 1), read-only.
  std::string compare;
};

// A scene from a mesh and a sphere set or tree file, or a URDF and its links' spheres (a
// cuRobo/Lula YAML, or a URDF with sphere collisions); with options.compare, a second file's
// solids after the first's (set 1), loaded the same way. Errors: those of loadSolid, readSpheres,
// readSphereTree, readLinkSpheres, loadRobot and linkSolid; kInvalidArgument for a level out of
// range, a save path of a format that cannot hold the scene, or one that is an input
// (checkOutputPath); kInvalidData for a sphere file naming a link the robot lacks or with no
// solid to show.
Expected<ViewScene> loadViewScene(const std::string& mesh_or_urdf, const std::string& spheres,
                                  const ViewLoadOptions& options = {});

// The scene of a robot loaded already and its links' spheres in memory (the fit of `sphereset
// robot`), for a static page: loadViewScene's robot scene without a save path (a save is
// refused). Errors: those of loadViewScene for a robot.
Expected<ViewScene> robotViewScene(const Robot& robot, const std::string& urdf,
                                   std::vector<LinkSpheres> links,
                                   const ViewLoadOptions& options = {});

// The certificate of one solid's shown set, in full: the evaluation's coverage certificates and
// exact E_r, with the original triangles when the repair changed them (a fresh incremental
// certificate, certificate.hpp, stored in `solid->engine`).
void certifyViewSolid(ViewSolid* solid);
// The solid's shown set replaced by `spheres` (checked already) and certified in full; the
// caller counts the scene's version on (once for a change of several solids).
void replaceViewSet(ViewSolid* solid, std::vector<Sphere> spheres);
// The CERTIFICATE of docs/view.md from the solid's incremental certificate (empty for an empty
// set); the uncovered triangles are ids into the displayed mesh.
ViewCertificate viewCertificate(const ViewSolid& solid);

// One edit of a set (docs/view.md): set sphere `index`, add a sphere, delete sphere `index`.
struct ViewEdit {
  enum class Op { kSet, kAdd, kDelete };
  Op op = Op::kSet;
  int64_t index = 0;
  Sphere sphere;
};

// The edits applied in order to solid `solid`'s shown set, each checked against the set as the
// edits before it left it; all or nothing. Errors (kInvalidArgument, nothing changes): an
// unknown solid, an index out of range, a NaN, infinite, out-of-range (limits::kMaxCoordinate)
// or negative value, more than limits::kMaxSpheres spheres.
Status applyViewEdits(ViewScene* scene, int64_t solid, const std::vector<ViewEdit>& edits);
// The shown set of `solid` grown until it covers (boundSpheres, fit.hpp).
Status boundViewSolid(ViewScene* scene, int64_t solid);
// Shows level `level` of a tree. kInvalidArgument: not a tree, a level out of range.
Status setViewLevel(ViewScene* scene, int64_t solid, int64_t level);
// Sets the given joints (the others keep their values), clamped to their limits (jointState's
// errors: kInvalidArgument for an unknown joint or a value that is not finite).
Status setViewJoints(ViewScene* scene, const std::map<std::string, double>& joints);
// A fit started from the page (POST /api/fit), run in a thread of its own while the page keeps
// asking how far it is: solid `solid`'s set fitted afresh with `spheres` spheres (a link's sphere
// primitives first, as `sphereset robot` does), or with the fewest that meet `tolerance`
// (fitToTolerance, as `sphereset fit --max-protrusion`; when no count up to its cap meets it,
// the best count found is applied and the status says so); or, with `robot` (or `budget` > 0),
// every link of a robot fitted by fitRobot: within `budget`, and with a tolerance's
// max_protrusion as every link's limit (RobotFitOptions::max_protrusion or its fraction; a
// robot takes no max_er or max_spheres). `quality` is fit.hpp's preset; the seed is 1.
struct ViewFitRequest {
  int64_t solid = 0;
  int spheres = 0;
  int budget = 0;
  bool robot = false;
  FitQuality quality = FitQuality::kDefault;
  ToleranceOptions tolerance;  // its limits and cap only (original, walls, progress unused)
};
// How a fit is: "idle" (none started), "running", "done", "cancelled" or "failed"; `fraction` of
// its work (0 to 1, an estimate from its rounds), `stage` in words, the error of a failed one,
// and the solids it replaced once applied with the version that did it.
struct ViewFitStatus {
  std::string state = "idle";
  double fraction = 0.0;
  std::string stage;
  std::string error;
  std::vector<int64_t> solids;        // the solids it fits
  std::map<std::string, int> counts;  // a robot's split (link -> spheres); a tolerance's count
                                      // for one solid (its link, or "mesh" -> spheres)
  bool tolerance = false;             // the fit had a tolerance or protrusion limit
  bool tolerance_met = true;          // and met it (else the best found was applied)
  bool applied = false;               // this call applied it to the scene
};
// Starts a fit. Errors (kInvalidArgument, nothing starts): a fit running already or finished
// and not yet applied (viewFitStatus applies it), an unknown
// solid, a tree's solid (trees are fitted by `sphereset tree`), spheres outside [1,
// limits::kMaxSpheres] without a budget or a tolerance, spheres with a tolerance, a tolerance
// checkToleranceOptions refuses, a budget on a mesh or below one per link, a robot fit without
// a budget or a max_protrusion, a robot's max_er or max_spheres, options fitRequestOptions
// refuses.
Status startViewFit(ViewScene* scene, const ViewFitRequest& request);
// How the fit is; a finished one is applied to the scene the first time it is asked for (its
// solids get the new sets and their certificates, the version grows by one).
ViewFitStatus viewFitStatus(ViewScene* scene);
// Asks a running fit to stop at its next progress report (a mesh fit reports every round and
// every 0.25 s; a robot's link repair is not interrupted); nothing changes. No error when none
// runs.
void cancelViewFit(ViewScene* scene);

// A robot's links' spheres as the scene holds them: the sphere file's links in its order, each
// shown link with its (edited) set, the compared set left out. Saves and the self-collision
// pairs use it.
std::vector<LinkSpheres> viewLinkSpheres(const ViewScene& scene);

// A robot's self-collision at its current pose: the pairs of links whose spheres overlap
// (selfCollisionPairs' rule) that are not allowed (ViewScene::allowed_pairs). Empty for a mesh.
std::vector<std::array<std::string, 2>> viewContactPairs(const ViewScene& scene);

// Writes every set to the scene's save path in its format, atomically. Returns the bytes
// written. Errors: those of the writers; kInvalidArgument when a tree's level no longer fits its
// layout (spheres added or deleted).
// A robot's scene can be saved as another robot format (`as`: kRobotYaml, kRobotUrdf,
// kRobotMjcf or kRobotLula, the last at the robot's reference pose as `sphereset robot` writes
// it): beside the save path, its name with that format's ending (viewSavePath). A
// request never names a path. Errors: kInvalidArgument for a mesh's scene, a set or tree
// format, or a path that is one of the inputs.
Expected<int64_t> saveViewScene(const ViewScene& scene,
                                std::optional<ViewSaveFormat> as = std::nullopt);
// Where a save in `format` goes: the save path, or for another robot format the save path with
// that format's ending (.yml, .urdf, .xml, .lula.yml) in place of its own (and of ".lula" before
// it). An existing file there is replaced, as a save replaces its own file. Empty without a save
// path.
std::string viewSavePath(const ViewScene& scene, ViewSaveFormat format);
// The formats a scene can be saved as: its own, and for a robot every robot format the build
// writes (MJCF with MuJoCo).
std::vector<ViewSaveFormat> viewSaveFormats(const ViewScene& scene);
// "txt", "json", "sph", "yaml", "urdf", "mjcf", "lula" (the scene JSON's save.format), and back for
// the robot formats (kInvalidArgument otherwise).
std::string viewSaveFormatName(const ViewScene& scene, ViewSaveFormat format);
Expected<ViewSaveFormat> viewRobotSaveFormat(const std::string& name);

// Which surface of a solid: the displayed mesh (the original triangles when the repair changed
// them, else the solid), or the repaired solid itself.
enum class ViewSurface { kDisplayed, kRepaired };
// Whether the repair changed the solid's triangles (the page can then show either surface).
bool viewSolidRepaired(const ViewSolid& solid);

// The scene as JSON text (GET /api/scene), and one solid's surface as the binary of
// GET /api/geometry (uint32 V, uint32 T, float32 xyz × V, uint32 abc × T, little-endian).
std::string viewSceneJson(const ViewScene& scene);
std::string viewGeometry(const ViewSolid& solid, ViewSurface surface = ViewSurface::kDisplayed);

// Whether this build has the page (web/ was built), and the one message for when it has not
// (kInvalidData).
bool viewPageAvailable();
Status checkViewPage();
// `html` with the scene's data element at its marker (docs/view.md, "Static pages").
// kInvalidData when `html` has no marker.
Expected<std::string> inlineViewData(std::string_view html, const ViewScene& scene);
// The page of this build with the scene inlined; kInvalidData when the build has no page.
Expected<std::string> viewStaticPage(const ViewScene& scene);

// A request to the API: header names in lower case, each as often as it was sent.
struct ViewRequest {
  std::string method;  // "GET", "POST", ...
  std::string path;    // without the query
  std::map<std::string, std::string> query;
  std::vector<std::pair<std::string, std::string>> headers;
  std::string body;
};

struct ViewResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  // Sent with the answer: handleViewRequest sets viewResponseHeaders() on every answer.
  std::vector<std::pair<std::string, std::string>> headers;
};

// The headers of every answer of the API: nothing cached (Cache-Control: no-store), no type
// guessed from the content (X-Content-Type-Options: nosniff), no address (and with it the page's
// token) sent to another site (Referrer-Policy: no-referrer), no framing by another page.
const std::vector<std::pair<std::string, std::string>>& viewResponseHeaders();

// Who may talk to the server: its token and the address it listens on.
struct ViewAccess {
  std::string token;
  std::string host = "127.0.0.1";
  int port = 0;
};

// 128 random bits (std::random_device) as 32 hexadecimal digits.
std::string randomViewToken();

// The API (docs/view.md): checks the request (size, Host, Origin, token, path, method, body)
// and answers it, changing `scene` only for a request that is right in every field.
ViewResponse handleViewRequest(ViewScene* scene, const ViewAccess& access,
                               const ViewRequest& request);

// The API on a socket (cpp-httplib), one request at a time on the scene.
class ViewServer {
 public:
  // Binds `host`:`port` (0: any free port) with a fresh token and serves in a thread of its
  // own. kInvalidArgument when the address cannot be bound.
  static Expected<std::unique_ptr<ViewServer>> start(ViewScene scene, const std::string& host,
                                                     int port);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;
  const ViewAccess& access() const;
  // http://HOST:PORT/?token=TOKEN
  std::string url() const;
  // The scene as it is now (a copy, taken under the server's lock).
  ViewScene scene() const;
  // Stops serving and joins the thread (also done by the destructor).
  void stop();

 private:
  struct Impl;
  explicit ViewServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace sphereset

// MJCF robot descriptions (https://mujoco.readthedocs.io/en/2.2.2/XMLreference.html) read by
// MuJoCo itself: mj_loadXML compiles the file (defaults and classes, childclass, includes,
// fromto, angle units, meshdir, mesh scale and re-centring) and the compiled mjModel becomes a
// Robot (robot.hpp, loadRobot). No MJCF is parsed here; the text is only checked first
// (mjcf_text.cpp). Reference for the kinematics: MuJoCo's mj_kinematics (engine_core_smooth.c):
// a body's frame is its parent's times (body_pos, body_quat), then each joint in order rotates
// about the axis through its anchor (hinge) or slides along it, by qpos − qpos0. Reference for
// the pairs: mj_collision's filter (engine_collision_driver.c): bodies welded together or to a
// welded parent, contype/conaffinity masks that never match, and <contact><exclude>.
#include "robot/mjcf.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "robot/mujoco_model.hpp"
#include "robot/xml_text.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot.hpp"

namespace sphereset {

bool mujocoAvailable() { return true; }

namespace detail {
namespace {

namespace fs = std::filesystem;

Eigen::Isometry3d mjPose(const mjtNum* pos, const mjtNum* quat) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Vec3(pos[0], pos[1], pos[2]);
  t.linear() =
      Eigen::Quaterniond(quat[0], quat[1], quat[2], quat[3]).normalized().toRotationMatrix();
  return t;
}

// The compiled mesh `id` (float vertices as MuJoCo keeps them), shared by its geoms.
std::shared_ptr<const Mesh> compiledMesh(const mjModel& m, int id) {
  auto mesh = std::make_shared<Mesh>();
  const int v0 = m.mesh_vertadr[id], nv = m.mesh_vertnum[id];
  const int f0 = m.mesh_faceadr[id], nf = m.mesh_facenum[id];
  mesh->vertices.reserve(nv);
  for (int v = v0; v < v0 + nv; ++v)
    mesh->vertices.emplace_back(m.mesh_vert[3 * v], m.mesh_vert[3 * v + 1], m.mesh_vert[3 * v + 2]);
  mesh->triangles.reserve(nf);
  for (int f = f0; f < f0 + nf; ++f)
    mesh->triangles.push_back({m.mesh_face[3 * f], m.mesh_face[3 * f + 1], m.mesh_face[3 * f + 2]});
  return mesh;
}

// Geom `g` as link geometry in its body's frame; nullopt for planes and height fields.
std::optional<LinkGeometry> geomGeometry(const mjModel& m, int g,
                                         std::map<int, std::shared_ptr<const Mesh>>& meshes) {
  LinkGeometry out;
  out.origin = mjPose(m.geom_pos + 3 * g, m.geom_quat + 4 * g);
  const mjtNum* size = m.geom_size + 3 * g;
  switch (m.geom_type[g]) {
    case mjGEOM_SPHERE:
      out.kind = LinkGeometry::Kind::kSphere;
      out.radius = size[0];
      break;
    case mjGEOM_CAPSULE:
      out.kind = LinkGeometry::Kind::kCapsule;
      out.radius = size[0];
      out.length = 2.0 * size[1];
      break;
    case mjGEOM_ELLIPSOID:
      out.kind = LinkGeometry::Kind::kEllipsoid;
      out.radii = Vec3(size[0], size[1], size[2]);
      break;
    case mjGEOM_CYLINDER:
      out.kind = LinkGeometry::Kind::kCylinder;
      out.radius = size[0];
      out.length = 2.0 * size[1];
      break;
    case mjGEOM_BOX:
      out.kind = LinkGeometry::Kind::kBox;
      out.box_size = 2.0 * Vec3(size[0], size[1], size[2]);
      break;
    case mjGEOM_MESH: {
      const int id = m.geom_dataid[g];
      auto& mesh = meshes[id];
      if (!mesh) mesh = compiledMesh(m, id);
      out.kind = LinkGeometry::Kind::kTriangles;
      out.triangles = mesh;
      break;
    }
    default:  // mjGEOM_PLANE, mjGEOM_HFIELD: not solids
      return std::nullopt;
  }
  return out;
}

// Body `b`'s joints as RobotJoints from `parent` (a link name) to `child`, with the
// geometry-less links between them appended to `links` (a body of several joints).
void addBodyJoints(const mjModel& m, int b, const std::string& parent, const std::string& child,
                   Robot& robot) {
  const Eigen::Isometry3d origin = mjPose(m.body_pos + 3 * b, m.body_quat + 4 * b);
  const int n = m.body_jntnum[b], j0 = m.body_jntadr[b];
  if (n == 0) {
    RobotJoint j;
    j.name = child + "/fixed";
    j.parent = parent;
    j.child = child;
    j.origin = origin;
    robot.joints.push_back(std::move(j));
    return;
  }
  std::string from = parent;
  for (int k = 0; k < n; ++k) {
    const int id = j0 + k;
    RobotJoint j;
    j.name = mujocoName(m, mjOBJ_JOINT, id, "joint");
    j.parent = from;
    j.child = k + 1 == n ? child : child + "/" + j.name;
    j.origin = k == 0 ? origin : Eigen::Isometry3d::Identity();
    j.anchor = Vec3(m.jnt_pos[3 * id], m.jnt_pos[3 * id + 1], m.jnt_pos[3 * id + 2]);
    j.axis = Vec3(m.jnt_axis[3 * id], m.jnt_axis[3 * id + 1], m.jnt_axis[3 * id + 2]).normalized();
    const bool limited = m.jnt_limited[id] != 0;
    j.lower = limited ? m.jnt_range[2 * id] : 0.0;
    j.upper = limited ? m.jnt_range[2 * id + 1] : 0.0;
    switch (m.jnt_type[id]) {
      case mjJNT_HINGE:
        j.type = limited ? RobotJoint::Type::kRevolute : RobotJoint::Type::kContinuous;
        j.reference = m.qpos0[m.jnt_qposadr[id]];
        break;
      case mjJNT_SLIDE:
        j.type = limited ? RobotJoint::Type::kPrismatic : RobotJoint::Type::kOther;
        j.reference = m.qpos0[m.jnt_qposadr[id]];
        break;
      default:  // ball and free joints: at their reference
        j.type = RobotJoint::Type::kOther;
        break;
    }
    if (k + 1 < n) robot.links.push_back(RobotLink{j.child, {}, false});
    from = j.child;
    robot.joints.push_back(std::move(j));
  }
}

// Whether MuJoCo never collides bodies a and b: bodiesFiltered, or (by contype/conaffinity) no
// pair of their collision geoms whose masks match.
bool filteredPair(const mjModel& m, int a, int b, const std::vector<std::vector<int>>& geoms,
                  bool by_group) {
  if (bodiesFiltered(m, a, b)) return true;
  if (by_group) return false;
  for (int ga : geoms[a])
    for (int gb : geoms[b])
      if ((m.geom_contype[ga] & m.geom_conaffinity[gb]) != 0 ||
          (m.geom_contype[gb] & m.geom_conaffinity[ga]) != 0)
        return false;
  return true;
}

Expected<Robot> robotFromModel(const mjModel& m, const std::string& path,
                               const RobotLoadOptions& options) {
  if (m.nbody > limits::kMaxMjcfBodies || m.ngeom > limits::kMaxMjcfGeoms)
    return Error{ErrorCode::kInvalidData, path + ": " + std::to_string(m.nbody) + " bodies and " +
                                              std::to_string(m.ngeom) + " geoms (read up to " +
                                              std::to_string(limits::kMaxMjcfBodies) + " and " +
                                              std::to_string(limits::kMaxMjcfGeoms) + ")"};
  Robot robot;
  robot.name = m.names != nullptr && m.names[0] != '\0' ? std::string(m.names)
                                                        : fs::path(path).stem().string();
  std::vector<std::string> names(m.nbody);
  for (int b = 0; b < m.nbody; ++b) names[b] = mujocoName(m, mjOBJ_BODY, b, "body");
  robot.root = names[0];
  std::map<int, std::shared_ptr<const Mesh>> meshes;
  std::vector<std::vector<int>> collision(m.nbody);
  std::vector<size_t> link_of(m.nbody);
  bool any = false;
  for (int b = 0; b < m.nbody; ++b) {
    if (b > 0) addBodyJoints(m, b, names[m.body_parentid[b]], names[b], robot);
    RobotLink link{names[b], {}, false};
    bool flat = false;  // a plane or height field among its collision geoms
    for (int g = m.body_geomadr[b]; g >= 0 && g < m.body_geomadr[b] + m.body_geomnum[b]; ++g) {
      if (!isCollisionGeom(m, g, options)) continue;
      auto geometry = geomGeometry(m, g, meshes);
      if (!geometry) {
        flat = true;
        continue;
      }
      collision[b].push_back(g);
      link.geometry.push_back(std::move(*geometry));
    }
    if (flat && b > 0 && link.geometry.empty())
      return Error{ErrorCode::kInvalidData,
                   path + ": body '" + names[b] +
                       "': its collision geoms are planes or height fields only (not solids)"};
    any = any || !link.geometry.empty();
    link_of[b] = robot.links.size();
    robot.links.push_back(std::move(link));
  }
  if (!any)
    return Error{ErrorCode::kInvalidData,
                 path + ": no body has collision geoms" +
                     (options.mjcf_collision_group >= 0
                          ? " in group " + std::to_string(options.mjcf_collision_group)
                          : std::string(" (geoms with a non-zero contype or conaffinity)"))};
  for (int a = 0; a < m.nbody; ++a)
    for (int b = a + 1; b < m.nbody; ++b)
      if (!collision[a].empty() && !collision[b].empty() &&
          filteredPair(m, a, b, collision, options.mjcf_collision_group >= 0))
        robot.excluded_pairs.push_back(
            {robot.links[link_of[a]].name, robot.links[link_of[b]].name});
  return robot;
}

}  // namespace

Expected<Robot> loadMjcf(const std::string& path, const RobotLoadOptions& options) {
  if (options.mjcf_collision_group < -1 || options.mjcf_collision_group > 5)
    return Error{ErrorCode::kInvalidArgument,
                 "the MJCF collision group must be from 0 to 5, or -1 for contype/conaffinity "
                 "(got " +
                     std::to_string(options.mjcf_collision_group) + ")"};
  auto text = readXmlText(path, "MJCF");
  if (!text) return text.error();
  const std::string dir = fs::absolute(fs::path(path)).parent_path().string();
  if (Status st = checkMjcfText(path, *text, dir); !st) return st.error();
  auto model = compileWithMujoco(path, path);
  if (!model) return model.error();
  auto robot = robotFromModel(**model, path, options);
  if (!robot) return robot.error();
  if (auto settled = jointState(*robot, {}); !settled)
    return Error{ErrorCode::kInvalidData, path + ": " + settled.error().message};
  return robot;
}

}  // namespace detail
}  // namespace sphereset

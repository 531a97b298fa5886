// MuJoCo as the tests' independent judge of MJCF models: a model loaded by mj_loadXML, posed by
// mj_kinematics (or mj_fwdPosition, with its contacts) at joint values given by name, and points
// drawn on the surface of each of its geoms in world coordinates, as MuJoCo places them.
#pragma once

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/robot.hpp"

namespace sphereset::test {

struct MjModelFree {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataFree {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// A model and its data; `model` is null when MuJoCo refused the file (`error` says why).
struct MjScene {
  std::unique_ptr<mjModel, MjModelFree> model;
  std::unique_ptr<mjData, MjDataFree> data;
  std::string error;

  explicit MjScene(const std::string& path) {
    char buf[1024] = "";
    model.reset(mj_loadXML(path.c_str(), nullptr, buf, sizeof buf));
    error = buf;
    if (model) data.reset(mj_makeData(model.get()));
  }

  // Sets the hinge and slide joints named in `q` (others at qpos0) and poses the model;
  // `contacts` also runs the collision detection (mj_fwdPosition).
  void pose(const std::map<std::string, double>& q, bool contacts = false) {
    const mjModel* m = model.get();
    for (int i = 0; i < m->nq; ++i) data->qpos[i] = m->qpos0[i];
    for (const auto& [name, value] : q) {
      const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str());
      if (j >= 0 && (m->jnt_type[j] == mjJNT_HINGE || m->jnt_type[j] == mjJNT_SLIDE))
        data->qpos[m->jnt_qposadr[j]] = value;
    }
    if (contacts)
      mj_fwdPosition(m, data.get());
    else
      mj_kinematics(m, data.get());
  }

  std::string bodyName(int b) const {
    const char* n = mj_id2name(model.get(), mjOBJ_BODY, b);
    return n ? n : "";
  }

  // Geom g's frame in the world, as MuJoCo posed it.
  Vec3 toWorld(int g, const Vec3& local) const {
    const mjtNum* p = data->geom_xpos + 3 * g;
    const mjtNum* r = data->geom_xmat + 9 * g;  // row-major
    Vec3 out;
    for (int i = 0; i < 3; ++i)
      out[i] = p[i] + r[3 * i] * local.x() + r[3 * i + 1] * local.y() + r[3 * i + 2] * local.z();
    return out;
  }

  // Body-name pairs in contact after pose(q, true).
  std::set<std::pair<std::string, std::string>> contactPairs(
      const std::set<int>& skip_geoms = {}) const {
    std::set<std::pair<std::string, std::string>> out;
    for (int i = 0; i < data->ncon; ++i) {
      const mjContact& c = data->contact[i];
      if (skip_geoms.count(c.geom1) || skip_geoms.count(c.geom2)) continue;
      std::string a = bodyName(model->geom_bodyid[c.geom1]);
      std::string b = bodyName(model->geom_bodyid[c.geom2]);
      if (a > b) std::swap(a, b);
      out.emplace(a, b);
    }
    return out;
  }
};

// Random values within each movable joint's sampling range.
inline std::map<std::string, double> randomJointValues(const Robot& r, std::mt19937_64& rng) {
  std::map<std::string, double> q;
  for (const RobotJoint& j : r.joints) {
    if (!isMovable(j)) continue;
    const auto [lo, hi] = jointSampleRange(j);
    q[j.name] = std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  return q;
}

// Points on the surface of geom g in its own frame: the primitive's surface drawn at random,
// or a mesh's vertices and points inside its triangles.
inline std::vector<Vec3> geomSurface(const mjModel& m, int g, int count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> n;
  auto unit = [&] { return Vec3(n(rng), n(rng), n(rng)).normalized(); };
  const mjtNum* s = m.geom_size + 3 * g;
  std::vector<Vec3> out;
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * std::numbers::pi * u(rng);
    switch (m.geom_type[g]) {
      case mjGEOM_SPHERE:
        out.push_back(s[0] * unit());
        break;
      case mjGEOM_ELLIPSOID:
        out.push_back(unit().cwiseProduct(Vec3(s[0], s[1], s[2])));
        break;
      case mjGEOM_CAPSULE: {
        const Vec3 v = unit();
        if (u(rng) < 0.5)
          out.push_back(Vec3(s[0] * std::cos(a), s[0] * std::sin(a), (2.0 * u(rng) - 1.0) * s[1]));
        else
          out.push_back(s[0] * v + Vec3(0.0, 0.0, v.z() < 0.0 ? -s[1] : s[1]));
        break;
      }
      case mjGEOM_CYLINDER:
        if (u(rng) < 0.5) {
          out.push_back(Vec3(s[0] * std::cos(a), s[0] * std::sin(a), (2.0 * u(rng) - 1.0) * s[1]));
        } else {
          const double rho = s[0] * std::sqrt(u(rng));
          out.push_back(Vec3(rho * std::cos(a), rho * std::sin(a), u(rng) < 0.5 ? -s[1] : s[1]));
        }
        break;
      case mjGEOM_BOX: {
        Vec3 p(s[0] * (2.0 * u(rng) - 1.0), s[1] * (2.0 * u(rng) - 1.0),
               s[2] * (2.0 * u(rng) - 1.0));
        const int axis = i % 3;
        p[axis] = u(rng) < 0.5 ? -s[axis] : s[axis];
        out.push_back(p);
        break;
      }
      case mjGEOM_MESH: {
        const int id = m.geom_dataid[g];
        const int f =
            m.mesh_faceadr[id] + static_cast<int>(u(rng) * m.mesh_facenum[id]) % m.mesh_facenum[id];
        double b1 = u(rng), b2 = u(rng);
        if (b1 + b2 > 1.0) b1 = 1.0 - b1, b2 = 1.0 - b2;
        const float* v = m.mesh_vert + 3 * m.mesh_vertadr[id];
        auto vertex = [&](int k) {
          const int at = m.mesh_face[3 * f + k];
          return Vec3(v[3 * at], v[3 * at + 1], v[3 * at + 2]);
        };
        out.push_back(vertex(0) + b1 * (vertex(1) - vertex(0)) + b2 * (vertex(2) - vertex(0)));
        break;
      }
      default:
        break;
    }
  }
  if (m.geom_type[g] == mjGEOM_MESH) {
    const int id = m.geom_dataid[g];
    const float* v = m.mesh_vert + 3 * m.mesh_vertadr[id];
    for (int k = 0; k < m.mesh_vertnum[id]; ++k)
      out.push_back(Vec3(v[3 * k], v[3 * k + 1], v[3 * k + 2]));
  }
  return out;
}

// Whether mesh geom g is convex: every vertex on the inner side of every face plane (MuJoCo
// collides a mesh as its convex hull, so only a convex mesh's contacts are the mesh's own).
inline bool convexMesh(const mjModel& m, int g) {
  const int id = m.geom_dataid[g];
  const float* v = m.mesh_vert + 3 * m.mesh_vertadr[id];
  auto vertex = [&](int k) { return Vec3(v[3 * k], v[3 * k + 1], v[3 * k + 2]); };
  for (int f = m.mesh_faceadr[id]; f < m.mesh_faceadr[id] + m.mesh_facenum[id]; ++f) {
    const Vec3 a = vertex(m.mesh_face[3 * f]);
    const Vec3 nrm = (vertex(m.mesh_face[3 * f + 1]) - a).cross(vertex(m.mesh_face[3 * f + 2]) - a);
    for (int k = 0; k < m.mesh_vertnum[id]; ++k)
      if (nrm.dot(vertex(k) - a) > 1e-9 * nrm.norm()) return false;
  }
  return true;
}

}  // namespace sphereset::test

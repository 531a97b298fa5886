// mj_step of a robot's sphere model against its mesh model, in a scene with contacts: the
// robot, a table beside it and a floor; the mesh model released from a start pose under gravity
// falls onto the table and folds onto itself, and one mj_step of each model is timed from each
// state of that fall (the same states for both). One CSV row per model (bench/mujoco_step.sh):
// name, variant, collision geoms, steps, seconds, microseconds per step, microseconds of
// collision detection alone (mj_collision) per step, mean contacts per step, the share of steps
// with a contact against the table, and with a contact between two robot bodies that are not welded
// together and not parent and child (self-contact).
//   mujoco_step --header
//   mujoco_step NAME MESH_MODEL SPHERE_MODEL STEPS TABLE_X TABLE_Z [JOINT=VALUE,...]
//   mujoco_step --mesh-model ROBOT.urdf PACKAGE_DIR OUT.xml   (the URDF as MuJoCo reads it)
#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"

namespace {

namespace fs = std::filesystem;

// The model with a table (a box whose top is at table_z, from x = table_x - 0.3 to + 0.3) and a
// floor added to its world body, written beside it (so that its asset paths resolve) and loaded.
mjModel* withTable(const std::string& path, double table_x, double table_z) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const size_t at = xml.rfind("</worldbody>");
  if (at == std::string::npos) return nullptr;
  char table[512];
  std::snprintf(table, sizeof table,
                "<geom name=\"bench_table\" type=\"box\" size=\"0.3 0.4 0.02\" pos=\"%g 0 %g\"/>"
                "<geom name=\"bench_floor\" type=\"plane\" size=\"3 3 0.1\" pos=\"0 0 -0.5\"/>",
                table_x, table_z - 0.02);
  xml.insert(at, table);
  const fs::path scene =
      fs::path(path).parent_path() / (".bench_scene_" + fs::path(path).filename().string());
  std::ofstream(scene) << xml;
  char error[1024] = "";
  mjModel* m = mj_loadXML(scene.c_str(), nullptr, error, sizeof error);
  fs::remove(scene);
  if (m == nullptr) std::fprintf(stderr, "mujoco_step: %s: %s\n", path.c_str(), error);
  return m;
}

// Whether a contact joins two robot bodies that are neither welded together nor parent and
// child (those touch at every joint).
bool selfContact(const mjModel* m, const mjContact& c) {
  const int a = m->geom_bodyid[c.geom1], b = m->geom_bodyid[c.geom2];
  if (a == 0 || b == 0 || m->body_weldid[a] == 0 || m->body_weldid[b] == 0) return false;
  const int wa = m->body_weldid[a], wb = m->body_weldid[b];
  return wa != wb && m->body_weldid[m->body_parentid[wa]] != wb &&
         m->body_weldid[m->body_parentid[wb]] != wa;
}

// The start pose: qpos0 with the hinge and slide joints of "J=V,..." set.
void startPose(const mjModel* m, mjData* d, const std::string& pose) {
  mj_resetData(m, d);
  std::stringstream in(pose);
  std::string item;
  while (std::getline(in, item, ',')) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos) continue;
    const int j = mj_name2id(m, mjOBJ_JOINT, item.substr(0, eq).c_str());
    if (j >= 0) d->qpos[m->jnt_qposadr[j]] = std::atof(item.c_str() + eq + 1);
  }
}

// The states of the mesh model's own fall from the start pose (qpos, qvel per step).
struct Trajectory {
  std::vector<mjtNum> qpos, qvel;
  int steps = 0;
};

Trajectory fall(const mjModel* m, int steps, const std::string& pose) {
  mjData* d = mj_makeData(m);
  startPose(m, d, pose);
  Trajectory t;
  t.steps = steps;
  for (int i = 0; i < steps; ++i) {
    t.qpos.insert(t.qpos.end(), d->qpos, d->qpos + m->nq);
    t.qvel.insert(t.qvel.end(), d->qvel, d->qvel + m->nv);
    mj_step(m, d);
  }
  mj_deleteData(d);
  return t;
}

// One mj_step from each state of `t`: the same states for both models, so that the times
// compare the collision work of the same poses and not two diverging falls.
void run(const std::string& name, const char* variant, const mjModel* m, const Trajectory& t) {
  mjData* d = mj_makeData(m);
  int collision_geoms = 0;
  for (int g = 0; g < m->ngeom; ++g)
    collision_geoms += (m->geom_contype[g] != 0 || m->geom_conaffinity[g] != 0) ? 1 : 0;
  const int table = mj_name2id(m, mjOBJ_GEOM, "bench_table");
  auto set = [&](int i) {
    d->time = 0.0;
    std::copy_n(t.qpos.begin() + static_cast<std::ptrdiff_t>(i) * m->nq, m->nq, d->qpos);
    std::copy_n(t.qvel.begin() + static_cast<std::ptrdiff_t>(i) * m->nv, m->nv, d->qvel);
  };
  for (int i = 0; i < std::min(t.steps, 50); ++i) {  // warm-up
    set(i);
    mj_step(m, d);
  }
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < t.steps; ++i) {
    set(i);
    mj_step(m, d);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The contacts, and the collision detection alone (mj_collision after mj_kinematics), in a
  // second pass (the timed one above is mj_step alone).
  double contacts = 0.0, collision_seconds = 0.0;
  int table_steps = 0, self_steps = 0;
  for (int i = 0; i < t.steps; ++i) {
    set(i);
    mj_kinematics(m, d);
    const auto c0 = std::chrono::steady_clock::now();
    mj_collision(m, d);
    collision_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
    contacts += d->ncon;
    bool on_table = false, self = false;
    for (int c = 0; c < d->ncon; ++c) {
      on_table = on_table || d->contact[c].geom1 == table || d->contact[c].geom2 == table;
      self = self || selfContact(m, d->contact[c]);
    }
    table_steps += on_table ? 1 : 0;
    self_steps += self ? 1 : 0;
  }
  std::printf("%s,%s,%d,%d,%.4f,%.2f,%.2f,%.2f,%.3f,%.3f\n", name.c_str(), variant, collision_geoms,
              t.steps, seconds, 1e6 * seconds / t.steps, 1e6 * collision_seconds / t.steps,
              contacts / t.steps, static_cast<double>(table_steps) / t.steps,
              static_cast<double>(self_steps) / t.steps);
  mj_deleteData(d);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--header") {
    std::puts(
        "robot,model,collision_geoms,steps,seconds,us_per_step,collision_us_per_step,"
        "contacts_per_step,"
        "table_contact_share,self_contact_share");
    return 0;
  }
  if (argc == 5 && std::string(argv[1]) == "--mesh-model") {
    sphereset::RobotLoadOptions lo;
    lo.package_paths = {argv[3]};
    const sphereset::Status st = sphereset::writeSphereMjcf(argv[2], argv[4], {}, {}, lo);
    if (!st) std::fprintf(stderr, "mujoco_step: %s\n", st.error().message.c_str());
    return st ? 0 : 1;
  }
  if (argc != 7 && argc != 8) {
    std::fprintf(stderr,
                 "usage: mujoco_step NAME MESH_MODEL SPHERE_MODEL STEPS TABLE_X TABLE_Z "
                 "[JOINT=VALUE,...]\n");
    return 2;
  }
  const int steps = std::atoi(argv[4]);
  const double x = std::atof(argv[5]), z = std::atof(argv[6]);
  const std::string pose = argc == 8 ? argv[7] : "";
  mjModel* meshes = withTable(argv[2], x, z);
  mjModel* spheres = withTable(argv[3], x, z);
  if (meshes == nullptr || spheres == nullptr) return 1;
  if (meshes->nq != spheres->nq || meshes->nv != spheres->nv) {
    std::fprintf(stderr, "mujoco_step: the two models have different joints\n");
    return 1;
  }
  const Trajectory t = fall(meshes, steps, pose);
  run(argv[1], "meshes", meshes, t);
  run(argv[1], "spheres", spheres, t);
  mj_deleteModel(meshes);
  mj_deleteModel(spheres);
  return 0;
}

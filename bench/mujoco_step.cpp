// mj_step of a robot's sphere model against its mesh model, in a scene with contacts: the
// robot, a table beside it and a floor, released from its reference pose under gravity so that
// it falls onto the table and onto itself. One CSV row per model (bench/mujoco_step.sh):
// name, variant, collision geoms, steps, seconds, microseconds per step, mean contacts per
// step, the share of steps with a contact between two robot bodies.
//   mujoco_step --header
//   mujoco_step NAME MESH_MODEL SPHERE_MODEL STEPS TABLE_X TABLE_Z
//   mujoco_step --mesh-model ROBOT.urdf PACKAGE_DIR OUT.xml   (the URDF as MuJoCo reads it)
#include <mujoco/mujoco.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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
  const fs::path scene = fs::path(path).parent_path() / (".bench_scene_" + fs::path(path).filename().string());
  std::ofstream(scene) << xml;
  char error[1024] = "";
  mjModel* m = mj_loadXML(scene.c_str(), nullptr, error, sizeof error);
  fs::remove(scene);
  if (m == nullptr) std::fprintf(stderr, "mujoco_step: %s: %s\n", path.c_str(), error);
  return m;
}

void run(const std::string& name, const char* variant, const std::string& path, int steps,
         double table_x, double table_z) {
  mjModel* m = withTable(path, table_x, table_z);
  if (m == nullptr) std::exit(1);
  mjData* d = mj_makeData(m);
  int collision_geoms = 0;
  for (int g = 0; g < m->ngeom; ++g)
    collision_geoms += (m->geom_contype[g] != 0 || m->geom_conaffinity[g] != 0) ? 1 : 0;
  for (int i = 0; i < 20; ++i) mj_step(m, d);  // warm-up
  mj_resetData(m, d);
  double contacts = 0.0;
  int self_steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    mj_step(m, d);
    contacts += d->ncon;
    bool self = false;
    for (int c = 0; c < d->ncon && !self; ++c)
      self = m->geom_bodyid[d->contact[c].geom1] != 0 && m->geom_bodyid[d->contact[c].geom2] != 0;
    self_steps += self ? 1 : 0;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s,%s,%d,%d,%.4f,%.2f,%.2f,%.3f\n", name.c_str(), variant, collision_geoms, steps,
              seconds, 1e6 * seconds / steps, contacts / steps,
              static_cast<double>(self_steps) / steps);
  mj_deleteData(d);
  mj_deleteModel(m);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--header") {
    std::puts("robot,model,collision_geoms,steps,seconds,us_per_step,contacts_per_step,"
              "self_contact_share");
    return 0;
  }
  if (argc == 5 && std::string(argv[1]) == "--mesh-model") {
    sphereset::RobotLoadOptions lo;
    lo.package_paths = {argv[3]};
    const sphereset::Status st = sphereset::writeSphereMjcf(argv[2], argv[4], {}, {}, lo);
    if (!st) std::fprintf(stderr, "mujoco_step: %s\n", st.error().message.c_str());
    return st ? 0 : 1;
  }
  if (argc != 7) {
    std::fprintf(stderr, "usage: mujoco_step NAME MESH_MODEL SPHERE_MODEL STEPS TABLE_X TABLE_Z\n");
    return 2;
  }
  const int steps = std::atoi(argv[4]);
  const double x = std::atof(argv[5]), z = std::atof(argv[6]);
  run(argv[1], "meshes", argv[2], steps, x, z);
  run(argv[1], "spheres", argv[3], steps, x, z);
  return 0;
}

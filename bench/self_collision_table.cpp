// One CSV row for the self-collision sampling of a robot (sampleSelfCollisions,
// robot_collision.hpp) on a sphere file of its links: the pairs per reason, the pairs left to
// check, and the sampling's time, on the spheres or on the link solids (each link's geometry
// made a solid as `sphereset robot` makes it, repair included when this build has it).
//
//   self_collision_table URDF PACKAGE_PATH SPHERES.yml SAMPLES spheres|meshes THREADS
//   self_collision_table --header
#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/sphere_io.hpp"
#ifdef SPHERESET_BENCH_REPAIR
#include "sphereset/repair_cgal.hpp"
#endif

using namespace sphereset;

namespace {

constexpr const char* kHeader =
    "robot,links,spheres,check,threads,samples,pairs,adjacent,default,always,never,enabled,"
    "solids_s,sampling_s";

int failed(const std::string& what) {
  std::fprintf(stderr, "self_collision_table: %s\n", what.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--header") == 0) {
    std::printf("%s\n", kHeader);
    return 0;
  }
  if (argc != 7)
    return failed(
        "usage: self_collision_table URDF PACKAGE_PATH SPHERES.yml SAMPLES spheres|meshes "
        "THREADS");
  const std::string check = argv[5];
  const int threads = std::atoi(argv[6]);
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  RobotLoadOptions lo;
  lo.package_paths = {argv[2]};
  auto robot = loadRobot(argv[1], lo);
  if (!robot) return failed(robot.error().message);
  auto spheres = readLinkSpheres(argv[3]);
  if (!spheres) return failed(spheres.error().message);
  CollisionSamplingOptions o;
  if (Status st = setCollisionSamplingOption(&o, "collision_samples", argv[4]); !st)
    return failed(st.error().message);
  if (Status st = setCollisionSamplingOption(&o, "collision_check", check); !st)
    return failed(st.error().message);

  // The link solids, as the robot command fits them.
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<CollisionSolid> solids;
  if (o.check == CollisionCheck::kMeshes) {
    RepairOptions ro;
#ifdef SPHERESET_BENCH_REPAIR
    ro.operations = cgalSolidOperations();
#endif
    auto made = robotCollisionSolids(*robot, ro);
    if (!made) return failed(made.error().message);
    solids = std::move(made).value();
  }
  const double solids_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto m = sampleSelfCollisions(*robot, *spheres, o, solids);
  if (!m) return failed(m.error().message);
  size_t total = 0;
  for (const LinkSpheres& l : *spheres) total += l.spheres.size();
  std::printf("%s,%zu,%zu,%s,%d,%d,%lld,%lld,%lld,%lld,%lld,%lld,%.3f,%.3f\n", robot->name.c_str(),
              spheres->size(), total, check.c_str(), threads, m->samples,
              static_cast<long long>(m->pairs),
              static_cast<long long>(m->count(DisableReason::kAdjacent)),
              static_cast<long long>(m->count(DisableReason::kDefault)),
              static_cast<long long>(m->count(DisableReason::kAlways)),
              static_cast<long long>(m->count(DisableReason::kNever)),
              static_cast<long long>(m->enabled), solids_s, m->seconds);
  return 0;
}

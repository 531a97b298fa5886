// MuJoCo models loaded and written back with MuJoCo's errors as sphereset's: one lock around
// MuJoCo's global state (its error and warning handlers, the last loaded XML that
// mj_saveLastXML writes), and the model freed on every path. Only built with MuJoCo.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <string>

#include "sphereset/robot.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
using MjModelPtr = std::unique_ptr<mjModel, MjModelDeleter>;

// A new empty file of its own (mkstemps) in `dir`, or else in the system's temporary folder,
// removed when this goes. `path()` is empty when none could be made.
class TempFile {
 public:
  explicit TempFile(const std::string& suffix, const std::string& dir = "");
  ~TempFile();
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Compiles the MJCF or URDF file at `path` with mj_loadXML. `saved_xml`, when given, receives
// the model as MuJoCo writes it back (mj_saveLastXML). Errors (kInvalidData): "NAME: MuJoCo:
// MESSAGE" with MuJoCo's message on one line (it names the element and the line); MuJoCo's
// fatal errors, which would otherwise end the process, are caught and reported the same way.
Expected<MjModelPtr> compileWithMujoco(const std::string& path, const std::string& name,
                                       std::string* saved_xml = nullptr);

// Whether geom `g` is collision geometry under `options` (robot.hpp: RobotLoadOptions::
// mjcf_collision_group): in that group, or else MuJoCo collides it (contype or conaffinity
// non-zero).
bool isCollisionGeom(const mjModel& m, int g, const RobotLoadOptions& options);

// Whether MuJoCo's collision filter always skips bodies a and b whatever their geoms
// (mj_collision: the same weld body; a weld body and the weld body of the other's parent,
// unless filterparent is disabled or one is the world; an <exclude> of the pair).
bool bodiesFiltered(const mjModel& m, int a, int b);

// The name MuJoCo gives object `id` of `type`, or `fallback` + id when it has none.
std::string mujocoName(const mjModel& m, mjtObj type, int id, const char* fallback);

}  // namespace sphereset::detail

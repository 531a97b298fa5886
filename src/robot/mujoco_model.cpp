// MuJoCo's loader behind one lock, with its errors turned into sphereset's. MuJoCo (2.2.2)
// keeps global state: mju_user_error and mju_user_warning (by default an error prints and exits
// the process, and both append to MUJOCO_LOG.TXT in the working folder) and the model last
// loaded by mj_loadXML, which mj_saveLastXML writes. Here the handlers are ours for the length
// of one load: a fatal error becomes an exception caught below, a warning is dropped (MuJoCo
// goes on with its own default), and nothing is printed or logged.
#include "robot/mujoco_model.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sphereset::detail {
namespace {

std::mutex& mujocoLock() {
  static std::mutex lock;
  return lock;
}

struct MujocoFatal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void throwFatal(const char* message) { throw MujocoFatal(message); }
void dropWarning(const char*) {}

// MuJoCo's messages span lines ("Error: ...\nElement 'geom', line 3\n"): one line, joined by
// "; ", without the "Error: " prefix.
std::string mujocoMessage(const std::string& text) {
  std::string out, line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.rfind("Error: ", 0) == 0) line.erase(0, 7);
    if (line.empty()) continue;
    out += (out.empty() ? "" : "; ") + line;
  }
  return out.empty() ? "unknown error" : out;
}

// Restores MuJoCo's handlers when a load ends, however it ends.
struct Handlers {
  void (*error)(const char*) = mju_user_error;
  void (*warning)(const char*) = mju_user_warning;
  Handlers() {
    mju_user_error = throwFatal;
    mju_user_warning = dropWarning;
  }
  ~Handlers() {
    mju_user_error = error;
    mju_user_warning = warning;
  }
  Handlers(const Handlers&) = delete;
  Handlers& operator=(const Handlers&) = delete;
};

}  // namespace

TempFile::TempFile(const std::string& suffix, const std::string& dir) {
  std::error_code ec;
  std::filesystem::path base = dir;
  if (base.empty()) base = std::filesystem::temp_directory_path(ec);
  if (ec) base = "/tmp";
  std::string pattern = (base / ".sphereset-XXXXXX").string();
  pattern += suffix;
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const int fd = mkstemps(buf.data(), static_cast<int>(suffix.size()));
  if (fd < 0) return;
  ::close(fd);
  path_ = buf.data();
}

TempFile::~TempFile() {
  if (path_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

Expected<MjModelPtr> compileWithMujoco(const std::string& path, const std::string& name,
                                       std::string* saved_xml) {
  std::lock_guard<std::mutex> guard(mujocoLock());
  Handlers handlers;
  char error[1024] = "";
  MjModelPtr model;
  try {
    model.reset(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
  } catch (const MujocoFatal& e) {
    return Error{ErrorCode::kInvalidData, name + ": MuJoCo: " + mujocoMessage(e.what())};
  }
  if (!model) return Error{ErrorCode::kInvalidData, name + ": MuJoCo: " + mujocoMessage(error)};
  if (saved_xml == nullptr) return model;
  // mj_saveLastXML writes to a file only: a private temporary file, read back and removed.
  const TempFile tmp(".xml");
  if (tmp.path().empty())
    return Error{ErrorCode::kWriteFailed, name + ": no temporary file for MuJoCo's model"};
  char save_error[1024] = "";
  int saved = 0;
  try {
    saved = mj_saveLastXML(tmp.path().c_str(), model.get(), save_error, sizeof save_error);
  } catch (const MujocoFatal& e) {
    return Error{ErrorCode::kInvalidData, name + ": MuJoCo: " + mujocoMessage(e.what())};
  }
  std::ifstream in(tmp.path(), std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (saved == 0 || text.str().empty())
    return Error{ErrorCode::kWriteFailed,
                 name + ": MuJoCo could not write the model back: " + mujocoMessage(save_error)};
  *saved_xml = text.str();
  return model;
}

bool isCollisionGeom(const mjModel& m, int g, const RobotLoadOptions& options) {
  if (options.mjcf_collision_group >= 0) return m.geom_group[g] == options.mjcf_collision_group;
  return m.geom_contype[g] != 0 || m.geom_conaffinity[g] != 0;
}

bool bodiesFiltered(const mjModel& m, int a, int b) {
  const int wa = m.body_weldid[a], wb = m.body_weldid[b];
  if (wa == wb) return true;
  const int pa = m.body_weldid[m.body_parentid[wa]], pb = m.body_weldid[m.body_parentid[wb]];
  const bool filterparent = (m.opt.disableflags & mjDSBL_FILTERPARENT) == 0;
  if (filterparent && wa != 0 && wb != 0 && (wa == pb || wb == pa)) return true;
  for (int e = 0; e < m.nexclude; ++e) {
    const int sig = m.exclude_signature[e];
    if (sig == ((a + 1) << 16) + b + 1 || sig == ((b + 1) << 16) + a + 1) return true;
  }
  return false;
}

std::string mujocoName(const mjModel& m, mjtObj type, int id, const char* fallback) {
  const char* n = mj_id2name(&m, type, id);
  if (n != nullptr && *n != '\0') return n;
  return std::string(fallback) + std::to_string(id);
}

}  // namespace sphereset::detail

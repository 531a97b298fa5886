// The hostile-input table (tests/hostile/cases.json) through the C++ API: every case ends in the
// status and message the table gives, never a crash, a hang or an allocation beyond the limits.
// python/tests/test_hostile.py runs the same table through the command line and Python.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "sphereset/animate.hpp"
#include "sphereset/batch.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "sphereset/query.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/tree.hpp"
#ifdef SPHERESET_TEST_REPAIR
#include "sphereset/repair_cgal.hpp"
#endif

namespace sphereset {
namespace {

const std::string kDir = std::string(SPHERESET_TEST_DATA_DIR) + "/../hostile/";

ErrorCode codeNamed(const std::string& name) {
  static const std::map<std::string, ErrorCode> codes = {
      {"invalid_argument", ErrorCode::kInvalidArgument},
      {"unreadable", ErrorCode::kUnreadable},
      {"invalid_data", ErrorCode::kInvalidData},
      {"not_solid", ErrorCode::kNotSolid},
      {"write_failed", ErrorCode::kWriteFailed}};
  return codes.at(name);
}

template <class T>
Status statusOf(const Expected<T>& e) {
  return e ? Status{} : Status{e.error()};
}

// The fit's and the repair's options of a case, as the front doors hand them to the library:
// the repair's rows to setRepairOption, the others to setFitRequestOption.
Status setOptions(const nlohmann::json& opts, RepairOptions* repair, FitRequest* request) {
#ifdef SPHERESET_TEST_REPAIR
  repair->operations = cgalSolidOperations();
#endif
  for (const auto& [name, value] : opts.items()) {
    const std::string text = value.get<std::string>();
    const Status st = findOption(repairOptionTable(), name)
                          ? setRepairOption(repair, name, text)
                          : setFitRequestOption(request, name, text);
    if (!st) return st;
  }
  return {};
}

// The solid the fit would run on (loadSolid), as `sphereset check` and `ss.solid` make it.
Status repairCase(const std::vector<std::string>& in, const nlohmann::json& opts) {
  FitRequest unused;
  RepairOptions repair;
  if (Status st = setOptions(opts, &repair, &unused); !st) return st;
  return statusOf(loadSolid(in[0], repair));
}

Status fitCase(const std::vector<std::string>& in, const nlohmann::json& opts) {
  FitRequest request;
  RepairOptions repair;
  if (Status st = setOptions(opts, &repair, &request); !st) return st;
  auto solid = loadSolid(in[0], repair);
  if (!solid) return solid.error();
  FitOptions fo = fitOptionsFor(request);
  fo.original = solid->original();
  return statusOf(fitSpheres(SolidIndex(solid->repair.solid), fo));
}

Status treeCase(const std::vector<std::string>& in, const nlohmann::json& opts) {
  TreeOptions to;
  for (const auto& [name, value] : opts.items())
    if (Status st = setTreeOption(&to, name, value.get<std::string>()); !st) return st;
  auto solid = loadSolid(in[0], RepairOptions{});
  if (!solid) return solid.error();
  FitOptions fo;
  fo.num_spheres = 0;
  return statusOf(fitSphereTree(SolidIndex(solid->repair.solid), fo, to));
}

Status evalCase(const std::vector<std::string>& in, const nlohmann::json& opts) {
  EvalOptions eo;
  for (const auto& [name, value] : opts.items())
    if (Status st = setEvalOption(&eo, name, value.get<std::string>()); !st) return st;
  auto solid = loadSolid(in[0], RepairOptions{});
  if (!solid) return solid.error();
  auto spheres = readSpheres(in[1]);
  if (!spheres) return spheres.error();
  return statusOf(evaluateSpheres(SolidIndex(solid->repair.solid), *spheres, eo));
}

Status queryCase(const std::vector<std::string>& in, const nlohmann::json& point) {
  auto tree = readSphereTree(in[0]);
  if (!tree) return tree.error();
  Vec3 p;
  for (int k = 0; k < 3; ++k)
    p[k] = point[k].is_string() ? std::stod(point[k].get<std::string>()) : point[k].get<double>();
  return statusOf(pointDistance(*tree, p));
}

// "KEY=VALUE" as the pair.
std::pair<std::string, std::string> keyed(const nlohmann::json& item) {
  const std::string text = item.get<std::string>();
  const size_t eq = text.rfind('=');
  return {text.substr(0, eq), text.substr(eq + 1)};
}

// A URDF loaded with its package folder beside it, then fitted with the options set in the
// struct (not through the table's setter: fitRobot's own check is what is tested).
Status robotCase(const std::vector<std::string>& in, const nlohmann::json& opts) {
  RobotLoadOptions lo;
  lo.package_paths = {std::filesystem::path(in[0]).parent_path().string()};
  auto robot = loadRobot(in[0], lo);
  if (!robot) return robot.error();
  RobotFitOptions fo;
  fo.name = in[0];
  fo.quality = FitQuality::kFast;
  auto number = [&](const char* name) { return std::stod(opts.at(name).get<std::string>()); };
  if (opts.contains("budget")) fo.budget = static_cast<int>(number("budget"));
  if (opts.contains("padding")) fo.padding = number("padding");
  if (opts.contains("link_spheres")) {
    const auto [link, count] = keyed(opts.at("link_spheres"));
    fo.link_spheres[link] = std::stoi(count);
  }
  if (opts.contains("link_padding")) {
    const auto [link, padding] = keyed(opts.at("link_padding"));
    fo.link_padding[link] = std::stod(padding);
  }
  if (opts.contains("link_solid_for")) {
    const auto [link, solid] = keyed(opts.at("link_solid_for"));
    fo.link_solid_for[link] = solid == "walls" ? LinkSolid::kWalls : LinkSolid::kEnvelope;
  }
  return statusOf(fitRobot(*robot, fo));
}

// The asset's clip read, then its bind pose's spheres moved through it (options set in the
// structs, checked by loadAnimation and animateSpheres).
Status animateCase(const std::vector<std::string>& in, const nlohmann::json& opts) {
  SkinnedLoadOptions so;
  if (opts.contains("fps")) so.fps = std::stod(opts.at("fps").get<std::string>());
  auto anim = loadAnimation(in[0], so);
  if (!anim) return anim.error();
  auto spheres = readSpheres(in[1]);
  if (!spheres) return spheres.error();
  AnimateOptions o;
  if (opts.contains("bone_neighbours"))
    o.bone_neighbours = std::stoi(opts.at("bone_neighbours").get<std::string>());
  return statusOf(animateSpheres(anim->asset.rest, *spheres, anim->frames, o, &anim->asset.skin));
}

Status runCase(const nlohmann::json& c) {
  std::vector<std::string> in;
  for (const auto& f : c.at("inputs")) in.push_back(kDir + f.get<std::string>());
  const nlohmann::json opts = c.value("options", nlohmann::json::object());
  const std::string op = c.at("op");
  if (op == "fit") return fitCase(in, opts);
  if (op == "repair") return repairCase(in, opts);
  if (op == "batch") {
    const BatchOptions defaults;
    return statusOf(listBatchItems(in[0], defaults));
  }
  if (op == "tree") return treeCase(in, opts);
  if (op == "eval") return evalCase(in, opts);
  if (op == "query") return queryCase(in, c.at("point"));
  if (op == "robot") return robotCase(in, opts);
  if (op == "animate") return animateCase(in, opts);
  if (op == "links") return statusOf(readLinkSpheres(in[0]));
  ADD_FAILURE() << "unknown op " << op;
  return {};
}

TEST(Hostile, EveryCaseEndsInItsStatusAndMessage) {
  std::ifstream file(kDir + "cases.json");
  ASSERT_TRUE(file) << kDir;
  const nlohmann::json cases = nlohmann::json::parse(file);
  ASSERT_GE(cases.size(), 16u);
  for (const nlohmann::json& c : cases) {
    SCOPED_TRACE(c.at("name").get<std::string>());
#ifndef SPHERESET_TEST_REPAIR
    if (c.value("repair", false)) continue;
#endif
    if (c.value("mujoco", false) && !mujocoAvailable()) continue;
    const Status st = runCase(c);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, codeNamed(c.at("code")));
    EXPECT_TRUE(
        std::regex_search(st.error().message, std::regex(c.at("message").get<std::string>())))
        << st.error().message;
    EXPECT_EQ(st.error().message.find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace sphereset

// Shared pieces of the sphereset subcommands: error mapping, mesh loading, fit options, the
// coverage check of a result.
#include "cli_common.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "sphereset/sphere_io.hpp"
#include "sphereset/view.hpp"
#ifdef SPHERESET_WITH_REPAIR
#include "sphereset/load.hpp"
#include "sphereset/repair_cgal.hpp"
#endif

namespace sphereset::cli {

int exitFor(const Error& e) { return exitCodeFor(e.code); }

ProgressLine::ProgressLine(std::string command)
    : command_(std::move(command)),
      t0_(std::chrono::steady_clock::now()),
      tty_(isatty(STDERR_FILENO) != 0) {}

void ProgressLine::show(const std::string& stage, int64_t done, int64_t total,
                        const std::string& item) {
  const int64_t tenth = total > 0 ? 10 * done / total : 10;
  const bool last = done >= total;
  if (!tty_ && !last && stage == stage_ && tenth == tenth_) return;
  stage_ = stage;
  tenth_ = tenth;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  std::fprintf(stderr, "%s%s: %s %lld/%lld%s%s (%.1f s)%s", tty_ ? "\r\033[K" : "",
               command_.c_str(), stage.c_str(), static_cast<long long>(done),
               static_cast<long long>(total), item.empty() ? "" : ", ", item.c_str(), s,
               tty_ && !last ? "" : "\n");
}

int fail(const Error& e) {
  std::cerr << "sphereset: " << e.message << '\n';
  return exitFor(e);
}

int requirePage() {
  if (Status st = checkViewPage(); !st) {
    fail(st.error());
    return kNoPage;
  }
  return kOk;
}

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

void addMeshArgs(CLI::App* cmd, MeshArgs* a, bool repair) {
  cmd->add_option("mesh", a->path, "Mesh file (OBJ, PLY, STL, OFF, DAE, glTF/GLB, ...)")
      ->required();
  if (repair)
    addRepairArgs(cmd, a);
  else
    addWeldArg(cmd, a);
}

void addWeldArg(CLI::App* cmd, MeshArgs* a) {
  addTableOptions(cmd, &a->repair, repairOptionTable(), {"repair", "wrap_alpha", "wrap_offset"});
  // Without a repair there is no automatic tolerance to try: the row's value, or exact welding.
  a->repair.options.at("weld_tolerance")
      ->description("Merge vertices closer than this distance (default 0: exact duplicates only)");
}

void addRepairArgs(CLI::App* cmd, MeshArgs* a) {
  addTableOptions(cmd, &a->repair, repairOptionTable());
  cmd->add_flag("--fill-cavities,!--keep-cavities", a->fill_cavities,
                "Fill inner cavities and holes (default; a hollow casing is solid for "
                "collision), or keep cavities as empty space");
}

Expected<RepairOptions> repairOptions(const MeshArgs& a) {
  RepairOptions ro;
  for (const auto& [name, text] : a.repair.given())
    if (Status st = setRepairOption(&ro, name, text); !st) return st.error();
  ro.fill_cavities = a.fill_cavities;
#ifdef SPHERESET_WITH_REPAIR
  ro.operations = cgalSolidOperations();
#endif
  return ro;
}

LoadOptions loadOptions(const RepairOptions& ro) {
  LoadOptions lo;
  lo.weld_tolerance = std::max(0.0, ro.weld_tolerance);  // negative: automatic, exact here
  return lo;
}

Expected<LoadOptions> loadOptions(const MeshArgs& a) {
  auto ro = repairOptions(a);
  if (!ro) return ro.error();
  return loadOptions(*ro);
}

Expected<SolidInput> loadSolid(const MeshArgs& a) {
  auto ro = repairOptions(a);
  if (!ro) return ro.error();
  return sphereset::loadSolid(a.path, *ro);
}

// --joint-positions j1=v1,j2=v2 (radians or metres), for joints of the robot.
void addRobotLoadArgs(CLI::App* cmd, RobotLoadArgs* a, const std::string& when) {
  cmd->add_option("--package-path", a->package_paths,
                  when +
                      "folder searched for package://NAME/ paths (repeatable; then "
                      "ROS_PACKAGE_PATH)");
  cmd->add_option("--collision-group", a->collision_group,
                  when +
                      "an MJCF's collision geoms are those of this group (0-5) instead of those "
                      "MuJoCo collides (non-zero contype or conaffinity)");
}

RobotLoadOptions robotLoadOptions(const RobotLoadArgs& a) {
  RobotLoadOptions lo;
  lo.package_paths = a.package_paths;
  lo.mjcf_collision_group = a.collision_group;
  return lo;
}

Expected<std::map<std::string, double>> parseJointPositions(const std::string& text,
                                                            const Robot& robot) {
  auto parsed = parseJointValues(text);
  if (!parsed) return Error{parsed.error().code, "--joint-positions " + parsed.error().message};
  const std::map<std::string, double>& out = *parsed;
  // The library checks the names and values, and says what it clamps.
  auto state = jointState(robot, out);
  if (!state) return Error{state.error().code, "--joint-positions: " + state.error().message};
  for (const std::string& note : state->notes)
    std::fprintf(stderr, "sphereset: warning: %s\n", note.c_str());
  return out;
}

nlohmann::json repairJson(const RepairResult& r) {
  // NaN (an undefined volume ratio) is not JSON: it is written as null.
  return fieldsJson(repairResultFields(r));
}

std::string repairLine(const RepairResult& r) {
  if (r.notes.empty() && r.kind == RepairKind::kNone) return {};
  std::string s = std::string("repair ") + repairName(r.kind);
  for (size_t i = 0; i < r.notes.size(); ++i) s += (i == 0 ? ": " : "; ") + r.notes[i];
  if (std::isfinite(r.volume_ratio) && r.kind != RepairKind::kNone) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "; volume %.4f of the input's", r.volume_ratio);
    s += buf;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, " (%.2f s)", r.seconds);
  return s + buf;
}

nlohmann::json fieldsJson(const std::vector<ResultField>& fields) {
  nlohmann::json j = nlohmann::json::object();
  for (const ResultField& f : fields) {
    const std::string name = f.name;
    const size_t dot = name.find('.');
    nlohmann::json& slot =
        dot == std::string::npos ? j[name] : j[name.substr(0, dot)][name.substr(dot + 1)];
    std::visit([&](const auto& v) { slot = v; }, f.value);
  }
  return j;
}

std::vector<std::pair<std::string, std::string>> TableArgs::given() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [name, opt] : options) {
    if (opt->count() == 0) continue;
    if (auto it = items.find(name); it != items.end())
      for (const std::string& item : it->second) out.emplace_back(name, item);
    else
      out.emplace_back(name, text.at(name));
  }
  return out;
}

void addTableOptions(CLI::App* cmd, TableArgs* a, std::span<const OptionSpec> table,
                     std::initializer_list<std::string_view> skip) {
  for (const OptionSpec& o : table) {
    if (std::find(skip.begin(), skip.end(), std::string_view(o.name)) != skip.end()) continue;
    const char* type = o.type == OptionType::kChoice ? "TEXT"
                       : o.type == OptionType::kReal ? (o.percent ? "FLOAT[%]" : "FLOAT")
                                                     : "INT";
    // No CLI11 checks: the library parses and checks the text (one message for every door).
    const std::string help = std::string(o.help) + " (default " + o.default_text + ")";
    if (o.key)  // KEY=VALUE, repeatable
      a->options[o.name] = cmd->add_option(o.flag, a->items[o.name], help)
                               ->type_name(std::string(o.key) + "=" + type)
                               ->allow_extra_args(false);
    else
      a->options[o.name] =
          cmd->add_option(o.flag, a->text[o.name], help)->type_name(type)->allow_extra_args(false);
  }
}

void addFitArgs(CLI::App* cmd, FitArgs* a, bool count_option) {
  addMeshArgs(cmd, &a->mesh);
  cmd->add_option("-o,--output", a->out_path,
                  count_option ? "Output file; the format follows the extension: .txt (x y z r), "
                                 ".json, .sph, .yaml (cuRobo collision_spheres)"
                               : "Output file: .sph (Bradshaw's layout) or .json (nodes with "
                                 "parent and children)")
      ->required();
  addFitTuningArgs(cmd, a, count_option);
  cmd->add_flag("-q,--quiet", a->quiet, "No progress on stderr");
}

void addFitTuningArgs(CLI::App* cmd, FitArgs* a, bool count_option) {
  if (count_option)
    addTableOptions(cmd, &a->fit, fitRequestOptions());
  else
    addTableOptions(cmd, &a->fit, fitRequestOptions(), {"n"});
}

Expected<FitRequest> fitRequest(const FitArgs& a) {
  FitRequest r;
  for (const auto& [name, text] : a.fit.given())
    if (Status st = setFitRequestOption(&r, name, text); !st) return st.error();
  return r;
}

Expected<FitOptions> fitOptions(const FitArgs& a) {
  auto request = fitRequest(a);
  if (!request) return request.error();
  return fitOptions(*request, a.quiet);
}

FitOptions fitOptions(const FitRequest& request, bool quiet) {
  FitOptions fo = fitOptionsFor(request);
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (!quiet)
    fo.progress = [tty](const FitProgress& p) {
      if (tty)
        std::fprintf(stderr, "\r%-10s round %3d  outside volume %.6g  spheres %d  %.1f s   ",
                     p.phase.c_str(), p.iteration, p.energy, p.spheres, p.seconds);
      else
        std::fprintf(stderr, "%s round %d outside volume %.6g spheres %d %.1f s\n", p.phase.c_str(),
                     p.iteration, p.energy, p.spheres, p.seconds);
      if (tty && p.phase == "done") std::fprintf(stderr, "\n");
    };
  return fo;
}

std::string coverageGaps(const EvalResult& r) {
  char buf[160];
  std::string gaps;
  if (!r.surface_covered) {
    std::snprintf(buf, sizeof buf,
                  "surface not covered (max gap %.3g of the diagonal, %lld triangles not covered)",
                  r.max_surface_gap, static_cast<long long>(r.uncovered_triangles));
    gaps = buf;
  }
  // The interior counts as uncovered whenever the surface is; report it when it has a gap of its
  // own.
  if (!r.interior_covered && (r.surface_covered || r.max_interior_gap > 0.0)) {
    std::snprintf(buf, sizeof buf, "interior not covered (max gap %.3g of the diagonal)",
                  r.max_interior_gap);
    gaps += (gaps.empty() ? "" : ", ") + std::string(buf);
  }
  if (!r.original_covered) {
    std::snprintf(buf, sizeof buf,
                  "original triangles not covered (max gap %.3g of the diagonal, %lld "
                  "triangles)",
                  r.max_original_gap, static_cast<long long>(r.original_uncovered_triangles));
    gaps += (gaps.empty() ? "" : ", ") + std::string(buf);
  }
  return gaps;
}

int coverageExit(const std::string& mesh, const std::string& what, const std::string& out,
                 const EvalResult& r, std::ostream& err) {
  const std::string gaps = coverageGaps(r);
  if (gaps.empty()) return kOk;
  err << "sphereset: " << mesh << ": " << what << " failed the coverage check: " << gaps
      << " (written to " << out << " anyway)\n";
  return kUncovered;
}

std::string jsonText(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

Status writeCurve(const std::string& path, const std::vector<CurvePoint>& points) {
  std::string text = "n,er_sum,protrusion,covered,meets,seconds\n";
  for (const CurvePoint& p : points) {
    char line[160];
    std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%d,%d,%.3f\n", p.n, p.er_sum, p.protrusion,
                  p.covered ? 1 : 0, p.meets ? 1 : 0, p.seconds);
    text += line;
  }
  return writeTextFile(path, text);
}

nlohmann::json curvePointJson(const CurvePoint& p) {
  return {{"n", p.n},
          {"er_sum", p.er_sum},
          {"protrusion", p.protrusion},
          {"covered", p.covered},
          {"meets", p.meets},
          {"seconds", p.seconds}};
}

}  // namespace sphereset::cli

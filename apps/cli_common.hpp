// Pieces shared by the sphereset subcommands: exit codes and how library errors map to them,
// the one-line error printing, mesh loading, the fit options of `fit` and `tree`, the coverage
// check of their results, and JSON helpers.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/exit_codes.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/options.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/result_fields.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset::cli {

// Exit codes: the library's table for every door (exit_codes.hpp), by their short names here.
enum Exit {
  kOk = kExitOk,
  kInternal = kExitInternal,
  kUsage = kExitUsage,
  kUnreadable = kExitUnreadable,
  kInvalid = kExitInvalid,
  kNotSolid = kExitNotSolid,
  kWrite = kExitWrite,
  kUncovered = kExitUncovered,
  kItemsFailed = kExitItemsFailed,
  kNoPage = kExitNoPage,
  kToleranceNotMet = kExitToleranceNotMet,
};

// Progress of a long command on stderr, "COMMAND: STAGE done/total, ITEM (elapsed)": on a
// terminal one line rewritten in place; in a log a line at each tenth of a stage and at its end,
// so that a long run says where it is without flooding the log.
class ProgressLine {
 public:
  explicit ProgressLine(std::string command);
  void show(const std::string& stage, int64_t done, int64_t total, const std::string& item);

 private:
  std::string command_;
  std::chrono::steady_clock::time_point t0_;
  bool tty_;
  std::string stage_;
  int64_t tenth_ = -1;
};

// The exit code for a library error.
int exitFor(const Error& e);

// Prints the error as one line on stderr and returns its exit code.
int fail(const Error& e);

// kOk when this build has the view's page; else its one-line message and kNoPage.
int requirePage();

nlohmann::json vec(const Vec3& v);

// A result's fields (result_fields.hpp) as a JSON object; "group.name" nests.
nlohmann::json fieldsJson(const std::vector<ResultField>& fields);

// The mesh argument and how a mesh that is not a clean solid is made one (repair.hpp).
struct TableArgs {
  std::map<std::string, std::string> text;                // row name -> the text given
  std::map<std::string, std::vector<std::string>> items;  // keyed rows: every KEY=VALUE given
  std::map<std::string, CLI::Option*> options;            // row name -> its flag
  // The rows given on the command line, in the table's order (a keyed row once per item).
  std::vector<std::pair<std::string, std::string>> given() const;
};

// One flag per row of `table` (help with the row's default), except the rows named in `skip`.
void addTableOptions(CLI::App* cmd, TableArgs* a, std::span<const OptionSpec> table,
                     std::initializer_list<std::string_view> skip = {});

// What every door that reads a robot takes: --package-path (repeatable) and --collision-group
// (an MJCF's collision geoms by group), as RobotLoadOptions.
struct RobotLoadArgs {
  std::vector<std::string> package_paths;
  int collision_group = -1;
  bool given() const { return !package_paths.empty() || collision_group != -1; }
};
// `when` opens each option's help ("Robot: ", "With a robot as MESH: ").
void addRobotLoadArgs(CLI::App* cmd, RobotLoadArgs* a, const std::string& when);
RobotLoadOptions robotLoadOptions(const RobotLoadArgs& a);

struct MeshArgs {
  std::string path;
  TableArgs repair;  // the rows of repairOptionTable() given (weld tolerance, repair, wrap)
  bool fill_cavities = true;
};

// `repair`: whether the repair options are added (commands that fit or measure) or only the
// weld tolerance (commands that draw).
void addMeshArgs(CLI::App* cmd, MeshArgs* a, bool repair = true);

// The repair table's weld row alone, for commands that load meshes without repairing them.
void addWeldArg(CLI::App* cmd, MeshArgs* a);

// The repair options alone (the rows of repairOptionTable() and --fill-cavities/
// --keep-cavities), for commands whose meshes come from elsewhere (robot, batch).
void addRepairArgs(CLI::App* cmd, MeshArgs* a);

// The repair options the arguments ask for, with the union and the wrapping of this build;
// kInvalidArgument from the library's table for a value outside its row.
Expected<RepairOptions> repairOptions(const MeshArgs& a);

// Loading as the diagnosis and the pictures see a mesh: exactly welded, or welded with the
// tolerance given (the automatic tolerance welds exactly here).
LoadOptions loadOptions(const RepairOptions& ro);
Expected<LoadOptions> loadOptions(const MeshArgs& a);

// A loaded mesh and the solid made of it (repair.hpp).
using SolidInput = sphereset::SolidInput;

// Loads the mesh and makes a solid of it (or says why it cannot).
Expected<SolidInput> loadSolid(const MeshArgs& a);

// --joint-positions JOINT=VALUE,... (radians or metres) for joints of the robot; empty text
// gives no values (every joint at 0). kInvalidArgument names the bad item; the library's
// jointState checks the names and values, and its notes (values clamped to the limits) are
// printed as warnings.
Expected<std::map<std::string, double>> parseJointPositions(const std::string& text,
                                                            const Robot& robot);

// The "repair" object of the JSON summaries.
nlohmann::json repairJson(const RepairResult& r);

// One line for the summaries on stderr, e.g. "repair: wrapped (...)"; empty for "none".
std::string repairLine(const RepairResult& r);

// The options of a library option table (options.hpp) as the user typed them: one flag per row,
// the text handed to the library's setter unchanged.
// Fit options shared by `fit` and `tree`.
struct FitArgs {
  MeshArgs mesh;
  TableArgs fit;  // the rows of fitRequestOptions()
  std::string out_path, link_name;
  bool quiet = false;
};

// `count_option`: whether -n is added here (`fit`, from the table) or by the caller with its own
// meaning (`tree`).
void addFitArgs(CLI::App* cmd, FitArgs* a, bool count_option);

// The options that tune the fit (every row of fitRequestOptions() but n, and n too when
// `count_option`), part of addFitArgs; for commands with their own input and output options
// (batch).
void addFitTuningArgs(CLI::App* cmd, FitArgs* a, bool count_option = false);

// The fit the parsed options ask for: the quality preset and the options given explicitly, as
// the library's setFitRequestOption parses them (its message for a bad value).
Expected<FitRequest> fitRequest(const FitArgs& a);

// fitOptionsFor(request) with the progress on stderr unless `quiet`.
FitOptions fitOptions(const FitRequest& request, bool quiet);

// fitOptions(fitRequest(a), a.quiet).
Expected<FitOptions> fitOptions(const FitArgs& a);

// What eval's coverage certificate does not confirm in `r`, e.g. "surface not covered (max gap
// 0.002 of the diagonal, 3 triangles not covered)"; empty when surface and interior are covered.
std::string coverageGaps(const EvalResult& r);

// The exit code of a command whose result `what` (fitted from `mesh`, written to `out`) was
// evaluated as `r`: kOk when the surface and the interior are covered; otherwise kUncovered,
// after one line on `err` naming the mesh and what is not covered.
int coverageExit(const std::string& mesh, const std::string& what, const std::string& out,
                 const EvalResult& r, std::ostream& err = std::cerr);

// JSON text for stdout and the command's files: invalid UTF-8 in strings (file names are bytes)
// replaced by U+FFFD instead of nlohmann's exception (a fit of "l\xff.stl" used to end in an
// internal error after the work was done).
std::string jsonText(const nlohmann::json& j, int indent = -1);

// Points of a curve (a tolerance search's counts tried, or `curve`'s counts) as CSV: n, E_r,
// certified protrusion, covered, meets, seconds; written atomically.
Status writeCurve(const std::string& path, const std::vector<CurvePoint>& points);

// A curve point as the JSON summaries give it: n, er_sum, protrusion, covered, meets, seconds.
nlohmann::json curvePointJson(const CurvePoint& p);

}  // namespace sphereset::cli

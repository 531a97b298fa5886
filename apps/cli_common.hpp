// Pieces shared by the sphereset subcommands: exit codes and how library errors map to them,
// the one-line error printing, mesh loading, the fit options of `fit` and `tree`, and JSON
// helpers.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "sphereset/fit.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset::cli {

// Exit codes, listed under --help (kExitCodesHelp) and in the README.
enum Exit {
  kOk = 0,
  kInternal = 1,
  kUsage = 2,
  kUnreadable = 3,
  kInvalid = 4,
  kNotSolid = 5,
  kWrite = 6,
};

// The footer of --help.
inline constexpr const char* kExitCodesHelp =
    "Exit codes: 0 success, 1 internal error, 2 bad options, 3 unreadable input,\n"
    "4 invalid data, 5 mesh is not a closed solid, 6 output could not be written.";

// The exit code for a library error.
int exitFor(const Error& e);

// Prints the error as one line on stderr and returns its exit code.
int fail(const Error& e);

nlohmann::json vec(const Vec3& v);

// The mesh argument and the weld tolerance of the commands that load a mesh.
struct MeshArgs {
  std::string path;
  double weld = 0.0;
};

void addMeshArgs(CLI::App* cmd, MeshArgs* a);

// If the mesh is open and welding within 1e-7 of its diagonal makes it a solid, the option to
// pass ("--weld-tolerance X"); empty otherwise.
std::string weldHint(const MeshArgs& a, const MeshDiagnosis& d);

// Loads and requires a closed solid.
Expected<LoadedMesh> loadSolid(const MeshArgs& a);

// Fit options shared by `fit` and `tree`.
struct FitArgs {
  MeshArgs mesh;
  FitOptions fit;
  std::string out_path, link_name, quality = "default", optimizer = "powell", init = "fps",
                                   method = "variational";
  bool quiet = false;
  int64_t points = 0;
};

// `count_option`: whether -n is added here (`fit`) or by the caller with its own meaning
// (`tree`).
void addFitArgs(CLI::App* cmd, FitArgs* a, bool count_option);

// Turns the parsed options into FitOptions: quality presets, optimiser, seeding, progress.
FitOptions fitOptions(const FitArgs& a, const CLI::App* cmd);

}  // namespace sphereset::cli

// One definition of each result's fields: the name every front door gives a field, its value and
// what it means (the robot's and the animation's lists are in robot_fit.hpp and animate.hpp). The
// command line's --json summaries and the Python module's result objects (their classes generated
// from these lists, scripts/update_stubs.sh) are made from them, so a field is named, typed and
// documented once.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/mesh_defects.hpp"
#include "sphereset/repair.hpp"

namespace sphereset {

struct ResultField {
  const char* name;  // "er_sum"; a dot nests the field in a group ("seconds.total")
  std::variant<bool, int64_t, double, std::string, std::vector<double>, std::vector<int64_t>,
               std::vector<std::string>>
      value;
  const char* help;
};

// A fit's diagnostics (FitResult without its spheres): E_r before and after the bound against
// `mesh_volume` (the solid's), counts of each phase, the timings ("seconds.*"). A default
// FitResult gives the names and types alone.
std::vector<ResultField> fitResultFields(const FitResult& r, double mesh_volume);

// An evaluation's figures (EvalResult): E_r summed and of the union, the certificates with
// their gaps, proximity and shadow errors.
std::vector<ResultField> evalResultFields(const EvalResult& r);

// What the repair did (RepairResult without its meshes): kind, weld tolerance, counts of each
// step, the solid's triangles and volume, the volume ratio (NaN where undefined: null in JSON),
// the wrap's parameters (0 unless wrapped), time and notes.
std::vector<ResultField> repairResultFields(const RepairResult& r);

// A mesh's diagnosis: counts, the closed/manifold/oriented/solid flags, volume, area, bounding
// box ("bbox_min", "bbox_max" as x, y, z) and edge lengths.
std::vector<ResultField> meshDiagnosisFields(const MeshDiagnosis& d);

// A shell analysis's counts (countShells).
std::vector<ResultField> shellCountFields(const ShellCounts& c);

// How a file became a mesh (LoadReport without its maps): the file's counts and what the
// clean-up merged, dropped or flipped.
std::vector<ResultField> loadReportFields(const LoadReport& r);

}  // namespace sphereset

// Turning the meshes users have into a solid the fit can run on, while keeping the original
// triangles: the fit then bounds both (FitOptions::original, EvalOptions::original).
//
// The ladder, first step that yields a clean solid wins:
//   none     the mesh is a clean solid: closed, 2-manifold, oriented, no self-intersections,
//            shells apart (nested shells are allowed: an inward one is a cavity);
//   welded   welding vertices within a tolerance (at most kAutoWeldRel of the bounding box
//            diagonal unless given) closes it;
//   reoriented  flipping triangles to a consistent orientation (across two-triangle edges)
//            makes every shell clean;
//   capped   its boundary loops, closed by triangulations of their own vertices, make every
//            shell clean;
//   union    every shell is clean but some cross (the union of the shells by corefinement) or
//            nest (shells dropped or cavities filled, no computation);
//   wrapped  anything else (open, non-manifold, inconsistently oriented, self-intersecting):
//            CGAL's 3D Alpha Wrapping, a watertight 2-manifold that contains every triangle.
// Shells nested inside another with the same orientation add nothing and are dropped; inward
// shells inside another are cavities, filled by default (RepairOptions::fill_cavities).
//
// The union and the wrapping are given by the caller (RepairOptions::operations): the
// sphereset_repair library (GPL, CGAL; repair_cgal.hpp) provides them. Without them the meshes
// that need them are refused.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/mesh_defects.hpp"
#include "sphereset/options.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// Largest weld tolerance tried automatically, relative to the bounding box diagonal.
inline constexpr double kAutoWeldRel = 1e-6;

// The operations of the repair that a library outside the MIT-licensed core performs:
// sphereset_repair (GPL, CGAL) provides them as cgalSolidOperations() (repair_cgal.hpp).
struct SolidOperations {
  // The union of clean closed outward-oriented shells.
  std::function<Expected<Mesh>(const std::vector<Mesh>& shells)> unite;
  // A watertight 2-manifold outward-oriented mesh without self-intersections that strictly
  // contains every triangle of the soup; alpha and offset are absolute lengths.
  std::function<Expected<Mesh>(const Mesh& soup, double alpha, double offset)> wrap;
};

enum class RepairKind { kNone, kWelded, kReoriented, kCapped, kUnion, kWrapped };
// "none", "welded", "reoriented", "capped", "union", "wrapped"
const char* repairName(RepairKind k);

struct RepairOptions {
  bool enabled = true;  // false: only a clean solid is accepted (the others are refused)
  // Weld tolerance, absolute. Negative: automatic (exact welding, then up to kAutoWeldRel of
  // the diagonal if that closes the mesh).
  double weld_tolerance = -1.0;
  // Fill cavities (inward shells inside another shell, and holes the wrap could otherwise
  // enter). A hollow casing is filled by default: for collision, its inside cannot be reached
  // without crossing its walls, and spheres that bound the walls cover it anyway.
  bool fill_cavities = true;
  // Alpha Wrapping parameters, absolute lengths; 0 chooses them from the mesh (repair.cpp).
  double wrap_alpha = 0.0;
  double wrap_offset = 0.0;
  // The link envelope (envelope.cpp): after the steps above have made the walls a solid,
  // openings narrower than this length are closed and the hollow behind them counts as inside
  // (a wrap from outside whose carving ball is this wide). 0: off, the walls are the solid;
  // kAutomatic (options.hpp): the smallest extent of the walls' bounding box, so a casing or
  // tube is closed and a shape wide open on a side is not; an envelope that then encloses no
  // hollow (less than 1.5 times the walls' volume: it would only round concavities) is dropped
  // and the walls stay the solid (RepairResult::fill_openings 0). The original triangles and the
  // walls stay in the result, for the certificate and for E_r against the walls.
  double fill_openings = 0.0;
  // With fill_openings kAutomatic: keep the envelope whatever its volume (the robot's
  // link_solid_for LINK=envelope, a user's choice for one link, overrules the hollow rule).
  bool keep_envelope = false;
  // The union and the wrapping; when empty, meshes that need them are refused.
  SolidOperations operations;
};

// The repair's options as one table (options.hpp): repair (auto or off: `enabled`),
// weld_tolerance (absolute; automatic when not given), wrap_alpha and wrap_offset (absolute; 0
// chooses them from the mesh), fill_openings (absolute, 0 off, "auto" chosen from the mesh). The
// command line's flags, the Dask batch's flags and the Python keywords are made from it.
// (fill_cavities is a switch of its own: --fill-cavities and
// --keep-cavities.)
std::span<const OptionSpec> repairOptionTable();
// Sets the option `name` from `text` as a user typed it. kInvalidArgument names the option and
// the accepted values ("wrap_alpha 'nan': expected a number from 0 to 1e+30").
Status setRepairOption(RepairOptions* o, const std::string& name, const std::string& text);
// kInvalidArgument, with setRepairOption's message, when a value is outside its row (NaN,
// infinite, negative alpha or offset, beyond 1e30); a negative weld tolerance is the automatic
// one. repairMesh checks its options with it.
Status checkRepairOptions(const RepairOptions& o);

struct RepairResult {
  // Closed, 2-manifold, oriented outward, free of crossings (a union rounded to doubles may
  // keep triangle pairs that touch, reported in the notes): what is fitted.
  Mesh solid;
  Mesh original;  // the input's triangles (exactly welded, degenerate ones dropped)
  RepairKind kind = RepairKind::kNone;
  MeshDiagnosis diagnosis;                     // of the input (exact welding)
  ShellAnalysis shells;                        // of the input after welding
  double weld_tolerance = 0.0;                 // used (0: exact)
  int64_t triangles_flipped = 0;               // by the consistent orientation
  int64_t holes_capped = 0;                    // boundary loops closed
  int64_t shells_dropped = 0;                  // nested inside another with the same orientation
  int64_t cavities_filled = 0;                 // inward shells dropped (fill_cavities)
  int64_t cavities_kept = 0;                   // inward shells kept as cavities
  double wrap_alpha = 0.0, wrap_offset = 0.0;  // when wrapped
  // The envelope (RepairOptions::fill_openings): the opening size used (0: none, `solid` is the
  // walls) and the walls, the solid before the openings were closed (empty without an envelope).
  double fill_openings = 0.0;
  Mesh walls;
  // Volume of the solid over the input's, when the input's is defined: its shells clean and
  // apart (the nested ones as planned), or the input closed with every edge traversed as often
  // each way (|signed volume|, regions wound twice counting twice); NaN otherwise.
  double volume_ratio = 0.0;
  double seconds = 0.0;
  std::vector<std::string> notes;  // one sentence per step taken, for the summary
};

// The input's triangles when the solid differs from them (the fit and the evaluation must bound
// them too: FitOptions::original, EvalOptions::original), else null: a repair that changed
// anything, dropped shells, filled cavities or closed openings. Points into `r`.
const Mesh* originalTriangles(const RepairResult& r);
// The walls when the solid is their envelope (EvalOptions::walls, for E_r against them), else
// null. Points into `r`.
const Mesh* envelopeWalls(const RepairResult& r);
// "envelope" when the solid is the walls' envelope, else "walls": the result fields' `solid`.
inline const char* solidName(const RepairResult& r) {
  return envelopeWalls(r) ? "envelope" : "walls";
}

// Repairs `mesh` (as loadMesh returns it, welded exactly). `name` prefixes error messages.
// Errors: kNotSolid when the mesh needs a repair that is disabled or unavailable,
// kInvalidData when nothing solid can be made of it (no triangles with area).
Expected<RepairResult> repairMesh(const Mesh& mesh, const RepairOptions& options,
                                  const std::string& name);

}  // namespace sphereset

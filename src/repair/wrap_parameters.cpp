// The wrapping's parameters and limits (wrap_parameters.hpp). The wrap itself is CGAL's 3D Alpha
// Wrapping (Portaneri, Rouxel-Labbé, Hemmer, Cohen-Steiner, Alliez 2022), in src/repair_cgal.
#include "repair/wrap_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "sphereset/limits.hpp"

namespace sphereset::detail {
namespace {

// Automatic wrap parameters. CGAL 5.5's wrapping time grows with the number of triangles it
// outputs, about kWrapTrianglesPerArea * area / alpha^2 for an offset of alpha / 20 (measured on
// the benchmark meshes: spot gives 5.0k triangles at alpha = d/50), at a rate that falls with
// the input's size (about 10k triangles per second for small inputs, 3k at 86k input triangles).
// Alpha is the smallest that keeps the predicted output within what kWrapSeconds allows, so a
// mesh with little surface for its size (a compact link) is wrapped more tightly than one with
// much (a chair's thin legs), and a large input more coarsely; it stays between d/100 and d/50
// of the bounding box diagonal d. The offset is alpha / 20.
constexpr double kWrapTrianglesPerArea = 2.35;
constexpr double kWrapRate = 10000.0;           // output triangles per second, small inputs
constexpr double kWrapRateHalfInput = 37000.0;  // input triangles at which the rate halves
constexpr double kWrapSeconds = 0.5;
constexpr double kWrapAlphaMinRel = 1.0 / 100.0, kWrapAlphaMaxRel = 1.0 / 50.0;
constexpr double kWrapOffsetOfAlpha = 1.0 / 20.0;
// Limits of a wrap, checked before CGAL runs. Its exact arithmetic raises a floating-point
// signal in GMP (a double overflowing to infinity) when coordinates, alpha or offset are
// astronomically large (seen at 1e80 and at alpha 1e200), and its time grows with the output:
// alpha and offset at most kWrapMaxSizeRel times the diagonal, coordinates (units of the mesh)
// at most limits::kMaxCoordinate, and, for an alpha or offset the user chose, at most
// kMaxWrapTriangles (wrap_parameters.hpp) predicted output triangles.
constexpr double kWrapMaxSizeRel = 100.0;

}  // namespace

std::string numberFormat(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

void wrapParameters(const Mesh& m, const RepairOptions& o, double* alpha, double* offset) {
  const double diag = boundingBox(m).diagonal();
  const double rate =
      kWrapRate / (1.0 + static_cast<double>(m.triangles.size()) / kWrapRateHalfInput);
  const double budget = rate * kWrapSeconds;  // output triangles
  const double fit = std::sqrt(kWrapTrianglesPerArea * surfaceArea(m) / budget);
  *alpha = o.wrap_alpha > 0.0 ? o.wrap_alpha
                              : std::clamp(fit, kWrapAlphaMinRel * diag, kWrapAlphaMaxRel * diag);
  *offset = o.wrap_offset > 0.0 ? o.wrap_offset : kWrapOffsetOfAlpha * *alpha;
}

// The output's area is at most about twice the input's (both sides of an open surface) plus the
// offset's sphere and band around it (Steiner's formula with the diagonal for the mean width).
double predictedWrapTriangles(const Mesh& m, double alpha, double offset) {
  const double diag = boundingBox(m).diagonal();
  const double area = 2.0 * surfaceArea(m) + 4.0 * std::numbers::pi * offset * (offset + diag);
  return kWrapTrianglesPerArea * area / (alpha * alpha);
}

Status checkWrap(const Mesh& m, bool user_sized, double alpha, double offset,
                 const std::string& name) {
  const Aabb box = boundingBox(m);
  const double coordinate = std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
  if (!(coordinate <= limits::kMaxCoordinate))
    return Error{ErrorCode::kInvalidData, name + ": coordinates up to " +
                                              numberFormat("%.3g", coordinate) +
                                              " cannot be wrapped (the limit is " +
                                              numberFormat("%.3g", limits::kMaxCoordinate) + ")"};
  const double diag = box.diagonal();
  for (const auto& [what, value] : {std::pair{"wrap_alpha", alpha}, {"wrap_offset", offset}})
    if (!(value <= kWrapMaxSizeRel * diag))
      return Error{ErrorCode::kInvalidArgument,
                   name + ": " + what + " " + numberFormat("%.3g", value) + " is more than " +
                       numberFormat("%.3g", kWrapMaxSizeRel) + " times the mesh's diagonal " +
                       numberFormat("%.3g", diag)};
  if (user_sized) {
    const double predicted = predictedWrapTriangles(m, alpha, offset);
    if (!(predicted <= kMaxWrapTriangles))
      return Error{ErrorCode::kInvalidArgument,
                   name + ": a wrap with alpha " + numberFormat("%.3g", alpha) + " and offset " +
                       numberFormat("%.3g", offset) + " would make about " +
                       numberFormat("%.3g", predicted) + " triangles (the limit is " +
                       numberFormat("%.3g", kMaxWrapTriangles) +
                       "); give a larger wrap_alpha or a smaller wrap_offset"};
  }
  return {};
}

}  // namespace sphereset::detail

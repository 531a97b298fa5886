// The wrapping's parameters (repair.hpp's wrap_alpha and wrap_offset, 0 for automatic) and the
// limits checked before CGAL's 3D Alpha Wrapping runs: shared by the repair's wrap step
// (repair.cpp) and the envelope (envelope.cpp).
#pragma once
#include <string>

#include "sphereset/mesh.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

// Alpha and offset for a wrap of `m`: the options' or the automatic ones.
void wrapParameters(const Mesh& m, const RepairOptions& o, double* alpha, double* offset);

// Whether a wrap of `m` with these parameters stays within the limits (coordinates, alpha and
// offset against the diagonal, and, when `user_sized`, the predicted output size); a one-line
// error naming `name` otherwise.
Status checkWrap(const Mesh& m, bool user_sized, double alpha, double offset,
                 const std::string& name);

// About how many triangles a wrap of `m` makes (CGAL 5.5's time grows with them), and the most a
// wrap sized by a user may make (about a minute: the wrap of a one-triangle mesh of diagonal 1.4
// at offset 2 predicts 0.26M and took 20 s).
double predictedWrapTriangles(const Mesh& m, double alpha, double offset);
inline constexpr double kMaxWrapTriangles = 1e6;

// "%.3g" and the like for messages.
std::string numberFormat(const char* f, double x);

}  // namespace sphereset::detail

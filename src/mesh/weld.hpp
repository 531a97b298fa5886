// Private: vertex welding used by the mesh loader.
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// Welds vertices and returns, for each input vertex, its index in *out. Exact mode (tol <= 0)
// merges bit-identical positions (after -0 -> +0). Tolerance mode snaps to a grid of cell
// `tol` and merges each vertex into the first kept vertex within `tol` in its own or a
// neighbouring cell (deterministic: in input order). Any finite coordinates and tolerance are
// handled: a tolerance below 2^-40 of the median vertex magnitude (far below the resolution
// of the coordinates) uses cells of that size instead, and cell coordinates beyond 2^60 are
// saturated (cell_key.hpp); neither changes which vertices are within `tol` of each other.
std::vector<int32_t> weldVertices(const std::vector<Vec3>& v, double tol, std::vector<Vec3>* out);

}  // namespace sphereset::detail

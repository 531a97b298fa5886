// Vertex welding for the mesh loader: exact (bit-identical positions) or within a tolerance
// on a hash grid of cells of the tolerance's size (cell_key.hpp), raised for tolerances far
// below the resolution of the coordinates.
#include "mesh/weld.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "util/cell_key.hpp"

namespace sphereset::detail {
namespace {

// Grid cells are at least this fraction of the median vertex magnitude (largest absolute
// coordinate): about 4096 ulps of it. A smaller tolerance would put every vertex more than
// 2^60 tolerances from the origin into the saturated outermost cells of cell_key.hpp (one
// cell per octant), where the search for a vertex within the tolerance becomes a scan; with
// this floor only vertices 2^20 times the median magnitude from the origin saturate.
constexpr double kMinCellRel = 0x1.0p-40;

// The cell size for welding within `tol`: tol, or the floor above if that is larger. Any
// cell no smaller than tol finds every vertex within tol in the 27 cells about a vertex.
double weldCell(const std::vector<Vec3>& v, double tol) {
  std::vector<double> magnitude(v.size());
  for (size_t i = 0; i < v.size(); ++i) magnitude[i] = v[i].cwiseAbs().maxCoeff();
  const auto mid = magnitude.begin() + static_cast<ptrdiff_t>(magnitude.size() / 2);
  std::nth_element(magnitude.begin(), mid, magnitude.end());
  return mid == magnitude.end() ? tol : std::max(tol, kMinCellRel * *mid);
}

// Exact mode: bit-identical positions (after -0 -> +0).
std::vector<int32_t> weldExact(const std::vector<Vec3>& v, std::vector<Vec3>* out) {
  // The key is the position itself, not a grid cell: nothing to share with cell_key.hpp.
  struct ExactHash {
    size_t operator()(const Vec3& p) const {
      size_t h = 0;
      for (int k = 0; k < 3; ++k) h = h * 1000003u ^ std::hash<double>()(p[k] + 0.0);
      return h;
    }
  };
  struct ExactEq {
    bool operator()(const Vec3& a, const Vec3& b) const { return a == b; }
  };
  std::vector<int32_t> remap(v.size());
  std::unordered_map<Vec3, int32_t, ExactHash, ExactEq> seen;
  seen.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    auto [it, inserted] = seen.emplace(v[i], static_cast<int32_t>(out->size()));
    if (inserted) out->push_back(v[i]);
    remap[i] = it->second;
  }
  return remap;
}

}  // namespace

std::vector<int32_t> weldVertices(const std::vector<Vec3>& v, double tol, std::vector<Vec3>* out) {
  out->clear();
  if (tol <= 0.0) return weldExact(v, out);
  std::vector<int32_t> remap(v.size());
  const double cell = weldCell(v, tol);
  std::unordered_map<CellKey, std::vector<int32_t>, CellKeyHash> grid;
  const double tol2 = tol * tol;
  for (size_t i = 0; i < v.size(); ++i) {
    const CellKey key = cellKey(v[i], cell);
    int32_t found = -1;
    anyCellAround(key, 1, [&](const CellKey& c) {
      const auto it = grid.find(c);
      if (it == grid.end()) return false;
      for (int32_t j : it->second)
        if (((*out)[j] - v[i]).squaredNorm() <= tol2) {
          found = j;
          return true;
        }
      return false;
    });
    if (found < 0) {
      found = static_cast<int32_t>(out->size());
      out->push_back(v[i]);
      grid[key].push_back(found);
    }
    remap[i] = found;
  }
  return remap;
}

}  // namespace sphereset::detail

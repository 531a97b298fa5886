// Vertex welding for the mesh loader: exact (bit-identical positions) or within a tolerance
// on a hash grid of cell size equal to the tolerance.
#include "mesh/weld.hpp"

#include <array>
#include <cmath>
#include <unordered_map>

#include "util/cell_key.hpp"

namespace sphereset::detail {

std::vector<int32_t> weldVertices(const std::vector<Vec3>& v, double tol, std::vector<Vec3>* out) {
  std::vector<int32_t> remap(v.size());
  out->clear();
  if (tol <= 0.0) {
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
    std::unordered_map<Vec3, int32_t, ExactHash, ExactEq> seen;
    seen.reserve(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
      auto [it, inserted] = seen.emplace(v[i], static_cast<int32_t>(out->size()));
      if (inserted) out->push_back(v[i]);
      remap[i] = it->second;
    }
    return remap;
  }
  std::unordered_map<CellKey, std::vector<int32_t>, CellKeyHash> grid;
  const double tol2 = tol * tol;
  for (size_t i = 0; i < v.size(); ++i) {
    const std::array<int64_t, 3> key = {static_cast<int64_t>(std::floor(v[i].x() / tol)),
                                        static_cast<int64_t>(std::floor(v[i].y() / tol)),
                                        static_cast<int64_t>(std::floor(v[i].z() / tol))};
    int32_t found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx)
      for (int dy = -1; dy <= 1 && found < 0; ++dy)
        for (int dz = -1; dz <= 1 && found < 0; ++dz) {
          auto it = grid.find({key[0] + dx, key[1] + dy, key[2] + dz});
          if (it == grid.end()) continue;
          for (int32_t j : it->second)
            if (((*out)[j] - v[i]).squaredNorm() <= tol2) {
              found = j;
              break;
            }
        }
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

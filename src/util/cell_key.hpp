// Private: integer cell coordinates of a uniform grid and their hash, for the hash grids.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace sphereset::detail {

using CellKey = std::array<int64_t, 3>;

// FNV-1a over the three coordinates.
struct CellKeyHash {
  size_t operator()(const CellKey& k) const {
    size_t h = 1469598103934665603ull;
    for (int64_t v : k) h = (h ^ static_cast<size_t>(v)) * 1099511628211ull;
    return h;
  }
};

}  // namespace sphereset::detail

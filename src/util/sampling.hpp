// Private: seeded random sampling shared by evaluation and fitting.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// A well-mixed 64-bit seed for stream `stream` of run `seed` (SplitMix64 finaliser), so that
// blocks of work get independent generators whatever thread runs them.
inline uint64_t mixSeed(uint64_t seed, uint64_t stream) {
  uint64_t z = seed + 0x9e3779b97f4a7c15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Picks triangles in proportion to area and points uniformly in them.
class SurfaceSampler {
 public:
  explicit SurfaceSampler(const Mesh& mesh);
  Vec3 sample(std::mt19937_64& rng, int32_t* triangle = nullptr) const;
  double area() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }

 private:
  const Mesh& mesh_;
  std::vector<double> cumulative_;
};

}  // namespace sphereset::detail

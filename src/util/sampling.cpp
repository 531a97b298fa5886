// Seeded surface sampling: triangle chosen by area (binary search in the cumulative areas),
// point uniform in the triangle by the square-root parametrisation (Turk, Graphics Gems 1990,
// the reference the paper cites for its surface points).
#include "util/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace sphereset::detail {

SurfaceSampler::SurfaceSampler(const Mesh& mesh) : mesh_(mesh) {
  cumulative_.reserve(mesh.triangles.size());
  double total = 0.0;
  for (const Triangle& t : mesh.triangles) {
    total += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                       .norm();
    cumulative_.push_back(total);
  }
}

Vec3 SurfaceSampler::sample(std::mt19937_64& rng, int32_t* triangle) const {
  const double x = uniform01(rng) * cumulative_.back();
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), x);
  const int32_t t = static_cast<int32_t>(std::min<ptrdiff_t>(
      it - cumulative_.begin(), static_cast<ptrdiff_t>(cumulative_.size()) - 1));
  if (triangle) *triangle = t;
  const double s = std::sqrt(uniform01(rng)), u = uniform01(rng);
  const auto& tri = mesh_.triangles[t];
  return (1.0 - s) * mesh_.vertices[tri[0]] + s * (1.0 - u) * mesh_.vertices[tri[1]] +
         s * u * mesh_.vertices[tri[2]];
}

}  // namespace sphereset::detail

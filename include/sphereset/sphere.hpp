// A sphere: plain data.
#pragma once

#include "sphereset/mesh.hpp"

namespace sphereset {

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  bool contains(const Vec3& p) const { return (p - center).squaredNorm() <= radius * radius; }
};

}  // namespace sphereset

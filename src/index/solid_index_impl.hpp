// Private: the state behind SolidIndex, shared by the query files.
#pragma once

#include "index/bvh.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {

struct SolidIndex::Impl {
  Mesh mesh;
  detail::Bvh bvh;
  Aabb bounds;
  double tolerance = 0.0;  // boundary tolerance, absolute units
};

}  // namespace sphereset

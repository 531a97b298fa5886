// Private: the state behind SolidIndex, shared by the query files.
#pragma once

#include "index/bvh.hpp"
#include "index/sov_memo.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {

struct SolidIndex::Impl {
  Mesh mesh;
  detail::Bvh bvh;
  Aabb bounds;
  double tolerance = 0.0;          // boundary tolerance, absolute units
  detail::SovMemo sov_memo;        // recent outside-volume answers (sov_memo.hpp)
  detail::CentreMemo centre_memo;  // containment of recent centres (sov_memo.hpp)
};

}  // namespace sphereset

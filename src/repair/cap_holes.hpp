// Private: closing the boundary loops of a mesh (repair step "capped").
#pragma once

#include <cstdint>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// Closes each boundary loop of *mesh by Liepa's triangulation (least dihedral angle, then area;
// loops of up to 300 edges) or a fan around a new vertex at the loop's centroid (longer loops).
// Cap triangles traverse the loop's edges opposite to the triangles beside them, so an oriented
// mesh stays oriented. A boundary vertex with several outgoing boundary edges (non-manifold) is
// left by the first unused one. Returns the number of loops closed.
int64_t capHoles(Mesh* mesh);

}  // namespace sphereset::detail

// Private: consistent orientation of the triangles of a mesh (repair step "reoriented").
#pragma once

#include <cstdint>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// Flips triangles so that every edge shared by exactly two triangles is traversed once each
// way, component by component, keeping the orientation most of each component's triangles
// have (outward orientation is settled afterwards, by the sign of each shell's volume and its
// nesting). Edges of
// three or more triangles do not propagate. Returns the number of triangles flipped, or -1
// when some component is not orientable (a Möbius strip, say); *mesh is then unchanged.
int64_t orientConsistently(Mesh* mesh);

}  // namespace sphereset::detail

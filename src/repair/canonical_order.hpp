// Private: a canonical numbering of a mesh's vertices and triangles, so that a repair's output
// does not depend on the order in which an outside library (CGAL's corefinement, the wrap)
// happened to produce it.
#pragma once

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

// Renumbers the vertices in lexicographic order of their coordinates (vertices at the same
// position keep their relative order), starts each triangle at its smallest vertex index
// (orientation kept) and sorts the triangles. Two meshes with the same vertex positions and the
// same triangles, listed in any order, come out identical.
Mesh canonicalOrder(Mesh mesh);

}  // namespace sphereset::detail

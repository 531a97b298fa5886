// Private: the operations of the repair that CGAL performs (GPL-licensed parts of CGAL, so
// they live in the sphereset_repair target only).
#pragma once

#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

// CGAL's 3D Alpha Wrapping of the triangles of `soup` (any soup: open, non-manifold,
// self-intersecting): a closed, 2-manifold, intersection-free, outward-oriented mesh that
// strictly contains every input triangle, at distance about `offset` outside them; cavities
// narrower than about `alpha` are not entered. Both are absolute lengths > 0.
Expected<Mesh> alphaWrap(const Mesh& soup, double alpha, double offset);

// The union of solids, each a clean closed shell (closed, 2-manifold, outward-oriented, free
// of self-intersections), by CGAL's corefinement with exact constructions.
Expected<Mesh> solidUnion(const std::vector<Mesh>& solids);

}  // namespace sphereset::detail

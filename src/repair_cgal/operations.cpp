// sphereset::cgalSolidOperations (repair_cgal.hpp): the union and the wrapping of the repair
// ladder, by CGAL's corefinement (CGAL 5.5 manual, "Polygon Mesh Processing: Corefinement")
// and 3D Alpha Wrapping (CGAL 5.5 manual, "3D Alpha Wrapping"; Portaneri, Rouxel-Labbé,
// Hemmer, Cohen-Steiner, Alliez, "Alpha Wrapping with an Offset", 2022).
//
// Licence: these CGAL packages are GPL-3+, and so is a program linking sphereset_repair (see
// the README's licence section).
#include "repair_cgal/cgal_ops.hpp"
#include "sphereset/repair_cgal.hpp"

namespace sphereset {

SolidOperations cgalSolidOperations() {
  SolidOperations ops;
  ops.unite = [](const std::vector<Mesh>& shells) { return detail::solidUnion(shells); };
  ops.wrap = [](const Mesh& soup, double alpha, double offset) {
    return detail::alphaWrap(soup, alpha, offset);
  };
  return ops;
}

}  // namespace sphereset

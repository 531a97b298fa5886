// A mesh file made a solid as the commands that fit do it (repair.hpp): loadMesh, then the
// repair ladder of repair.cpp. Glue only; the ladder's references are in repair.cpp.
#include <string>
#include <utility>

#include "sphereset/load.hpp"
#include "sphereset/repair.hpp"

namespace sphereset {

const Mesh* SolidInput::original() const { return originalTriangles(repair); }
const Mesh* SolidInput::walls() const { return envelopeWalls(repair); }

Expected<SolidInput> loadSolid(const std::string& path, const RepairOptions& options) {
  auto m = loadMesh(path);
  if (!m) return m.error();
  auto r = repairMesh(m->mesh, options, path);
  if (!r) return r.error();
  return SolidInput{std::move(m).value(), std::move(r).value()};
}

}  // namespace sphereset

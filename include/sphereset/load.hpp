// Reading meshes from files: any format assimp knows (OFF and PLY by the library's own readers),
// cleaned as cleanMesh cleans arrays, and made a solid as the commands that fit do it.
#pragma once

#include <string>

#include "sphereset/mesh.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// Reads OBJ, PLY (ASCII/binary, strips), STL (ASCII/binary), OFF, DAE (scene-graph transforms
// applied), glTF/GLB and any other format assimp knows. Besides the file itself, only the
// companions a format references are opened: .bin buffers, .mtl libraries and files of the same
// stem; any other file a mesh names (e.g. "mtllib /etc/passwd") is treated as missing. Welds,
// triangulates, drops degenerate triangles and reports what was done. Errors: kUnreadable (missing,
// unknown format, parse failure), kInvalidData (no triangles, NaN/Inf coordinates, out-of-range
// indices).
Expected<LoadedMesh> loadMesh(const std::string& path, const LoadOptions& options = {});

// A mesh file made a solid as the commands that fit do it: loadMesh (exact welding only) and
// then repairMesh with `options`.
struct SolidInput {
  LoadedMesh loaded;
  RepairResult repair;
  // The input's triangles when the solid differs from them (the fit and the evaluation must
  // bound them too: FitOptions::original, EvalOptions::original), else null. Points into
  // `repair`: valid while this object lives and is not moved.
  const Mesh* original() const;
  // The walls when the solid is their envelope (EvalOptions::walls), else null (repair.hpp).
  const Mesh* walls() const;
};

// Loads `path` and makes a solid of it. Errors: those of loadMesh and repairMesh, with messages
// that name the file.
Expected<SolidInput> loadSolid(const std::string& path, const RepairOptions& options);

}  // namespace sphereset

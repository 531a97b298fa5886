// Frames of a deforming mesh read from files in the rest mesh's order (animate.hpp:
// loadFrameMesh). Beyond the paper, which takes the deformed vertices as given: a file format
// may list a vertex per face corner (STL, some OBJ), so the frame's vertices are mapped through
// the rest's own clean-up rather than welded again.
#include <string>
#include <utility>
#include <vector>

#include "sphereset/animate.hpp"
#include "sphereset/load.hpp"

namespace sphereset {

Expected<AnimationFrame> loadFrameMesh(const std::string& path, const LoadedMesh& rest) {
  LoadOptions raw_options;
  raw_options.clean = false;
  auto raw = loadMesh(path, raw_options);
  if (!raw) return raw.error();
  const LoadReport& r = rest.report;
  const auto file_vertices = static_cast<int64_t>(raw->mesh.vertices.size());
  const auto file_faces = static_cast<int64_t>(raw->mesh.triangles.size());
  if (file_vertices != r.file_vertices || file_faces != r.file_faces)
    return Error{ErrorCode::kInvalidData,
                 path + ": " + std::to_string(file_vertices) + " vertices and " +
                     std::to_string(file_faces) + " faces, the rest mesh's file " + r.path + " " +
                     std::to_string(r.file_vertices) + " and " + std::to_string(r.file_faces) +
                     " (a frame lists the rest mesh's vertices and faces in its order)"};
  AnimationFrame f;
  f.name = path;
  // Each rest vertex at the position of the first file vertex it was made from.
  f.vertices.assign(rest.mesh.vertices.size(), Vec3::Zero());
  std::vector<char> placed(rest.mesh.vertices.size(), 0);
  for (size_t i = 0; i < r.vertex_of_file.size(); ++i) {
    const int32_t v = r.vertex_of_file[i];
    if (v >= 0 && !placed[v]) {
      f.vertices[v] = raw->mesh.vertices[i];
      placed[v] = 1;
    }
  }
  // The frame's faces in the rest's terms: each rest triangle from the same file face, through
  // the same vertex map (and the same flip). animateSpheres refuses a frame whose faces differ.
  f.triangles.reserve(rest.mesh.triangles.size());
  for (const int64_t face : r.source_face) {
    Triangle t;
    for (int k = 0; k < 3; ++k) t[k] = r.vertex_of_file[raw->mesh.triangles[face][k]];
    if (r.flipped) std::swap(t[1], t[2]);
    f.triangles.push_back(t);
  }
  return f;
}

}  // namespace sphereset

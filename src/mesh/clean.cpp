// The clean-up that turns a file's triangles into an indexed mesh: weld coincident vertices,
// drop degenerate and duplicate triangles, remove unused vertices, orient outward. Every step is
// counted in the LoadReport. Also the mesh's bounding box, volume and area.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "mesh/weld.hpp"
#include "sphereset/mesh.hpp"
#include "util/cell_key.hpp"

namespace sphereset {
using detail::weldVertices;

Aabb boundingBox(const Mesh& mesh) {
  Aabb b;
  for (const Vec3& v : mesh.vertices) b.extend(v);
  return b;
}

double signedVolume(const Mesh& mesh) {
  // Σ det(a, b, c) / 6 about the bounding-box centre (reduces cancellation far from origin).
  const Vec3 o = boundingBox(mesh).center();
  double vol = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - o, b = mesh.vertices[t[1]] - o,
               c = mesh.vertices[t[2]] - o;
    vol += a.dot(b.cross(c));
  }
  return vol / 6.0;
}

double surfaceArea(const Mesh& mesh) {
  double area = 0.0;
  for (const Triangle& t : mesh.triangles)
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .norm();
  return area;
}

Expected<LoadedMesh> cleanMesh(std::vector<Vec3> vertices, std::vector<Triangle> triangles,
                               const LoadOptions& options, std::string name) {
  LoadedMesh out;
  LoadReport& rep = out.report;
  rep.path = name;
  if (rep.file_vertices == 0) rep.file_vertices = static_cast<int64_t>(vertices.size());
  if (rep.file_faces == 0) rep.file_faces = static_cast<int64_t>(triangles.size());
  if (!(options.weld_tolerance >= 0.0) || !std::isfinite(options.weld_tolerance))
    return Error{ErrorCode::kInvalidArgument,
                 name + ": weld tolerance must be a finite number >= 0"};
  for (size_t i = 0; i < vertices.size(); ++i)
    if (!vertices[i].allFinite())
      return Error{ErrorCode::kInvalidData,
                   name + ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate"};
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int32_t k : triangles[t])
      if (k < 0 || static_cast<size_t>(k) >= vertices.size())
        return Error{ErrorCode::kInvalidData, name + ": triangle " + std::to_string(t) +
                                                  " references vertex " + std::to_string(k) +
                                                  " of " + std::to_string(vertices.size())};
  if (triangles.empty())
    return Error{ErrorCode::kInvalidData,
                 name + ": the file contains no triangles (points or lines only, or nothing)"};

  if (!options.clean) {
    rep.vertex_of_file.resize(vertices.size());
    std::iota(rep.vertex_of_file.begin(), rep.vertex_of_file.end(), 0);
    rep.source_face.resize(triangles.size());
    std::iota(rep.source_face.begin(), rep.source_face.end(), 0);
    out.mesh.vertices = std::move(vertices);
    out.mesh.triangles = std::move(triangles);
    return out;
  }
  std::vector<Vec3> welded;
  const std::vector<int32_t> remap = weldVertices(vertices, options.weld_tolerance, &welded);
  rep.welded_vertices = static_cast<int64_t>(vertices.size() - welded.size());

  // Drop triangles with repeated vertices or zero area, and exact duplicates (same vertex
  // set in any order: a doubled face is never part of a manifold solid's boundary).
  std::vector<Triangle> kept;
  kept.reserve(triangles.size());
  std::unordered_map<detail::CellKey, int, detail::CellKeyHash> seen;
  for (size_t face = 0; face < triangles.size(); ++face) {
    const Triangle& t0 = triangles[face];
    const Triangle t = {remap[t0[0]], remap[t0[1]], remap[t0[2]]};
    const Vec3 nrm = (welded[t[1]] - welded[t[0]]).cross(welded[t[2]] - welded[t[0]]);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(nrm.squaredNorm() > 0.0)) {
      ++rep.degenerate_dropped;
      continue;
    }
    std::array<int64_t, 3> key = {t[0], t[1], t[2]};
    std::sort(key.begin(), key.end());
    if (!seen.emplace(key, 1).second) {
      ++rep.duplicate_dropped;
      continue;
    }
    kept.push_back(t);
    rep.source_face.push_back(static_cast<int64_t>(face));
  }
  if (kept.empty())
    return Error{ErrorCode::kInvalidData,
                 name + ": every triangle is degenerate (zero area or repeated vertices)"};

  // Remove unused vertices, keeping first-use order stable by original index.
  std::vector<int32_t> used(welded.size(), -1);
  for (const Triangle& t : kept)
    for (int32_t k : t) used[k] = 0;
  int32_t next = 0;
  for (size_t i = 0; i < welded.size(); ++i)
    if (used[i] == 0) {
      used[i] = next++;
      out.mesh.vertices.push_back(welded[i]);
    }
  rep.unused_vertices = static_cast<int64_t>(welded.size()) - next;
  for (Triangle& t : kept)
    for (int32_t& k : t) k = used[k];
  rep.vertex_of_file.resize(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) rep.vertex_of_file[i] = used[remap[i]];
  out.mesh.triangles = std::move(kept);

  if (options.orient_outward && signedVolume(out.mesh) < 0.0) {
    for (Triangle& t : out.mesh.triangles) std::swap(t[1], t[2]);
    rep.flipped = true;
  }
  return out;
}

}  // namespace sphereset

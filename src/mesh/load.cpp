// Mesh input through assimp, and the clean-up that turns a file's triangles into an indexed
// mesh: weld coincident vertices, drop degenerate and duplicate triangles, remove unused
// vertices, orient outward. Every step is counted in the LoadReport.
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "mesh/companion_io.hpp"
#include "mesh/off_ply.hpp"
#include "mesh/weld.hpp"
#include "sphereset/mesh.hpp"
#include "util/cell_key.hpp"

namespace sphereset {
using detail::weldVertices;

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void collectNode(const aiScene* scene, const aiNode* node, const aiMatrix4x4& parent,
                 std::vector<Vec3>* verts, std::vector<Triangle>* tris, int64_t* meshes,
                 int64_t* file_vertices, int64_t* file_faces, bool* bad_index) {
  const aiMatrix4x4 xf = parent * node->mTransformation;
  for (unsigned m = 0; m < node->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[m]];
    ++*meshes;
    const int64_t base = static_cast<int64_t>(verts->size());
    *file_vertices += mesh->mNumVertices;
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D p = xf * mesh->mVertices[i];
      verts->emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices < 3) continue;  // points and lines are not part of a solid
      // Faces are triangulated by assimp; a remaining polygon is fanned as a safeguard.
      for (unsigned k = 1; k + 1 < face.mNumIndices; ++k) {
        const unsigned idx[3] = {face.mIndices[0], face.mIndices[k], face.mIndices[k + 1]};
        Triangle t;
        for (int c = 0; c < 3; ++c) {
          if (idx[c] >= mesh->mNumVertices) {
            *bad_index = true;
            t[c] = 0;
          } else {
            t[c] = static_cast<int32_t>(base + idx[c]);
          }
        }
        tris->push_back(t);
        ++*file_faces;
      }
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c)
    collectNode(scene, node->mChildren[c], xf, verts, tris, meshes, file_vertices, file_faces,
                bad_index);
}

}  // namespace

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

Expected<LoadedMesh> loadMesh(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    return Error{ErrorCode::kUnreadable, path + ": no such file"};
  if (std::filesystem::is_directory(path, ec))
    return Error{ErrorCode::kUnreadable, path + ": is a directory, not a mesh file"};
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) return Error{ErrorCode::kUnreadable, path + ": cannot be opened for reading"};
    if (probe.peek() == std::ifstream::traits_type::eof())
      return Error{ErrorCode::kUnreadable, path + ": the file is empty"};
  }
  // OFF and PLY are parsed by the project's own readers: Debian 12's assimp (5.2) reads one
  // face too few from an OFF file with comment lines between its header and its faces, and
  // keeps only part of a PLY triangle strip (one triangle of a five-vertex strip).
  const std::string ext = lowerExtension(path);
  if (ext == "off" || ext == "ply") {
    auto raw = ext == "off" ? detail::readOff(path) : detail::readPly(path);
    if (!raw) return raw.error();
    const int64_t nv = static_cast<int64_t>(raw->vertices.size());
    const int64_t nf = static_cast<int64_t>(raw->triangles.size());
    auto cleaned = cleanMesh(std::move(raw->vertices), std::move(raw->triangles), options, path);
    if (!cleaned) return cleaned.error();
    LoadedMesh out = std::move(cleaned).value();
    out.report.format = ext;
    out.report.scene_meshes = 1;
    out.report.file_vertices = nv;
    out.report.file_faces = nf;
    out.report.files = {path};
    return out;
  }
  if (Status st = detail::checkBeforeAssimp(path); !st) return st.error();
  Assimp::Importer importer;
  auto* io = new detail::CompanionIOSystem(path);  // owned by the importer
  importer.SetIOHandler(io);
  // No normals, no vertex joining (we weld positions ourselves, since assimp joins only
  // vertices whose every attribute matches). Points and lines are kept in the scene and
  // skipped when collecting (collectNode), so that a file of only points or lines is reported
  // as having no triangles rather than as unreadable.
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unknown format";
    return Error{ErrorCode::kUnreadable, path + ": cannot be read as a mesh (" + why + ")"};
  }
  std::vector<Vec3> verts;
  std::vector<Triangle> tris;
  int64_t meshes = 0, file_vertices = 0, file_faces = 0;
  bool bad_index = false;
  collectNode(scene, scene->mRootNode, aiMatrix4x4(), &verts, &tris, &meshes, &file_vertices,
              &file_faces, &bad_index);
  if (bad_index)
    return Error{ErrorCode::kInvalidData, path + ": a face references a vertex out of range"};
  if (tris.empty())
    return Error{ErrorCode::kInvalidData,
                 path + ": the file contains no triangles (points or lines only, or nothing)"};
  auto cleaned = cleanMesh(std::move(verts), std::move(tris), options, path);
  if (!cleaned) return cleaned.error();
  LoadedMesh out = std::move(cleaned).value();
  out.report.format = lowerExtension(path);
  out.report.scene_meshes = meshes;
  out.report.file_vertices = file_vertices;
  out.report.file_faces = file_faces;
  out.report.files = io->files();
  return out;
}

}  // namespace sphereset

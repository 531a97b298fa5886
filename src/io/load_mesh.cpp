// Mesh input: the project's own OFF and PLY readers and assimp for every other format, then
// the clean-up of cleanMesh (mesh/clean.cpp).
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/companion_io.hpp"
#include "io/off_ply.hpp"
#include "sphereset/load.hpp"
#include "util/read_file.hpp"

namespace sphereset {

namespace {

// "obj" for "a/b.OBJ": the format's name as the load report gives it.
std::string lowerExtension(const std::string& path) {
  const std::string ext = detail::extensionOf(path);
  return ext.empty() ? ext : ext.substr(1);
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
  // assimp reads coordinates in single precision: a value beyond float's range (1e80, say)
  // arrives as infinity, which the clean-up would call "NaN or infinite".
  for (size_t i = 0; i < verts.size(); ++i)
    if (!verts[i].allFinite())
      return Error{ErrorCode::kInvalidData,
                   path + ": vertex " + std::to_string(i) +
                       " has a coordinate that is NaN or beyond 3.4e+38 (this format is read in "
                       "single precision)"};
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

// Triangle meshes: plain data, loading through assimp, and diagnosis of broken solids.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "sphereset/status.hpp"

namespace sphereset {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int32_t, 3>;

// An indexed triangle mesh. A solid is expected to be closed and oriented with outward
// normals (counter-clockwise vertex order seen from outside).
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

struct Aabb {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Aabb& b) {
    min = min.cwiseMin(b.min);
    max = max.cwiseMax(b.max);
  }
  bool empty() const { return !(min.array() <= max.array()).all(); }
  Vec3 center() const { return 0.5 * (min + max); }
  double diagonal() const { return empty() ? 0.0 : (max - min).norm(); }
};

Aabb boundingBox(const Mesh& mesh);

struct LoadOptions {
  // Vertices closer than this (absolute units) are merged. 0 merges exactly coincident
  // positions only, which is what STL and per-corner OBJ/PLY files need.
  double weld_tolerance = 0.0;
  // Flip every triangle when the signed volume is negative (the mesh is inside out).
  bool orient_outward = true;
  // false: the file's vertices and triangles as they are (no welding, nothing dropped or
  // flipped), e.g. to read a deformed copy of a mesh vertex by vertex (loadFrameMesh).
  bool clean = true;
};

// What the loader did to the file's data to make an indexed triangle mesh.
struct LoadReport {
  std::string path;
  std::string format;              // file extension, lower case, without the dot
  int64_t file_vertices = 0;       // vertices as stored in the file (all meshes)
  int64_t file_faces = 0;          // faces after triangulation, before clean-up
  int64_t scene_meshes = 0;        // meshes in the file's scene graph
  int64_t welded_vertices = 0;     // vertices merged into another one
  int64_t unused_vertices = 0;     // vertices referenced by no kept triangle, removed
  int64_t degenerate_dropped = 0;  // triangles with repeated vertices or zero area, dropped
  int64_t duplicate_dropped = 0;   // triangles repeating another's vertex set, dropped
  bool flipped = false;            // orientation was reversed to make the volume positive
  // How the clean-up maps the file's data (as the reader lists it) to the mesh: the mesh vertex
  // of each file vertex (-1: unused), and the file face of each mesh triangle.
  std::vector<int32_t> vertex_of_file;
  std::vector<int64_t> source_face;
  // Every file read, the mesh first, then the companions its format references as the reader
  // opened them (a glTF's .bin buffers, an OBJ's .mtl): what the mesh depends on.
  std::vector<std::string> files;
};

struct LoadedMesh {
  Mesh mesh;
  LoadReport report;
};

// Builds a mesh from raw arrays with the same clean-up as loadMesh (used for in-memory data).
Expected<LoadedMesh> cleanMesh(std::vector<Vec3> vertices, std::vector<Triangle> triangles,
                               const LoadOptions& options = {}, std::string name = "mesh");

// Topological and geometric facts about a mesh.
struct MeshDiagnosis {
  int64_t vertices = 0;
  int64_t triangles = 0;
  int64_t edges = 0;
  int64_t boundary_edges = 0;        // edges with one incident triangle
  int64_t nonmanifold_edges = 0;     // edges with three or more incident triangles
  int64_t nonmanifold_vertices = 0;  // vertices whose triangle fan is not one disk or cone
  int64_t misoriented_edges = 0;     // interior edges traversed the same way by both triangles
  int64_t components = 0;            // edge-connected components
  bool closed = false;               // no boundary edges
  bool manifold = false;             // no non-manifold edges or vertices
  bool oriented = false;             // every interior edge traversed once each way
  double volume = 0.0;               // signed volume (positive for outward orientation)
  double area = 0.0;
  Aabb bbox;
  double min_edge = 0.0;
  double max_edge = 0.0;

  // Closed, manifold and consistently oriented with positive volume: what fitting needs.
  bool isSolid() const { return closed && manifold && oriented && volume > 0.0; }
};

MeshDiagnosis diagnoseMesh(const Mesh& mesh);

// Error for a mesh that is not a solid: one line naming the path and the counts.
Error notSolidError(const std::string& path, const MeshDiagnosis& d);

double signedVolume(const Mesh& mesh);
double surfaceArea(const Mesh& mesh);

}  // namespace sphereset

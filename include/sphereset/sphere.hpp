// Spheres and sphere sets: plain data and file formats.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  bool contains(const Vec3& p) const { return (p - center).squaredNorm() <= radius * radius; }
};

enum class SphereFormat {
  kText,  // "x y z r" per line, '#' starts a comment
  kJson,  // {"spheres": [{"center": [x, y, z], "radius": r}, ...], ...metadata}
  kSph,   // Bradshaw's sphere-tree layout; a flat set is written as root + one level
  kYaml,  // cuRobo-style "collision_spheres:" list under a link name
};

// Format from a file name's extension (.txt/.xyzr, .json, .sph, .yaml/.yml); kInvalidArgument
// for anything else.
Expected<SphereFormat> sphereFormatFromPath(const std::string& path);

struct SphereFileMeta {
  std::string name = "object";  // link name for YAML output
  std::string source_mesh;      // recorded in JSON output
  std::string generator = "sphereset";
};

// Reads a sphere set in the format given by the extension. For .sph files the deepest level
// with spheres of positive radius is returned. Errors: kUnreadable, kInvalidData (NaN, negative
// radius, malformed line; the message names the line).
Expected<std::vector<Sphere>> readSpheres(const std::string& path);

// Writes atomically: to a temporary file beside the target, then renamed over it, so a failed
// write never leaves a partial file.
Status writeSpheres(const std::string& path, const std::vector<Sphere>& spheres,
                    const SphereFileMeta& meta = {});

// The same, into a string (tests and embedding).
std::string formatSpheres(SphereFormat format, const std::vector<Sphere>& spheres,
                          const SphereFileMeta& meta = {});

// A sphere set as one triangle mesh: each sphere a subdivided icosahedron (20·4^s triangles)
// with its vertices on the sphere, so the mesh lies inside it.
struct SphereSetMesh {
  Mesh mesh;
  std::vector<Vec3> normals;                    // per vertex
  std::vector<std::array<uint8_t, 3>> colours;  // per vertex, one colour per sphere
  int32_t vertices_per_sphere = 0;
};
SphereSetMesh sphereSetMesh(const std::vector<Sphere>& spheres, int subdivisions = 2);
// Writes it as .ply (binary, vertex colours), .obj (one object per sphere, vertex colours) or
// glTF 2.0 (.gltf with an embedded buffer, or .glb), atomically.
Status writeSphereSetMesh(const std::string& path, const std::vector<Sphere>& spheres,
                          int subdivisions = 2);
// The colour of sphere i in pictures and exported meshes (a fixed palette).
std::array<uint8_t, 3> sphereColour(size_t i);

// Writes a whole file atomically (temporary file + rename). Used by every writer.
Status writeFileAtomically(const std::string& path, const std::string& contents);

}  // namespace sphereset

// Sphere sets as triangle meshes, to open beside the model in any viewer.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// A sphere set as one triangle mesh: each sphere a subdivided icosahedron (20·4^s triangles)
// with its vertices on the sphere, so the mesh lies inside it.
struct SphereSetMesh {
  Mesh mesh;
  std::vector<Vec3> normals;                    // per vertex
  std::vector<std::array<uint8_t, 3>> colours;  // per vertex, one colour per sphere
  int32_t vertices_per_sphere = 0;
};
// Subdivisions of an exported sphere at most (81 920 triangles a sphere).
inline constexpr int kMaxExportSubdivisions = 6;
// Whether `spheres` spheres at `subdivisions` can be exported: subdivisions from 0 to
// kMaxExportSubdivisions, and the mesh with its file within limits::kMaxArrayBytes and 2^31
// vertices (50 000 spheres at 4 subdivisions once ended in bad_alloc). kInvalidArgument naming
// the sizes otherwise; estimated before anything is allocated.
Status checkSphereSetMesh(size_t spheres, int subdivisions);
// The mesh of checkSphereSetMesh's sizes (its error otherwise).
Expected<SphereSetMesh> sphereSetMesh(const std::vector<Sphere>& spheres, int subdivisions = 2);
// Writes it as .ply (binary, vertex colours), .obj (one object per sphere, vertex colours) or
// glTF 2.0 (.gltf with an embedded buffer, or .glb), atomically. Errors of checkSphereSetMesh,
// checkSphere for each sphere, and the writer's.
Status writeSphereSetMesh(const std::string& path, const std::vector<Sphere>& spheres,
                          int subdivisions = 2);
// The colour of sphere i in pictures and exported meshes (a fixed palette).
std::array<uint8_t, 3> sphereColour(size_t i);

}  // namespace sphereset

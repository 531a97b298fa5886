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
SphereSetMesh sphereSetMesh(const std::vector<Sphere>& spheres, int subdivisions = 2);
// Writes it as .ply (binary, vertex colours), .obj (one object per sphere, vertex colours) or
// glTF 2.0 (.gltf with an embedded buffer, or .glb), atomically.
Status writeSphereSetMesh(const std::string& path, const std::vector<Sphere>& spheres,
                          int subdivisions = 2);
// The colour of sphere i in pictures and exported meshes (a fixed palette).
std::array<uint8_t, 3> sphereColour(size_t i);

}  // namespace sphereset

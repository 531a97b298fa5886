// Small closed meshes built in code, and paths of the bundled test data.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "sphereset/export.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/sphere.hpp"

namespace sphereset::test {

inline std::string dataPath(const std::string& name) {
  return std::string(SPHERESET_TEST_DATA_DIR) + "/" + name;
}
inline std::string examplePath(const std::string& name) {
  return std::string(SPHERESET_EXAMPLE_DIR) + "/" + name;
}

// The bundled robot link (tests/data/fr3_link1_collision.stl), a closed solid of 300 triangles.
inline Mesh robotLink() {
  auto m = loadMesh(dataPath("fr3_link1_collision.stl"));
  return m.ok() ? m->mesh : Mesh{};
}

// Axis-aligned box, outward orientation, 12 triangles.
inline Mesh makeBox(const Vec3& lo, const Vec3& hi) {
  Mesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                            (k & 4) ? hi.z() : lo.z());
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return m;
}

// Icosphere of radius r about the origin (subdivided icosahedron, vertices on the sphere):
// the library's own sphere-to-mesh conversion.
inline Mesh makeIcosphere(double r, int subdivisions) {
  return sphereSetMesh({{Vec3::Zero(), r}}, subdivisions)->mesh;
}

// Torus about the z axis: major radius R, minor radius r, nu × nv quads.
inline Mesh makeTorus(double R, double r, int nu, int nv) {
  Mesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
      m.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u),
                              (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// b's vertices and triangles appended to a's (two shells in one mesh).
inline Mesh joined(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const auto base = static_cast<int32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  return m;
}

// Applies x -> s R x + t to every vertex.
inline Mesh transformed(const Mesh& m, const Eigen::Matrix3d& R, const Vec3& t, double s) {
  Mesh out = m;
  for (Vec3& v : out.vertices) v = s * (R * v) + t;
  return out;
}

// A glTF tetrahedron whose geometry is in an external buffer: the .gltf text naming `bin`, and
// the buffer's bytes (4 float positions scaled by `scale`, then 12 uint16 indices, outward).
inline std::string tetrahedronGltf(const std::string& bin) {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
"buffers":[{"uri":")" +
         bin + R"(","byteLength":72}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},
{"buffer":0,"byteOffset":48,"byteLength":24}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3",
"min":[0,0,0],"max":[1,1,1]},
{"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}]})";
}
inline std::string tetrahedronBin(float scale) {
  const float p[12] = {0, 0, 0, scale, 0, 0, 0, scale, 0, 0, 0, scale};
  const uint16_t i[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  std::string out(reinterpret_cast<const char*>(p), sizeof p);
  out.append(reinterpret_cast<const char*>(i), sizeof i);
  return out;
}

}  // namespace sphereset::test

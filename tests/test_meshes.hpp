// Small closed meshes built in code, and paths of the bundled test data.
#pragma once

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "sphereset/mesh.hpp"

namespace sphereset::test {

inline std::string dataPath(const std::string& name) {
  return std::string(SPHERESET_TEST_DATA_DIR) + "/" + name;
}
inline std::string examplePath(const std::string& name) {
  return std::string(SPHERESET_EXAMPLE_DIR) + "/" + name;
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

// Icosphere of radius r about the origin (subdivided icosahedron, projected).
inline Mesh makeIcosphere(double r, int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  const double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : v) m.vertices.push_back(Vec3(p[0], p[1], p[2]).normalized() * r);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const int id = static_cast<int>(m.vertices.size());
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized() * r);
      mid[key] = id;
      return id;
    };
    std::vector<Triangle> next;
    for (const Triangle& tri : m.triangles) {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]),
                c = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles = std::move(next);
  }
  return m;
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

// Applies x -> s R x + t to every vertex.
inline Mesh transformed(const Mesh& m, const Eigen::Matrix3d& R, const Vec3& t, double s) {
  Mesh out = m;
  for (Vec3& v : out.vertices) v = s * (R * v) + t;
  return out;
}

}  // namespace sphereset::test

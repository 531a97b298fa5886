// Sphere sets as triangle meshes, to be opened beside the model in any viewer: each sphere
// becomes a subdivided icosahedron with its vertices on the sphere, coloured per sphere.
// Formats: PLY (binary, vertex colours), OBJ (one object per sphere, vertex colours as
// "v x y z r g b", which MeshLab, Blender and others read) and glTF 2.0 (.gltf with the buffer
// embedded as a data URI, or binary .glb), with normals and COLOR_0.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/atomic_write.hpp"
#include "io/json_text.hpp"
#include "sphereset/export.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "util/read_file.hpp"

namespace sphereset {
namespace {

struct UnitSphere {
  std::vector<Vec3> vertices;
  std::vector<std::array<int32_t, 3>> triangles;
};

UnitSphere icosphere(int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  UnitSphere s;
  s.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& v : s.vertices) v.normalize();
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int k = 0; k < subdivisions; ++k) {
    std::map<std::pair<int32_t, int32_t>, int32_t> mid;
    auto midpoint = [&](int32_t a, int32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      s.vertices.push_back((s.vertices[a] + s.vertices[b]).normalized());
      const int32_t i = static_cast<int32_t>(s.vertices.size() - 1);
      mid.emplace(key, i);
      return i;
    };
    std::vector<std::array<int32_t, 3>> next;
    for (const auto& tri : s.triangles) {
      const int32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                    ca = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    s.triangles = std::move(next);
  }
  return s;
}

std::string base64(const std::string& in) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = static_cast<uint8_t>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<uint8_t>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= static_cast<uint8_t>(in[i + 2]);
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? k[v & 63] : '=';
  }
  return out;
}

template <class T>
void append(std::string* buf, const T& v) {
  buf->append(reinterpret_cast<const char*>(&v), sizeof(T));
}

}  // namespace

std::array<uint8_t, 3> sphereColour(size_t i) {
  static const std::array<std::array<uint8_t, 3>, 8> palette = {{{230, 77, 64},
                                                                 {64, 140, 230},
                                                                 {77, 191, 89},
                                                                 {242, 179, 51},
                                                                 {166, 102, 217},
                                                                 {51, 191, 191},
                                                                 {230, 115, 179},
                                                                 {140, 140, 77}}};
  return palette[i % palette.size()];
}

// Bytes one exported vertex and one triangle take at most: the mesh (position, normal, colour;
// three indices) and the largest file text (an OBJ line "v x y z r g b" and "vn", an "f" line).
constexpr double kBytesPerVertex = 24 + 24 + 3 + 120;
constexpr double kBytesPerTriangle = 12 + 40;

Status checkSphereSetMesh(size_t spheres, int subdivisions) {
  if (Status st = limits::checkRange("subdivisions", subdivisions, 0, kMaxExportSubdivisions); !st)
    return st;
  const double faces = 20.0 * std::pow(4.0, subdivisions);
  const double vertices = faces / 2.0 + 2.0;
  const double n = static_cast<double>(spheres);
  const std::string what =
      std::to_string(spheres) + " spheres at " + std::to_string(subdivisions) + " subdivisions";
  if (n * vertices >= 2147483648.0)
    return Error{ErrorCode::kInvalidArgument,
                 what + " make more than 2^31 vertices; use fewer subdivisions"};
  return limits::checkArray(what, n, vertices * kBytesPerVertex + faces * kBytesPerTriangle,
                            ErrorCode::kInvalidArgument);
}

Expected<SphereSetMesh> sphereSetMesh(const std::vector<Sphere>& spheres, int subdivisions) {
  if (Status st = checkSphereSetMesh(spheres.size(), subdivisions); !st) return st.error();
  const UnitSphere u = icosphere(subdivisions);
  SphereSetMesh out;
  for (size_t i = 0; i < spheres.size(); ++i) {
    const int32_t base = static_cast<int32_t>(out.mesh.vertices.size());
    for (const Vec3& v : u.vertices) {
      out.mesh.vertices.push_back(spheres[i].center + spheres[i].radius * v);
      out.normals.push_back(v);
      out.colours.push_back(sphereColour(i));
    }
    for (const auto& t : u.triangles)
      out.mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  out.vertices_per_sphere = static_cast<int32_t>(u.vertices.size());
  return out;
}

namespace {

// Binary little-endian PLY with vertex colours.
std::string plyBytes(const SphereSetMesh& m, size_t spheres) {
  const auto& V = m.mesh.vertices;
  const auto& F = m.mesh.triangles;
  std::ostringstream h;
  h << "ply\nformat binary_little_endian 1.0\ncomment sphereset: " << spheres
    << " spheres\nelement vertex " << V.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
       "property uchar green\nproperty uchar blue\nelement face "
    << F.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string out = h.str();
  for (size_t i = 0; i < V.size(); ++i) {
    for (int k = 0; k < 3; ++k) append(&out, static_cast<float>(V[i][k]));
    for (int k = 0; k < 3; ++k) append(&out, m.colours[i][k]);
  }
  for (const auto& t : F) {
    append(&out, static_cast<uint8_t>(3));
    for (int k = 0; k < 3; ++k) append(&out, t[k]);
  }
  return out;
}

// OBJ, one object per sphere, vertex colours as `v x y z r g b`.
std::string objText(const SphereSetMesh& m, size_t spheres) {
  const auto& V = m.mesh.vertices;
  const auto& F = m.mesh.triangles;
  std::ostringstream os;
  os.precision(9);
  os << "# sphereset: " << spheres << " spheres, vertex colours as v x y z r g b\n";
  const size_t per = m.vertices_per_sphere, fper = F.size() / spheres;
  for (size_t s = 0; s < spheres; ++s) {
    os << "o sphere_" << s << '\n';
    for (size_t i = s * per; i < (s + 1) * per; ++i)
      os << "v " << V[i].x() << ' ' << V[i].y() << ' ' << V[i].z() << ' ' << m.colours[i][0] / 255.0
         << ' ' << m.colours[i][1] / 255.0 << ' ' << m.colours[i][2] / 255.0 << '\n';
    for (size_t f = s * fper; f < (s + 1) * fper; ++f)
      os << "f " << F[f][0] + 1 << ' ' << F[f][1] + 1 << ' ' << F[f][2] + 1 << '\n';
  }
  return os.str();
}

// glTF 2.0: JSON with the buffer embedded as base64 (.gltf), or the binary container (.glb).
std::string gltfBytes(const SphereSetMesh& m, bool binary) {
  const auto& V = m.mesh.vertices;
  const auto& F = m.mesh.triangles;
  std::string out;
  // One buffer: positions, normals, colours (float VEC3 each), then uint32 indices.
  std::string bin;
  Vec3 lo = V[0], hi = V[0];
  for (const Vec3& v : V) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
    for (int k = 0; k < 3; ++k) append(&bin, static_cast<float>(v[k]));
  }
  for (const Vec3& n : m.normals)
    for (int k = 0; k < 3; ++k) append(&bin, static_cast<float>(n[k]));
  for (const auto& c : m.colours)
    for (int k = 0; k < 3; ++k) append(&bin, static_cast<float>(c[k] / 255.0));
  for (const auto& t : F)
    for (int k = 0; k < 3; ++k) append(&bin, static_cast<uint32_t>(t[k]));
  const size_t nv = V.size(), vec_bytes = nv * 12, idx_bytes = F.size() * 12;
  // Accessor bounds in float, as stored.
  auto fvec = [](const Vec3& v) {
    return nlohmann::json{static_cast<float>(v.x()), static_cast<float>(v.y()),
                          static_cast<float>(v.z())};
  };
  nlohmann::json j = {
      {"asset", {{"version", "2.0"}, {"generator", "sphereset"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}, {"name", "spheres"}}}},
      {"meshes",
       {{{"name", "spheres"},
         {"primitives",
          {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"COLOR_0", 2}}},
            {"indices", 3},
            {"mode", 4}}}}}}},
      {"buffers", {{{"byteLength", bin.size()}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", vec_bytes}, {"target", 34962}},
        {{"buffer", 0}, {"byteOffset", vec_bytes}, {"byteLength", vec_bytes}, {"target", 34962}},
        {{"buffer", 0},
         {"byteOffset", 2 * vec_bytes},
         {"byteLength", vec_bytes},
         {"target", 34962}},
        {{"buffer", 0},
         {"byteOffset", 3 * vec_bytes},
         {"byteLength", idx_bytes},
         {"target", 34963}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", nv},
         {"type", "VEC3"},
         {"min", fvec(lo)},
         {"max", fvec(hi)}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", nv}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", nv}, {"type", "VEC3"}},
        {{"bufferView", 3},
         {"componentType", 5125},
         {"count", 3 * F.size()},
         {"type", "SCALAR"}}}}};
  if (!binary) {
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
    out = detail::jsonText(j, 1) + "\n";
  } else {
    std::string js = detail::jsonText(j);
    while (js.size() % 4) js += ' ';
    while (bin.size() % 4) bin += '\0';
    const uint32_t total =
        12 + 8 + static_cast<uint32_t>(js.size()) + 8 + static_cast<uint32_t>(bin.size());
    append(&out, uint32_t{0x46546C67});  // "glTF"
    append(&out, uint32_t{2});
    append(&out, total);
    append(&out, static_cast<uint32_t>(js.size()));
    append(&out, uint32_t{0x4E4F534A});  // "JSON"
    out += js;
    append(&out, static_cast<uint32_t>(bin.size()));
    append(&out, uint32_t{0x004E4942});  // "BIN\0"
    out += bin;
  }
  return out;
}

}  // namespace

Status writeSphereSetMesh(const std::string& path, const std::vector<Sphere>& spheres,
                          int subdivisions) {
  const std::string ext = detail::extensionOf(path);
  if (ext != ".ply" && ext != ".obj" && ext != ".gltf" && ext != ".glb")
    return Error{ErrorCode::kInvalidArgument,
                 path + ": unknown mesh extension (use .ply, .obj, .gltf or .glb)"};
  if (spheres.empty()) return Error{ErrorCode::kInvalidArgument, path + ": no spheres to export"};
  for (size_t i = 0; i < spheres.size(); ++i)
    if (Status st = checkSphere(path + ": sphere " + std::to_string(i), spheres[i],
                                ErrorCode::kInvalidArgument);
        !st)
      return st;
  const auto made = sphereSetMesh(spheres, subdivisions);
  if (!made) return Error{made.error().code, path + ": " + made.error().message};
  const SphereSetMesh& m = *made;
  const std::string out = ext == ".ply"   ? plyBytes(m, spheres.size())
                          : ext == ".obj" ? objText(m, spheres.size())
                                          : gltfBytes(m, ext == ".glb");
  return writeFileAtomically(path, out);
}

}  // namespace sphereset

// Mesh input in every supported format, the clean-up report, diagnosis of broken meshes and
// clear errors for bad files.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::expectError;

class MeshIo : public test::TempDirTest {};

const Mesh kCube = test::makeBox(Vec3::Zero(), Vec3::Ones());

std::string cubeObjQuads() {
  std::ostringstream os;
  os << "# unit cube with quads\n";
  for (const Vec3& v : kCube.vertices) os << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q)
    os << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << ' ' << f[3] + 1 << '\n';
  return os.str();
}

void expectUnitCube(const Expected<LoadedMesh>& m, double scale = 1.0, Vec3 offset = Vec3::Zero()) {
  ASSERT_TRUE(m.ok()) << m.error().message;
  const MeshDiagnosis d = diagnoseMesh(m->mesh);
  EXPECT_EQ(d.vertices, 8);
  EXPECT_EQ(d.triangles, 12);
  EXPECT_TRUE(d.closed);
  EXPECT_TRUE(d.manifold);
  EXPECT_TRUE(d.oriented);
  EXPECT_EQ(d.components, 1);
  EXPECT_NEAR(d.volume, scale * scale * scale, 1e-6);
  EXPECT_NEAR(d.area, 6 * scale * scale, 1e-6);
  EXPECT_NEAR((d.bbox.min - offset).norm(), 0.0, 1e-6);
  EXPECT_TRUE(d.isSolid());
}

TEST_F(MeshIo, ObjWithQuadsIsTriangulated) {
  expectUnitCube(loadMesh(write("c.obj", cubeObjQuads())));
}

TEST_F(MeshIo, AsciiAndBinaryStlAreWelded) {
  std::ostringstream a;
  a << "solid cube\n";
  for (const Triangle& t : kCube.triangles) {
    a << " facet normal 0 0 0\n  outer loop\n";
    for (int32_t k : t)
      a << "   vertex " << kCube.vertices[k].x() << ' ' << kCube.vertices[k].y() << ' '
        << kCube.vertices[k].z() << '\n';
    a << "  endloop\n endfacet\n";
  }
  a << "endsolid cube\n";
  auto ascii = loadMesh(write("a.stl", a.str()));
  expectUnitCube(ascii);
  EXPECT_EQ(ascii->report.welded_vertices, 36 - 8);

  std::string bin(80, ' ');
  const uint32_t n = 12;
  bin.append(reinterpret_cast<const char*>(&n), 4);
  for (const Triangle& t : kCube.triangles) {
    float f[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) f[3 + 3 * k + c] = static_cast<float>(kCube.vertices[t[k]][c]);
    bin.append(reinterpret_cast<const char*>(f), sizeof f);
    bin.append(2, '\0');
  }
  expectUnitCube(loadMesh(write("b.stl", bin)));
}

TEST_F(MeshIo, PlyAsciiWithTriangleStripsAndBinary) {
  std::ostringstream a;
  a << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
       "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
       "end_header\n";
  for (const Vec3& v : kCube.vertices) a << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  // Each quad (a, b, c, d) as the strip b c a d, strips separated by -1.
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  a << 6 * 5 - 1;
  for (int f = 0; f < 6; ++f) {
    a << ' ' << q[f][1] << ' ' << q[f][2] << ' ' << q[f][0] << ' ' << q[f][3];
    if (f < 5) a << " -1";
  }
  a << '\n';
  expectUnitCube(loadMesh(write("s.ply", a.str())));

  std::string b =
      "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty double x\n"
      "property double y\nproperty double z\nelement face 12\n"
      "property list uchar int vertex_indices\nend_header\n";
  for (const Vec3& v : kCube.vertices) b.append(reinterpret_cast<const char*>(v.data()), 24);
  for (const Triangle& t : kCube.triangles) {
    b.push_back(3);
    b.append(reinterpret_cast<const char*>(t.data()), 12);
  }
  expectUnitCube(loadMesh(write("b.ply", b)));
}

TEST_F(MeshIo, OffWithComments) {
  std::ostringstream a;
  a << "# written by a tool\nOFF\n# counts follow\n8 12 0\n\n# vertices\n";
  for (const Vec3& v : kCube.vertices) a << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  a << "# faces\n";
  for (const Triangle& t : kCube.triangles) a << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  expectUnitCube(loadMesh(write("c.off", a.str())));
}

TEST_F(MeshIo, ColladaSceneGraphTransformsAreApplied) {
  std::ostringstream pos, idx;
  for (const Vec3& v : kCube.vertices) pos << v.x() << ' ' << v.y() << ' ' << v.z() << ' ';
  for (const Triangle& t : kCube.triangles) idx << t[0] << ' ' << t[1] << ' ' << t[2] << ' ';
  const std::string dae =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
      "<asset><unit name=\"meter\" meter=\"1\"/><up_axis>Y_UP</up_axis></asset>\n"
      "<library_geometries><geometry id=\"cube\"><mesh>\n"
      "<source id=\"p\"><float_array id=\"pa\" count=\"24\">" +
      pos.str() +
      "</float_array>\n"
      "<technique_common><accessor source=\"#pa\" count=\"8\" stride=\"3\">"
      "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
      "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>\n"
      "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>\n"
      "<triangles count=\"12\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><p>" +
      idx.str() +
      "</p></triangles>\n</mesh></geometry></library_geometries>\n"
      "<library_visual_scenes><visual_scene id=\"s\">\n"
      "<node id=\"outer\"><matrix>1 0 0 10 0 1 0 0 0 0 1 0 0 0 0 1</matrix>\n"
      "<node id=\"inner\"><matrix>2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1</matrix>"
      "<instance_geometry url=\"#cube\"/></node></node>\n"
      "</visual_scene></library_visual_scenes>\n"
      "<scene><instance_visual_scene url=\"#s\"/></scene>\n</COLLADA>\n";
  auto m = loadMesh(write("c.dae", dae));
  ASSERT_TRUE(m.ok()) << m.error().message;
  const MeshDiagnosis d = diagnoseMesh(m->mesh);
  EXPECT_NEAR(d.volume, 8.0, 1e-6);
  EXPECT_NEAR(d.bbox.min.x(), 10.0, 1e-6);
  EXPECT_NEAR(d.bbox.max.x(), 12.0, 1e-6);
  EXPECT_TRUE(d.isSolid());
}

std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const uint32_t v = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8) | uint8_t(in[i + 2]);
    for (int k = 3; k >= 0; --k) out.push_back(t[(v >> (6 * k)) & 63]);
  }
  if (i < in.size()) {
    uint32_t v = uint8_t(in[i]) << 16;
    if (i + 1 < in.size()) v |= uint8_t(in[i + 1]) << 8;
    out.push_back(t[(v >> 18) & 63]);
    out.push_back(t[(v >> 12) & 63]);
    out.push_back(i + 1 < in.size() ? t[(v >> 6) & 63] : '=');
    out.push_back('=');
  }
  return out;
}

TEST_F(MeshIo, GltfWithEmbeddedBuffer) {
  std::string buf;
  for (const Vec3& v : kCube.vertices)
    for (int c = 0; c < 3; ++c) {
      const float f = static_cast<float>(v[c]);
      buf.append(reinterpret_cast<const char*>(&f), 4);
    }
  for (const Triangle& t : kCube.triangles)
    for (int32_t k : t) {
      const uint16_t s = static_cast<uint16_t>(k);
      buf.append(reinterpret_cast<const char*>(&s), 2);
    }
  const std::string gltf =
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
      "\"nodes\":[{\"mesh\":0,\"translation\":[0,5,0]}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
      "\"buffers\":[{\"byteLength\":" +
      std::to_string(buf.size()) + ",\"uri\":\"data:application/octet-stream;base64," +
      base64(buf) +
      "\"}],"
      "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":96},"
      "{\"buffer\":0,\"byteOffset\":96,\"byteLength\":72}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":8,\"type\":\"VEC3\","
      "\"min\":[0,0,0],\"max\":[1,1,1]},"
      "{\"bufferView\":1,\"componentType\":5123,\"count\":36,\"type\":\"SCALAR\"}]}";
  expectUnitCube(loadMesh(write("c.gltf", gltf)), 1.0, Vec3(0, 5, 0));
}

TEST_F(MeshIo, InvertedMeshIsFlippedOutward) {
  std::string obj = cubeObjQuads();
  // Reverse every face.
  std::ostringstream os;
  std::istringstream is(obj);
  std::string line;
  while (std::getline(is, line)) {
    if (line.rfind("f ", 0) == 0) {
      std::istringstream ls(line.substr(2));
      int a, b, c, d;
      ls >> a >> b >> c >> d;
      os << "f " << d << ' ' << c << ' ' << b << ' ' << a << '\n';
    } else {
      os << line << '\n';
    }
  }
  auto m = loadMesh(write("inv.obj", os.str()));
  expectUnitCube(m);
  EXPECT_TRUE(m->report.flipped);
}

TEST_F(MeshIo, DegenerateAndDuplicateTrianglesAreDroppedAndCounted) {
  std::string obj = cubeObjQuads();
  obj += "f 1 1 2\n";             // repeated vertex
  obj += "v 0.5 0 0\nf 1 2 9\n";  // zero area (collinear)
  obj += "f 1 3 4\n";             // duplicate of an existing triangle
  auto m = loadMesh(write("d.obj", obj));
  expectUnitCube(m);
  EXPECT_EQ(m->report.degenerate_dropped, 2);
  EXPECT_EQ(m->report.duplicate_dropped, 1);
  EXPECT_EQ(m->report.unused_vertices, 1);
}

TEST_F(MeshIo, OpenAndNonManifoldMeshesAreDiagnosed) {
  Mesh open = kCube;
  open.triangles.pop_back();
  MeshDiagnosis d = diagnoseMesh(open);
  EXPECT_FALSE(d.closed);
  EXPECT_EQ(d.boundary_edges, 3);
  EXPECT_FALSE(d.isSolid());
  const Error e = notSolidError("open.obj", d);
  EXPECT_EQ(e.code, ErrorCode::kNotSolid);
  EXPECT_NE(e.message.find("open.obj"), std::string::npos);
  EXPECT_NE(e.message.find("3 boundary edges"), std::string::npos);

  // Two cubes sharing one edge: four triangles on that edge.
  Mesh two = kCube;
  const Mesh other = test::makeBox(Vec3(1, 1, 0), Vec3(2, 2, 1));
  const int32_t base = static_cast<int32_t>(two.vertices.size());
  for (const Vec3& v : other.vertices) two.vertices.push_back(v);
  for (const Triangle& t : other.triangles)
    two.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  auto cleaned = cleanMesh(two.vertices, two.triangles);
  ASSERT_TRUE(cleaned.ok());
  d = diagnoseMesh(cleaned->mesh);
  EXPECT_TRUE(d.closed);
  EXPECT_FALSE(d.manifold);
  EXPECT_EQ(d.nonmanifold_edges, 1);
  EXPECT_EQ(d.components, 1);

  // Two cubes sharing one vertex: a non-manifold vertex, two components.
  Mesh bow = kCube;
  const Mesh corner = test::makeBox(Vec3(1, 1, 1), Vec3(2, 2, 2));
  for (const Vec3& v : corner.vertices) bow.vertices.push_back(v);
  for (const Triangle& t : corner.triangles)
    bow.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  auto welded = cleanMesh(bow.vertices, bow.triangles);
  ASSERT_TRUE(welded.ok());
  d = diagnoseMesh(welded->mesh);
  EXPECT_EQ(d.nonmanifold_vertices, 1);
  EXPECT_EQ(d.nonmanifold_edges, 0);
  EXPECT_EQ(d.components, 2);
  EXPECT_FALSE(d.manifold);

  // Inconsistent orientation: one face flipped.
  Mesh mis = kCube;
  std::swap(mis.triangles[0][1], mis.triangles[0][2]);
  d = diagnoseMesh(mis);
  EXPECT_FALSE(d.oriented);
  EXPECT_EQ(d.misoriented_edges, 3);
}

TEST_F(MeshIo, WeldToleranceMergesNearbyVertices) {
  Mesh m = kCube;
  // Split vertex 0 into a copy 1e-9 away used by half of its triangles.
  m.vertices.push_back(m.vertices[0] + Vec3(1e-9, 0, 0));
  int replaced = 0;
  for (Triangle& t : m.triangles)
    for (int32_t& k : t)
      if (k == 0 && (replaced++ % 2 == 0)) k = 8;
  auto exact = cleanMesh(m.vertices, m.triangles);
  ASSERT_TRUE(exact.ok());
  EXPECT_FALSE(diagnoseMesh(exact->mesh).closed);
  LoadOptions lo;
  lo.weld_tolerance = 1e-6;
  auto tol = cleanMesh(m.vertices, m.triangles, lo);
  ASSERT_TRUE(tol.ok());
  EXPECT_TRUE(diagnoseMesh(tol->mesh).isSolid());
  EXPECT_EQ(tol->report.welded_vertices, 1);
}

TEST_F(MeshIo, BadFilesGiveClearErrors) {
  const std::string missing = (dir_ / "nope.obj").string();
  expectError(loadMesh(missing), ErrorCode::kUnreadable, missing, "no such file");
  const std::string empty = write("empty.stl", "");
  expectError(loadMesh(empty), ErrorCode::kUnreadable, empty, "empty");
  const std::string junk = write("junk.xyzw", "this is not a mesh\n\x01\x02");
  expectError(loadMesh(junk), ErrorCode::kUnreadable, junk, "cannot be read");
  expectError(loadMesh(dir_.string()), ErrorCode::kUnreadable, dir_.string(), "directory");

  const std::string nan_off = write("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n");
  expectError(loadMesh(nan_off), ErrorCode::kInvalidData, nan_off, "NaN");
  const std::string inf_obj = write("inf.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n");
  auto inf = loadMesh(inf_obj);
  ASSERT_FALSE(inf.ok());
  EXPECT_NE(inf.error().message.find(inf_obj), std::string::npos);
  const std::string bad_index = write("idx.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  expectError(loadMesh(bad_index), ErrorCode::kInvalidData, bad_index, "vertex 7 of 3");
  const std::string no_faces = write("pts.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  expectError(loadMesh(no_faces), ErrorCode::kInvalidData, no_faces, "no triangles");
  const std::string flat = write("flat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
  expectError(loadMesh(flat), ErrorCode::kInvalidData, flat, "degenerate");
  const std::string trunc = write("trunc.off", "OFF\n8 12 0\n0 0 0\n");
  expectError(loadMesh(trunc), ErrorCode::kUnreadable, trunc, "expected a vertex");
}

TEST_F(MeshIo, BundledMeshesLoadAsSolids) {
  for (const std::string& p :
       {test::examplePath("spot.obj"), test::dataPath("fr3_link1_collision.stl")}) {
    auto m = loadMesh(p);
    ASSERT_TRUE(m.ok()) << m.error().message;
    const MeshDiagnosis d = diagnoseMesh(m->mesh);
    EXPECT_TRUE(d.isSolid()) << p;
    EXPECT_EQ(d.components, 1);
  }
  auto spot = loadMesh(test::examplePath("spot.obj"));
  EXPECT_EQ(spot->mesh.triangles.size(), 5856u);
  EXPECT_EQ(spot->mesh.vertices.size(), 2930u);
}

}  // namespace
}  // namespace sphereset

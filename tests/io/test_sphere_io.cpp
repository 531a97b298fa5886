// Sphere-set files: round trips in every format, malformed input, atomic writes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sphereset/export.hpp"
#include "sphereset/load.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

namespace fs = std::filesystem;

class SphereIo : public test::TempDirTest {};

using test::kRoundTripSet;

TEST_F(SphereIo, RoundTripsInEveryFormat) {
  for (const std::string ext : {".txt", ".json", ".sph", ".yaml"}) {
    const std::string p = path("set" + ext);
    SphereFileMeta meta;
    meta.name = "link_3";
    ASSERT_TRUE(writeSpheres(p, kRoundTripSet, meta).ok()) << ext;
    auto back = readSpheres(p);
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->size(), kRoundTripSet.size()) << ext;
    for (size_t i = 0; i < kRoundTripSet.size(); ++i) {
      EXPECT_EQ((*back)[i].center, kRoundTripSet[i].center) << ext;  // 17 significant digits: exact
      EXPECT_EQ((*back)[i].radius, kRoundTripSet[i].radius) << ext;
    }
  }
  std::ifstream yaml(path("set.yaml"));
  std::string all((std::istreambuf_iterator<char>(yaml)), std::istreambuf_iterator<char>());
  EXPECT_NE(all.find("collision_spheres:\n  link_3:"), std::string::npos);
}

TEST_F(SphereIo, ReadsTextWithCommentsAndSphTreesByDeepestLevel) {
  auto t = readSpheres(write("a.txt", "# header\n\n1 2 3 4 # trailing\n  5,6,7,8\n"));
  ASSERT_TRUE(t.ok()) << t.error().message;
  ASSERT_EQ(t->size(), 2u);
  EXPECT_EQ((*t)[1].radius, 8.0);
  // A 3-level binary tree with one unused leaf (negative radius).
  auto s = readSpheres(write("t.sph",
                             "3 2\n0 0 0 10 0\n-1 0 0 5 0\n1 0 0 5 0\n"
                             "-1.5 0 0 1 0\n-0.5 0 0 1 0\n0.5 0 0 1 0\n0 0 0 -1 0\n"));
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_EQ(s->size(), 3u);
}

TEST_F(SphereIo, MalformedFilesNameTheLine) {
  auto a = readSpheres(write("bad.txt", "1 2 3 4\n1 2 3\n"));
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(a.error().message.find("bad.txt:2"), std::string::npos) << a.error().message;
  auto b = readSpheres(write("neg.txt", "1 2 3 -4\n"));
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().message.find("negative radius"), std::string::npos);
  auto c = readSpheres(write("bad.json", "{\"spheres\": [{\"center\": [1, 2], \"radius\": 1}]}"));
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().message.find("sphere 0"), std::string::npos);
  auto d = readSpheres(write("broken.json", "{\"spheres\": ["));
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error().code, ErrorCode::kUnreadable);
  auto e = readSpheres(path("missing.txt"));
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().code, ErrorCode::kUnreadable);
  auto f = readSpheres(write("x.obj", "1 2 3 4\n"));
  ASSERT_FALSE(f.ok());
  EXPECT_EQ(f.error().code, ErrorCode::kInvalidArgument);
}

TEST_F(SphereIo, FailedWritesLeaveNoFile) {
  const std::string target = path("no_such_dir/out.txt");
  Status st = writeSpheres(target, kRoundTripSet);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.error().code, ErrorCode::kWriteFailed);
  EXPECT_FALSE(fs::exists(target));
  // A NaN sphere is refused before anything is written, and an existing file is kept.
  const std::string keep = write("keep.txt", "1 2 3 4\n");
  std::vector<Sphere> bad = kRoundTripSet;
  bad[1].radius = std::nan("");
  ASSERT_FALSE(writeSpheres(keep, bad).ok());
  auto back = readSpheres(keep);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->size(), 1u);
  // No temporary files remain in the directory.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

// One spelling of the format names at every door ("yml" and "text" were Python's alone).
TEST(SphereFormat, FormatNamesHaveOneSpelling) {
  for (SphereFormat f :
       {SphereFormat::kText, SphereFormat::kJson, SphereFormat::kSph, SphereFormat::kYaml}) {
    const auto back = sphereFormatFromName(sphereFormatName(f));
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, f);
  }
  for (const char* other : {"yml", "text", "xyzr", "TXT", ""}) {
    const auto f = sphereFormatFromName(other);
    ASSERT_FALSE(f.ok()) << other;
    EXPECT_EQ(f.error().message,
              std::string("format '") + other + "': expected txt, json, sph or yaml");
  }
}

// assimp reads coordinates as floats: 1e80 arrived as infinity and was reported as "NaN or
// infinite"; the message says what happened.
TEST(LoadMesh, CoordinatesBeyondFloatSayTheFormatIsSinglePrecision) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "sphereset_huge_coordinate.obj").string();
  std::ofstream(path) << "v 0 0 0\nv 1e80 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\n"
                         "f 2 4 3\n";
  const auto m = loadMesh(path);
  std::filesystem::remove(path);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(m.error().message.find("beyond 3.4e+38 (this format is read in single precision)"),
            std::string::npos)
      << m.error().message;
}

// 50 000 spheres at 4 subdivisions ended in bad_alloc, and a subdivision count out of range was
// clamped by the library while two doors refused it: the library estimates and refuses.
TEST(SphereExport, SizesAreCheckedBeforeAnythingIsAllocated) {
  EXPECT_TRUE(checkSphereSetMesh(1000, 2).ok());
  const Status big = checkSphereSetMesh(50000, 4);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(big.error().message.find("50000 spheres at 4 subdivisions would need"),
            std::string::npos)
      << big.error().message;
  for (int s : {-1, 7}) {
    const auto m = sphereSetMesh({{Vec3::Zero(), 1.0}}, s);
    ASSERT_FALSE(m.ok());
    EXPECT_NE(m.error().message.find("subdivisions must be from 0 to 6"), std::string::npos)
        << m.error().message;
  }
  const std::string out = (std::filesystem::temp_directory_path() / "sphereset_far.ply").string();
  const Status far = writeSphereSetMesh(out, {{Vec3(1e200, 0, 0), 1.0}}, 1);
  ASSERT_FALSE(far.ok());
  EXPECT_NE(far.error().message.find("sphere 0: a value beyond 1e+30"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(SphereExport, MeshesReadBackAsClosedSolidsInsideTheSpheres) {
  const std::vector<Sphere> spheres = {{Vec3(0, 0, 0), 1.0}, {Vec3(3, 0, 0), 0.5}};
  const SphereSetMesh m = *sphereSetMesh(spheres, 2);
  EXPECT_EQ(m.mesh.triangles.size(), 2u * 20u * 16u);
  for (size_t i = 0; i < m.mesh.vertices.size(); ++i) {
    const Sphere& s = spheres[i / m.vertices_per_sphere];
    EXPECT_NEAR((m.mesh.vertices[i] - s.center).norm(), s.radius, 1e-12);
  }
  const auto dir = test::tempPath("export_test");
  std::filesystem::create_directories(dir);
  for (const char* name : {"s.ply", "s.obj", "s.gltf", "s.glb"}) {
    const std::string path = (dir / name).string();
    ASSERT_TRUE(writeSphereSetMesh(path, spheres, 2).ok()) << name;
    auto back = loadMesh(path);
    ASSERT_TRUE(back.ok()) << name << ": " << back.error().message;
    const MeshDiagnosis d = diagnoseMesh(back->mesh);
    EXPECT_TRUE(d.isSolid()) << name;
    EXPECT_EQ(d.components, 2) << name;
    EXPECT_EQ(d.triangles, 640) << name;
    // Volume of two inscribed polyhedra: a little below that of the balls.
    const double balls = 4.0 / 3.0 * M_PI * (1.0 + 0.125);
    EXPECT_LT(d.volume, balls) << name;
    EXPECT_GT(d.volume, 0.95 * balls) << name;
  }
  EXPECT_FALSE(writeSphereSetMesh((dir / "s.stl").string(), spheres).ok());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sphereset

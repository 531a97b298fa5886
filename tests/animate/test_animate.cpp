// Animated sphere sets on a bar bent by two bones: centres follow the mesh (mean value
// coordinates and bone weights), fixed radii lose coverage at a sharp bend, the rebound
// restores it, and an independent brute-force check (random points on the deformed triangles
// against every sphere) confirms both.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "animate/bent_bar.hpp"
#include "sphereset/animate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/solid_index.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::bendFrame;
using test::makeBentBar;

// Spheres along the bar, each just holding the square cross-sections within ±0.25 of its
// centre: a tight cover of the straight bar.
std::vector<Sphere> barSpheres() {
  std::vector<Sphere> s;
  for (int i = 0; i < 8; ++i) s.push_back({Vec3(0.25 + 0.5 * i, 0.0, 0.0), std::sqrt(0.5625)});
  return s;
}

// Uniform random points on the triangles (by area) plus every vertex: how many lie in no sphere.
int64_t uncoveredSamples(const Mesh& m, const std::vector<Sphere>& s, int64_t samples,
                         uint64_t seed) {
  constexpr double kTol = 1e-9;  // absolute, the bar is 4 units long
  auto covered = [&](const Vec3& p) {
    for (const Sphere& b : s)
      if ((p - b.center).norm() <= b.radius + kTol) return true;
    return false;
  };
  std::vector<double> cdf;
  double total = 0.0;
  for (const Triangle& t : m.triangles) {
    total +=
        0.5 *
        (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
    cdf.push_back(total);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int64_t missed = 0;
  for (const Vec3& v : m.vertices) missed += !covered(v);
  for (int64_t k = 0; k < samples; ++k) {
    const auto it = std::lower_bound(cdf.begin(), cdf.end(), u(rng) * total);
    const Triangle& t = m.triangles[std::min<size_t>(it - cdf.begin(), cdf.size() - 1)];
    double a = u(rng), b = u(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const Vec3 p = m.vertices[t[0]] + a * (m.vertices[t[1]] - m.vertices[t[0]]) +
                   b * (m.vertices[t[2]] - m.vertices[t[0]]);
    missed += !covered(p);
  }
  return missed;
}

TEST(Animate, RestFrameKeepsTheSetAndItsCoverage) {
  const auto bar = makeBentBar();
  const auto spheres = barSpheres();
  for (CentreWeighting w : {CentreWeighting::kMeanValue, CentreWeighting::kBones}) {
    AnimateOptions o;
    o.weighting = w;
    auto r = animateSpheres(bar.rest, spheres, {bendFrame(bar, 0.0)}, o, &bar.skin);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->frames.size(), 1u);
    for (size_t i = 0; i < spheres.size(); ++i) {
      EXPECT_LT((r->frames[0].spheres[i].center - spheres[i].center).norm(), 1e-9);
      EXPECT_EQ(r->frames[0].spheres[i].radius, spheres[i].radius);
    }
    EXPECT_TRUE(r->frames[0].surface_covered);
    EXPECT_EQ(r->frames_covered, 1);
  }
}

TEST(Animate, RigidPartsMoveRigidly) {
  // Far from the joint the mesh moves rigidly with bone 1, so both weightings move the last
  // centre exactly with it.
  const auto bar = makeBentBar();
  const auto spheres = barSpheres();
  const AnimationFrame f = bendFrame(bar, 0.6);
  for (CentreWeighting w : {CentreWeighting::kMeanValue, CentreWeighting::kBones}) {
    AnimateOptions o;
    o.weighting = w;
    auto r = animateSpheres(bar.rest, spheres, {f}, o, &bar.skin);
    ASSERT_TRUE(r.ok());
    const Vec3 expect = f.bones[1] * spheres.back().center;
    // MVC of an interior point depend on the whole mesh, so only bone weights are exact.
    EXPECT_LT((r->frames[0].spheres.back().center - expect).norm(),
              w == CentreWeighting::kBones ? 1e-12 : 0.05);
  }
}

TEST(Animate, SharpBendLosesCoverageReboundRestoresIt) {
  const auto bar = makeBentBar();
  const auto spheres = barSpheres();
  const AnimationFrame f = bendFrame(bar, 1.4);  // about 80 degrees over a short blend
  const Mesh deformed{f.vertices, bar.rest.triangles};
  for (CentreWeighting w : {CentreWeighting::kMeanValue, CentreWeighting::kBones}) {
    AnimateOptions o;
    o.weighting = w;
    o.rebound = false;
    auto fixed = animateSpheres(bar.rest, spheres, {f}, o, &bar.skin);
    ASSERT_TRUE(fixed.ok());
    const AnimateFrameResult& a = fixed->frames[0];
    EXPECT_FALSE(a.surface_covered);
    EXPECT_GT(a.max_gap, 0.0);
    EXPECT_EQ(fixed->frames_covered, 0);
    EXPECT_GT(uncoveredSamples(deformed, a.spheres, 20000, 3), 0);

    o.rebound = true;
    auto grown = animateSpheres(bar.rest, spheres, {f}, o, &bar.skin);
    ASSERT_TRUE(grown.ok());
    const AnimateFrameResult& b = grown->frames[0];
    EXPECT_FALSE(b.surface_covered);  // the moved set itself, before the rebound
    EXPECT_TRUE(b.rebound_covered);
    EXPECT_EQ(uncoveredSamples(deformed, b.spheres, 200000, 5), 0);
    EXPECT_GT(b.grown, 0);
    EXPECT_GT(b.radius_growth, 0.0);
    EXPECT_GE(b.er_rebound, b.er);
    // Centres are those of the moved set; radii only grew.
    for (size_t i = 0; i < spheres.size(); ++i) {
      EXPECT_EQ(b.spheres[i].center, a.spheres[i].center);
      EXPECT_GE(b.spheres[i].radius, a.spheres[i].radius);
    }
  }
}

TEST(Animate, FramesThatPassThroughThemselvesAreFlagged) {
  const auto bar = makeBentBar();
  // Bent by 2.5 radians about the bar's axis (not its inner edge): the inner side folds.
  AnimationFrame fold;
  const Vec3 joint(2.0, 0.0, 0.0);
  fold.bones = {Eigen::Affine3d::Identity(), Eigen::Affine3d(Eigen::Translation3d(joint) *
                                                             Eigen::AngleAxisd(2.5, Vec3::UnitZ()) *
                                                             Eigen::Translation3d(-joint))};
  fold.vertices = skinPoints(bar.rest.vertices, bar.skin.vertex_weights, fold.bones).value();
  auto r = animateSpheres(bar.rest, barSpheres(), {bendFrame(bar, 1.4), fold});
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->frames[0].crossings, 0);
  EXPECT_GT(r->frames[1].crossings, 0);
  EXPECT_EQ(r->frames_crossing, 1);
}

TEST(Animate, BadInput) {
  const auto bar = makeBentBar();
  AnimationFrame f = bendFrame(bar, 0.3);
  f.vertices.pop_back();
  auto r = animateSpheres(bar.rest, barSpheres(), {f});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(r.error().message.find("vertices"), std::string::npos);
  AnimateOptions o;
  o.weighting = CentreWeighting::kBones;
  EXPECT_FALSE(animateSpheres(bar.rest, barSpheres(), {bendFrame(bar, 0.3)}, o).ok());
  EXPECT_FALSE(animateSpheres(bar.rest, {}, {bendFrame(bar, 0.3)}).ok());
}

// The rest mesh must be the skin's bind pose: the bind pose scaled by 3 and shifted has the
// same vertex count and triangles, and would be animated into a set that covers nothing.
TEST(Animate, RefusesARestMeshThatIsNotTheBindPose) {
  const auto bar = makeBentBar();
  Mesh scaled = bar.rest;
  for (Vec3& v : scaled.vertices) v = 3.0 * v + Vec3(1.0, 2.0, 0.0);
  AnimateOptions o;
  o.weighting = CentreWeighting::kBones;
  for (CentreWeighting w : {CentreWeighting::kBones, CentreWeighting::kMeanValue}) {
    o.weighting = w;
    auto r = animateSpheres(scaled, barSpheres(), {bendFrame(bar, 0.3)}, o, &bar.skin);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
    EXPECT_NE(r.error().message.find("not the skin's bind pose (vertex 0 differs)"),
              std::string::npos)
        << r.error().message;
  }
  // Same vertices, triangles in another order.
  Mesh reordered = bar.rest;
  std::swap(reordered.triangles[0], reordered.triangles[1]);
  auto r = animateSpheres(reordered, barSpheres(), {bendFrame(bar, 0.3)}, o, &bar.skin);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("its triangles differ"), std::string::npos);
  // A skin without its bind pose.
  SkinWeights no_bind = bar.skin;
  no_bind.bind_pose = {};
  EXPECT_FALSE(animateSpheres(bar.rest, barSpheres(), {bendFrame(bar, 0.3)}, o, &no_bind).ok());
  // The bind pose itself is accepted.
  EXPECT_TRUE(animateSpheres(bar.rest, barSpheres(), {bendFrame(bar, 0.3)}, o, &bar.skin).ok());
}

TEST(Animate, RefusesAFrameWithOtherTriangles) {
  const auto bar = makeBentBar();
  AnimationFrame f = bendFrame(bar, 0.3);
  f.triangles = bar.rest.triangles;
  EXPECT_TRUE(animateSpheres(bar.rest, barSpheres(), {f}).ok());
  std::swap(f.triangles[2][0], f.triangles[2][1]);
  f.name = "bent.off";
  auto r = animateSpheres(bar.rest, barSpheres(), {f});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
  EXPECT_EQ(
      r.error().message,
      "frame 0 (bent.off): its triangles differ from the rest mesh's (frames need the rest mesh's "
      "vertices in its order)");
}

// The public kernels check their parallel arrays instead of reading past them.
TEST(Animate, KernelsCheckTheirArraySizes) {
  const auto bar = makeBentBar();
  const std::vector<Vec3> pts = {{0.5, 0.0, 0.0}, {3.5, 0.1, 0.0}};
  SkinWeights short_skin = bar.skin;
  short_skin.vertex_weights.conservativeResize(3, 2);
  auto bw = pointBoneWeights(bar.rest, short_skin, pts, 8);
  ASSERT_FALSE(bw.ok());
  EXPECT_EQ(bw.error().code, ErrorCode::kInvalidArgument);
  EXPECT_FALSE(pointBoneWeights(bar.rest, bar.skin, pts, 0).ok());
  EXPECT_FALSE(pointBoneWeights(bar.rest, bar.skin, {{NAN, 0.0, 0.0}}, 8).ok());

  const Eigen::MatrixXd w = Eigen::MatrixXd::Constant(2, 2, 0.5);
  const std::vector<Eigen::Affine3d> two(2, Eigen::Affine3d::Identity());
  EXPECT_TRUE(skinPoints(pts, w, two).ok());
  EXPECT_FALSE(skinPoints(pts, w, {Eigen::Affine3d::Identity()}).ok());
  EXPECT_FALSE(skinPoints({pts[0]}, w, two).ok());

  auto mvw = meanValueWeights(bar.rest, pts);
  ASSERT_TRUE(mvw.ok());
  std::vector<Vec3> fewer = bar.rest.vertices;
  fewer.pop_back();
  auto moved = meanValuePoints(*mvw, fewer);
  ASSERT_FALSE(moved.ok());
  EXPECT_EQ(moved.error().code, ErrorCode::kInvalidArgument);
  EXPECT_FALSE(meanValueWeights(Mesh{}, pts).ok());
  EXPECT_FALSE(meanValueMatrix(bar.rest, {{0.0, INFINITY, 0.0}}).ok());
}

TEST(Animate, PointBoneWeightsFollowTheNearestSurface) {
  const auto bar = makeBentBar();
  const Eigen::MatrixXd w =
      pointBoneWeights(bar.rest, bar.skin, {{0.5, 0.0, 0.0}, {3.5, 0.1, 0.0}, {2.0, 0.0, 0.0}}, 8)
          .value();
  EXPECT_NEAR(w(0, 0), 1.0, 1e-12);
  EXPECT_NEAR(w(1, 1), 1.0, 1e-12);
  EXPECT_NEAR(w.row(2).sum(), 1.0, 1e-12);
  EXPECT_GT(w(2, 0), 0.0);
  EXPECT_GT(w(2, 1), 0.0);
}

}  // namespace
}  // namespace sphereset

namespace sphereset {
namespace {

// A skinned asset written here (Valve SMD, read through assimp): a 1 × 1 × 2 box whose bottom
// follows bone "root" and whose top follows bone "tip" (at z = 1), turned about x by 0, 0.3 and
// 0.6 radians in a 3-frame clip.
std::string writeSkinnedBox(const std::filesystem::path& path) {
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::ofstream f(path);
  f << "version 1\nnodes\n0 \"root\" -1\n1 \"tip\" 0\nend\nskeleton\n";
  const double angles[3] = {0.0, 0.3, 0.6};
  for (int t = 0; t < 3; ++t)
    f << "time " << t << "\n0 0 0 0 0 0 0\n1 0 0 1 " << angles[t] << " 0 0\n";
  f << "end\ntriangles\n";
  for (const auto& face : q)
    for (const auto& tri : {std::array<int, 3>{face[0], face[1], face[2]},
                            std::array<int, 3>{face[0], face[2], face[3]}}) {
      f << "skin\n";
      for (int i : tri) {
        const int x = i & 1, y = (i >> 1) & 1, z = (i >> 2) & 1;
        f << z << ' ' << x << ' ' << y << ' ' << 2 * z << " 0 0 1 0 0 1 " << z << " 1\n";
      }
    }
  f << "end\n";
  return path.string();
}

TEST(SkinnedAsset, ReadsBindPoseSkinAndClip) {
  const std::string path = writeSkinnedBox(test::tempPath("skinned_box.smd"));
  auto a = loadAnimation(path);
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_EQ(a->asset.rest.vertices.size(), 8u);
  EXPECT_GT(signedVolume(a->asset.rest), 1.99);
  ASSERT_EQ(a->frames.size(), 3u);
  for (const AnimationFrame& fr : a->frames) ASSERT_EQ(fr.vertices.size(), 8u);
  const double angles[3] = {0.0, 0.3, 0.6};
  for (int t = 0; t < 3; ++t) {
    const Eigen::Affine3d tip = Eigen::Translation3d(0, 0, 1) *
                                Eigen::AngleAxisd(angles[t], Vec3::UnitX()) *
                                Eigen::Translation3d(0, 0, -1);
    for (size_t i = 0; i < 8; ++i) {
      const Vec3& v = a->asset.rest.vertices[i];
      const Vec3 expect = v.z() > 1.0 ? Vec3(tip * v) : v;
      EXPECT_LT((a->frames[t].vertices[i] - expect).norm(), 1e-5) << t << ' ' << i;
    }
  }
  // Sampled at a rate instead of the keyframe times.
  SkinnedLoadOptions o;
  o.fps = 2.0 / a->duration;  // frames at 0, duration / 2, duration
  auto b = loadAnimation(path, o);
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(b->frames.size(), 3u);
  o.clip = "walk";
  auto c = loadAnimation(path, o);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(c.error().message.find("no clip 'walk'"), std::string::npos);
  std::filesystem::remove(path);
}

TEST(SkinnedAsset, AnAssetWithoutAnimationIsAnError) {
  const auto path = test::tempPath("static_box.off");
  std::ofstream(path)
      << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  auto a = loadAnimation(path.string());
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(a.error().message.find("no animation"), std::string::npos);
  std::filesystem::remove(path);
}

// A frame whose deformation makes two vertices coincide: welding the frame on its own merged
// them ("3 vertices, rest has 4" for a file with 4); loadFrameMesh keeps the rest's vertices.
class FrameMesh : public test::TempDirTest {};

TEST_F(FrameMesh, CoincidentVerticesOfAFrameStayDistinct) {
  const std::string cube =
      "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
      "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n"
      "3 0 6 2\n3 1 3 7\n3 1 7 5\n";
  auto rest = loadMesh(write("rest.off", cube));
  ASSERT_TRUE(rest.ok()) << rest.error().message;
  std::string moved = cube;
  moved.replace(moved.find("1 0 0\n"), 6, "0 0 0\n");  // vertex 1 onto vertex 0
  const std::string frame_path = write("frame.off", moved);
  ASSERT_EQ(loadMesh(frame_path)->mesh.vertices.size(), 7u);  // what welding it alone gives
  auto frame = loadFrameMesh(frame_path, *rest);
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  ASSERT_EQ(frame->vertices.size(), 8u);
  EXPECT_EQ(frame->vertices[1], Vec3::Zero());
  EXPECT_EQ(frame->triangles, rest->mesh.triangles);
  // A file of another mesh is refused, naming both counts.
  const std::string tet = write(
      "tet.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  test::expectError(loadFrameMesh(tet, *rest), ErrorCode::kInvalidData, tet,
                    "4 vertices and 4 faces, the rest mesh's file");
}

// Found by fuzzing: assimp's SMD reader loops for minutes on a NUL byte in a node name, and reads
// past its buffer on other control characters. Text formats with binary bytes are refused
// before assimp reads them.
TEST_F(FrameMesh, BinaryBytesInATextFormatAreRefusedBeforeAssimp) {
  const std::string smd = write(
      "nul.smd", std::string("version 1\nnodes\n0 \"ro\0ot\" -1\nend\nskeleton\ntime 0\n", 49));
  test::expectError(loadAnimation(smd), ErrorCode::kUnreadable, smd,
                    "binary data (byte 0x00 at offset 21) in a text format");
  test::expectError(loadMesh(smd), ErrorCode::kUnreadable, smd, "byte 0x00");
  // Also found by fuzzing: a section left open at the end of the file never returns.
  const std::string open = write("open.smd", "version 1\nnodes\n0 \"root\" -1\n1 \"tip\" 0\n");
  test::expectError(loadAnimation(open), ErrorCode::kUnreadable, open,
                    "the 'nodes' section is not closed by a line 'end'");
  const std::string words = write("words.smd", "version 1\nnodes 0 0 1\n");
  test::expectError(loadAnimation(words), ErrorCode::kUnreadable, words,
                    "line 2: expected a section");
  // And a node index of 25 digits made assimp ask for 412 GB.
  const std::string huge = write(
      "huge.smd", "version 1\nnodes\n0 \"root\" -1\n6666666666666666666666661 \"tip\" 0\nend\n");
  test::expectError(loadAnimation(huge), ErrorCode::kUnreadable, huge,
                    "line 4: not a line of the 'nodes' section");
  // A node that is its own parent made it ask for 26 GB.
  const std::string cycle =
      write("cycle.smd", "version 1\nnodes\n0 \"root\" -1\n1 \"tip\" 1\nend\n");
  test::expectError(loadAnimation(cycle), ErrorCode::kUnreadable, cycle,
                    "line 4: not a line of the 'nodes' section");
  // A nodes section with a blank line and no node, or a line of spaces, never returned.
  const std::string empty = write("empty.smd", "version 1\nnodes\n\nend\n");
  test::expectError(loadAnimation(empty), ErrorCode::kUnreadable, empty,
                    "line 3: a blank or indented line in the 'nodes' section");
  const std::string spaces = write("spaces.smd", "version 1\nnodes\n0 \"root\" -1\n \t\nend\n");
  test::expectError(loadAnimation(spaces), ErrorCode::kUnreadable, spaces,
                    "line 4: a blank or indented line in the 'nodes' section");
  const std::string none = write("none.smd", "version 1\nnodes\nend\n");
  test::expectError(loadAnimation(none), ErrorCode::kUnreadable, none,
                    "line 3: the 'nodes' section lists no node");
  // A number with 24 digits before its point made assimp ask for 33 GB.
  const std::string digits =
      write("digits.smd",
            "version 1\nnodes\n0 \"root\" -1\nend\nskeleton\ntime 0\n0 0 0 0 0 0 "
            "0000000000000000000001\nend\n");
  test::expectError(loadAnimation(digits), ErrorCode::kUnreadable, digits,
                    "line 7: not a line of the 'skeleton' section");
  // And one whose last "end" had no line break after it was read past its end.
  const std::string no_eol = write("no_eol.smd", "version 1\nnodes\n0 \"root\" -1\nend");
  test::expectError(loadAnimation(no_eol), ErrorCode::kUnreadable, no_eol,
                    "the last line does not end with a line break");
  // A form feed, which assimp takes for a line end, made it ask for 3.2 GB.
  const std::string ff = write("ff.smd", "version 1\nnodes\n0 \"root\" -1\nend\n\fend\n");
  test::expectError(loadAnimation(ff), ErrorCode::kUnreadable, ff, "byte 0x0c at offset 32");
  const std::string cr = write("cr.smd", "version 1\nnodes\n0 \"root\"\r-1\nend\n");
  test::expectError(loadAnimation(cr), ErrorCode::kUnreadable, cr,
                    "line 3: a carriage return inside the line");
}

}  // namespace
}  // namespace sphereset

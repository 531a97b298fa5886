// Unit tests of the command line's shared pieces: library errors to exit codes, and the coverage
// check that makes fit and tree exit with 7.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::cli {
namespace {

TEST(CliExitCodes, LibraryErrors) {
  EXPECT_EQ(exitFor(Error{ErrorCode::kInvalidArgument, ""}), 2);
  EXPECT_EQ(exitFor(Error{ErrorCode::kUnreadable, ""}), 3);
  EXPECT_EQ(exitFor(Error{ErrorCode::kInvalidData, ""}), 4);
  EXPECT_EQ(exitFor(Error{ErrorCode::kNotSolid, ""}), 5);
  EXPECT_EQ(exitFor(Error{ErrorCode::kWriteFailed, ""}), 6);
  EXPECT_EQ(kUncovered, 7);
  EXPECT_NE(std::string(kExitCodesHelp).find("7 the result failed its own coverage check"),
            std::string::npos);
}

EvalResult covered() {
  EvalResult r;
  r.surface_covered = r.interior_covered = true;
  return r;
}

TEST(CliCoverage, CoveredIsSilentSuccess) {
  std::ostringstream err;
  EXPECT_EQ(coverageExit("m.obj", "the fitted spheres", "out.txt", covered(), err), kOk);
  EXPECT_EQ(err.str(), "");
  EXPECT_EQ(coverageGaps(covered()), "");
}

TEST(CliCoverage, UncoveredSurfaceIsOneLine) {
  EvalResult r = covered();
  r.surface_covered = r.interior_covered = false;  // eval: no interior without the surface
  r.max_surface_gap = 0.0025;
  r.uncovered_triangles = 3;
  std::ostringstream err;
  EXPECT_EQ(coverageExit("m.obj", "the fitted spheres", "out.txt", r, err), kUncovered);
  EXPECT_EQ(err.str(),
            "sphereset: m.obj: the fitted spheres failed the coverage check: surface not covered "
            "(max gap 0.0025 of the diagonal, 3 triangles not covered) (written to out.txt "
            "anyway)\n");
}

TEST(CliCoverage, UncoveredInterior) {
  EvalResult r = covered();
  r.interior_covered = false;
  r.max_interior_gap = 0.125;
  EXPECT_EQ(coverageGaps(r), "interior not covered (max gap 0.125 of the diagonal)");
  r.surface_covered = false;
  r.uncovered_triangles = 1;
  EXPECT_EQ(coverageGaps(r),
            "surface not covered (max gap 0 of the diagonal, 1 triangles not covered), interior "
            "not covered (max gap 0.125 of the diagonal)");
}

// The whole path on a real evaluation: one sphere far too small for the robot link.
TEST(CliCoverage, TooSmallSphereOnAMesh) {
  auto m = loadMesh(std::string(SPHERESET_TEST_DATA_DIR) + "/fr3_link1_collision.stl");
  ASSERT_TRUE(m.ok());
  const SolidIndex index(m->mesh);
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  const std::vector<Sphere> small = {Sphere{Vec3(0.0, -0.037, -0.068), 0.05}};
  std::ostringstream err;
  EXPECT_EQ(coverageExit("link.stl", "the tree's leaves", "t.sph",
                         *evaluateSpheres(index, small, eo), err),
            kUncovered);
  EXPECT_NE(err.str().find("link.stl: the tree's leaves failed the coverage check: surface not "
                           "covered"),
            std::string::npos);
  const std::vector<Sphere> bound = {Sphere{Vec3(0.0, -0.037, -0.068), 0.17}};
  EXPECT_EQ(coverageExit("link.stl", "the fitted spheres", "out.txt",
                         *evaluateSpheres(index, bound, eo), err),
            kOk);
}

}  // namespace
}  // namespace sphereset::cli

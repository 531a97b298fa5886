// The limits on every size that input can drive, in one place. Each library function that
// allocates in proportion to such a size checks it against these before allocating and returns
// kInvalidArgument (an option) or kInvalidData (a file's content) naming the size and the limit.
// The command line, the Python module and the batch take their bounds from here.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "sphereset/status.hpp"

namespace sphereset::limits {

// Memory a single input may make the library allocate for one array of its own (bytes). Large
// enough for any mesh a user fits on a workstation; small enough that a typing error or a
// hostile file is refused at once instead of exhausting the machine.
inline constexpr double kMaxArrayBytes = 4.0 * 1024 * 1024 * 1024;  // 4 GiB

// Coordinates a query, pose or wrap accepts (length units): squares and products of two such
// numbers stay finite in double precision, so distances and lengths never overflow to inf.
inline constexpr double kMaxCoordinate = 1e30;

// The fit.
inline constexpr int kMaxSpheres = 1000000;              // spheres of one set
inline constexpr int64_t kMaxPoints = 100000000;         // points clustered
inline constexpr int kMaxIterations = 100000;            // assignment/update rounds
inline constexpr int kMaxRestarts = 1000;                // independent fits
inline constexpr double kMaxDecimation = 16.0;           // extra spheres, as a fraction of n
inline constexpr int kMaxOptimizerEvaluations = 100000;  // per sphere and round

// The evaluation.
inline constexpr int64_t kMaxUnionSamples = 100000000;      // Monte Carlo samples
inline constexpr int64_t kMaxProximitySegments = 10000000;  // proximity segments
inline constexpr int kMaxShadowResolution = 4096;           // pixels per side
inline constexpr int kMaxShadowLights = 4096;               // lights
// A curve's largest count (fitCurve): a run keeps every count's clustering of its points (100
// per sphere of the largest count), so memory grows with the square of the largest count.
inline constexpr int kMaxCurveCount = 1024;
inline constexpr int kMaxSurfaceDepth = 16;   // splits in four of a triangle by the certificate
inline constexpr int kMaxInteriorDepth = 12;  // octree levels below the 8³ grid

// Sphere trees: SphereTree::kMaxSlots (sphere_tree.hpp) slots over all levels.

// Animation: frames of one clip, and bones of one skin.
inline constexpr int64_t kMaxFrames = 1000000;
inline constexpr int64_t kMaxBones = 100000;

// Robots: nesting depth of a URDF's XML elements; obstacles (points or spheres) of one posed
// query, so that a hierarchy over them (branching 8, 7 levels below the root) stays within
// SphereTree::kMaxSlots; waypoints of one trajectory.
inline constexpr int kMaxXmlDepth = 256;
inline constexpr int64_t kMaxObstacles = int64_t{1} << 21;
inline constexpr int64_t kMaxWaypoints = 1000000;
// MJCF (read by MuJoCo): bytes of any file it names (includes, meshes, textures, height fields),
// pixels or samples along one side of a texture or height field, bodies and geoms of the
// compiled model. <composite> elements are refused whatever their count.
inline constexpr int64_t kMaxMjcfFileBytes = int64_t{512} * 1024 * 1024;  // 512 MiB
inline constexpr int kMaxMjcfGridSide = 16384;
inline constexpr int kMaxMjcfBodies = 10000;
inline constexpr int kMaxMjcfGeoms = 100000;

// The view's server (`sphereset view`): bytes of one request's body.
inline constexpr int64_t kMaxViewRequestBytes = int64_t{4} * 1024 * 1024;  // 4 MiB

// kInvalidArgument "`what` must be from `lo` to `hi` (got `value`)" when value is outside
// [lo, hi] or not a number; OK otherwise. The one wording of a range error.
Status checkRange(const std::string& what, double value, double lo, double hi);

// kInvalidData (or `code`) "`what` would need N GiB (more than the limit of 4 GiB)" when
// count × bytes_each exceeds kMaxArrayBytes; OK otherwise.
Status checkArray(const std::string& what, double count, double bytes_each,
                  ErrorCode code = ErrorCode::kInvalidData);

// kInvalidArgument "`what` (x y z): coordinates must be finite and at most 1e+30 in magnitude"
// when a value is NaN, infinite or beyond kMaxCoordinate; OK otherwise.
Status checkCoordinates(const std::string& what, std::span<const double> values);

}  // namespace sphereset::limits

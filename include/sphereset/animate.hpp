// Sphere sets that follow a deforming mesh (paper Sec. 6): the centres of a set fitted at the
// rest pose move with the mesh, by mean value coordinates over the rest mesh's vertices or by
// the skinning weights of the surface near them; every frame is certified (covered or not,
// largest gap), and radii can grow minimally to restore exact coverage ("rebound").
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/options.hpp"
#include "sphereset/result_fields.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// Mean value coordinates of x with respect to the vertices of a closed, outward-oriented
// triangle mesh (Ju, Schaefer and Warren 2005), for points inside and outside the solid:
// Σ_j w_j = 1 and Σ_j w_j p_j = x. A point on a triangle (or at a vertex) gets the
// triangle's barycentric coordinates (or the vertex alone). Outside the solid some weights are
// negative.
std::vector<double> meanValueCoordinates(const Mesh& rest, const Vec3& x);

// The coordinates of every point in double precision, row i over the rest mesh's vertices, so
// that the points of a deformed mesh are M * P with P the (vertices × 3) positions; rows in
// parallel (deterministic: each row on its own). Errors: kInvalidArgument (no vertices, a
// point that is not finite), kInvalidData (points × vertices beyond limits::kMaxArrayBytes).
Expected<Eigen::MatrixXd> meanValueMatrix(const Mesh& rest, const std::vector<Vec3>& points);

// What the per-frame update keeps of the coordinates: single precision only (half the memory
// traffic of the dense product, which is what bounds its time, and a quarter of the memory of
// keeping double precision too).
struct MeanValueWeights {
  // points × rest vertices, row-major.
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> weights;
  std::vector<Vec3> points;         // the weighted points at the rest pose
  std::vector<Vec3> rest_vertices;  // the rest mesh's vertices
  double seconds = 0.0;             // precomputation time
};

// The single-precision coordinates of every point (each row computed in double precision and
// rounded). Errors as meanValueMatrix's.
Expected<MeanValueWeights> meanValueWeights(const Mesh& rest, const std::vector<Vec3>& points);

// The points moved with the mesh (deformed: same count and order as the rest mesh's vertices),
// in displacement form: p + Σ_j w_j (v'_j - v_j), with the single-precision weights and
// double-precision sums, rows in parallel. Equal to Σ_j w_j v'_j up to the weights' rounding
// times the displacement, and exactly p at the rest pose. Errors: kInvalidArgument (a vertex
// count other than the rest mesh's).
Expected<std::vector<Vec3>> meanValuePoints(const MeanValueWeights& w,
                                            const std::vector<Vec3>& deformed);

// Skinning data of a rest mesh: per vertex, the weights of the bones moving it (each row sums
// to 1, or to 0 for a vertex no bone moves; such a vertex keeps its rest position).
struct SkinWeights {
  int bones = 0;
  Eigen::MatrixXd vertex_weights;  // rest vertices × bones
  // The mesh the weights belong to (the asset's bind pose; loadAnimation fills it). The frames'
  // vertices follow its order, so animateSpheres refuses a rest mesh that is not this pose.
  Mesh bind_pose;
};

// One pose of the deforming mesh: the vertices (same count and order as the rest mesh; the
// triangles are the rest mesh's) and, for skinned meshes, the transform of each bone from the
// rest pose to this pose (linear blend skinning: v' = Σ_b w_b T_b v).
struct AnimationFrame {
  double time = 0.0;  // seconds (informative)
  std::vector<Vec3> vertices;
  // The frame's own triangles when it was read from a mesh (empty: the rest mesh's). They must
  // be the rest mesh's: animateSpheres refuses a frame whose triangles differ.
  std::vector<Triangle> triangles;
  std::string name;  // where the frame came from (its file), named in messages; may be empty
  std::vector<Eigen::Affine3d> bones;
};

enum class CentreWeighting {
  kAuto,       // kBones when a skin with bones is given, else kMeanValue
  kMeanValue,  // centres = mean value coordinates of the rest mesh × deformed vertices (paper)
  kBones,      // centres skinned with the bone weights of the surface near them
};

struct AnimateOptions {
  CentreWeighting weighting = CentreWeighting::kAuto;
  // kBones: a centre takes the inverse-distance average of the bone weights of this many
  // nearest rest vertices.
  int bone_neighbours = 8;
  // Grow radii minimally each frame (the fit's guaranteed bound, started from the moved set)
  // so that the deformed surface and interior are covered exactly.
  bool rebound = false;
  // Fit a fresh set of as many spheres to each frame, to compare E_r (slow: a full fit).
  bool fresh_fit = false;
  FitOptions fit;  // for fresh_fit (num_spheres is set to the set's size)
  // The per-frame certificate. By default no union Monte Carlo, proximity or shadows: E_r is
  // the exact sum, coverage is certified.
  EvalOptions eval = [] {
    EvalOptions e;
    e.union_samples = 0;
    e.proximity_segments = 0;
    e.shadow_resolution = 0;
    return e;
  }();
  // Crossing pairs counted per frame (0 skips the check).
  int64_t max_crossings = 1000;
  // Called after each frame with its index (from the calling thread).
  std::function<void(int frame, int frames)> progress;
};

struct AnimateFrameResult {
  double time = 0.0;
  std::vector<Sphere> spheres;  // moved (and grown, with rebound)
  // The moved set with the rest radii (what the paper proposes).
  double er = 0.0;  // E_r: Σ outside volume / volume of the deformed mesh
  bool surface_covered = false, interior_covered = false;
  double max_gap = 0.0;  // largest surface or interior gap / diagonal of the deformed mesh
  // Crossing triangle pairs of the deformed mesh (at most AnimateOptions::max_crossings are
  // counted). Skinning can fold a mesh through itself; such a frame is no longer a solid, and
  // its E_r and certificates (and a fresh fit) are not meaningful.
  int64_t crossings = 0;
  // With rebound: the grown set (in `spheres`), certified again.
  double er_rebound = 0.0;
  bool rebound_covered = false;
  double radius_growth = 0.0;      // Σ (r' - r) / Σ r
  double max_radius_growth = 0.0;  // max (r' - r) / r
  int64_t grown = 0;               // spheres whose radius grew
  // With fresh_fit: E_r of a fresh fit of the frame.
  double er_fresh = 0.0;
  // Seconds: moving the centres, certifying (index + evaluation), rebound, fresh fit.
  double update_seconds = 0.0, eval_seconds = 0.0, rebound_seconds = 0.0, fresh_seconds = 0.0;
};

struct AnimateResult {
  std::vector<AnimateFrameResult> frames;
  CentreWeighting weighting = CentreWeighting::kMeanValue;  // the one used (kAuto resolved)
  double weights_seconds = 0.0;                             // precomputation of the centre weights
  int64_t frames_covered = 0;   // frames whose moved set covers surface and interior
  int64_t frames_crossing = 0;  // frames whose deformed mesh passes through itself
  double seconds = 0.0;
};

// The results as field lists (result_fields.hpp), for `sphereset animate`'s summary.json and
// Python's AnimateResult (which holds each frame field as an array over the frames): a frame's
// certificate, rebound and timings (its time and spheres are the doors' own); the totals.
std::vector<ResultField> animateFrameFields(const AnimateFrameResult& frame);
std::vector<ResultField> animateResultFields(const AnimateResult& result);

// "auto", "mvc", "bones": the weighting row's choices.
const char* centreWeightingName(CentreWeighting w);

// AnimateOptions' settings as one table (options.hpp): weighting (auto, mvc or bones),
// bone_neighbours and max_crossings. The command line's flags of `sphereset animate` and the
// keywords of Python's animate are made from it; setAnimateOption sets a row from the text a
// user typed, checkAnimateOptions checks a struct (with the evaluation's options) with the same
// messages. (rebound and fresh_fit are switches of their own.)
std::span<const OptionSpec> animateOptionTable();
Status setAnimateOption(AnimateOptions* o, const std::string& name, const std::string& text);
Status checkAnimateOptions(const AnimateOptions& o);

// How far (relative to the bind pose's bounding-box diagonal) a rest mesh's vertex may lie
// from the skin's bind pose: an asset's skinning matrices are single precision, and a mesh
// file written from the same pose rounds its coordinates.
inline constexpr double kBindPoseTolerance = 1e-5;

// Moves `spheres` (fitted to `rest`) through the frames. kBones needs `skin` (bone weights of
// the rest vertices) and per-frame bone transforms; whenever `skin` is given, `rest` must be its
// bind pose (same triangles, vertices within kBindPoseTolerance). Errors: kInvalidArgument (no
// spheres, kBones without skin or bone transforms, options out of range), kInvalidData (a frame
// whose vertex count or triangles differ from the rest mesh's, a rest mesh that is not the
// skin's bind pose, weights beyond limits::kMaxArrayBytes), kNotSolid (the rest mesh or a frame
// has no positive volume).
Expected<AnimateResult> animateSpheres(const Mesh& rest, const std::vector<Sphere>& spheres,
                                       const std::vector<AnimationFrame>& frames,
                                       const AnimateOptions& options = {},
                                       const SkinWeights* skin = nullptr);

// Bone weights of points from those of the nearest rest vertices (inverse-distance average of
// `neighbours` vertices): points × bones, rows summing to 1 (or 0 where no vertex has a bone).
// Errors: kInvalidArgument (skin rows other than the rest mesh's vertices, neighbours < 1),
// kInvalidData (points × bones beyond limits::kMaxArrayBytes).
Expected<Eigen::MatrixXd> pointBoneWeights(const Mesh& rest, const SkinWeights& skin,
                                           const std::vector<Vec3>& points, int neighbours);

// Linear blend skinning of points: p' = Σ_b w_b T_b p (points with no weight stay put). Errors:
// kInvalidArgument (weight rows other than the points, columns other than the bones).
Expected<std::vector<Vec3>> skinPoints(const std::vector<Vec3>& points,
                                       const Eigen::MatrixXd& weights,
                                       const std::vector<Eigen::Affine3d>& bones);

// A skinned, animated asset read through assimp (FBX, glTF 2.0, COLLADA, DirectX .x, SMD...).
struct SkinnedAsset {
  Mesh rest;  // the bind pose, welded (exactly coincident positions), as loadMesh would give
  SkinWeights skin;
  std::vector<std::string> bone_names;
  std::vector<std::string> clips;  // animation names ("" for an unnamed one)
};

struct SkinnedLoadOptions {
  std::string clip;  // empty: the first animation
  // Frames at the clip's keyframe times (0) or every 1/fps seconds over the clip.
  double fps = 0.0;
};

struct LoadedAnimation {
  SkinnedAsset asset;
  std::string clip;
  double duration = 0.0;  // seconds
  std::vector<AnimationFrame> frames;
};

// SkinnedLoadOptions' numbers as one table: fps (0, the default: the clip's keyframe times).
// `sphereset animate`/`render` --fps and Python's load_animation keyword are made from it.
std::span<const OptionSpec> skinnedLoadOptionTable();
Status setSkinnedLoadOption(SkinnedLoadOptions* o, const std::string& name,
                            const std::string& text);

// Reads the asset's bind pose and skin and evaluates the clip. Errors: kUnreadable (not
// readable), kInvalidData (no triangles, no animation; more than limits::kMaxBones bones, or
// frames × vertices beyond limits::kMaxArrayBytes), kInvalidArgument (fps outside its row,
// more than limits::kMaxFrames frames; no clip of that name: the message lists the
// clips).
Expected<LoadedAnimation> loadAnimation(const std::string& path,
                                        const SkinnedLoadOptions& options = {});

// One frame of a deforming mesh from a file that lists the same vertices and faces as the rest
// mesh's file, in the same order (`sphereset animate --frames`): its vertices are read as they
// are and taken through the rest's clean-up (LoadReport::vertex_of_file, source_face), so that
// vertices which the deformation makes coincide stay distinct (welding the frame on its own
// merged them); its faces come the same way, for animateSpheres to compare with the rest's.
// `rest` is the rest mesh as loadMesh read it. Errors: those of loadMesh; kInvalidData when the
// file's vertex or face count differs from the rest file's (both named).
Expected<AnimationFrame> loadFrameMesh(const std::string& path, const LoadedMesh& rest);

}  // namespace sphereset

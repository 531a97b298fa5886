// Animating a sphere set (paper Sec. 6): the set is fitted at the rest pose, and the centres
// follow the mesh as linear combinations of the deformed vertices (mean value coordinates,
// Ju et al. 2005, see mean_value.cpp), or by linear blend skinning with the bone weights of the
// surface near each centre. Radii stay fixed, as the paper proposes; beyond it, every frame is
// certified by the evaluation's coverage certificate, and "rebound" grows radii minimally
// with the fit's guaranteed bound (boundSpheres, fit.hpp), started from the moved set.
#include "sphereset/animate.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "sphereset/limits.hpp"
#include "sphereset/mesh_defects.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A neighbour closer than this fraction of the diagonal counts as at this distance, so that a
// centre on a vertex does not divide by zero.
constexpr double kNearestFloorRel = 1e-9;
struct Certificate {
  double er = 0.0;
  bool surface = false, interior = false;
  double gap = 0.0;
};

Expected<Certificate> certify(const SolidIndex& index, const std::vector<Sphere>& sp,
                              const EvalOptions& o) {
  auto e = evaluateSpheres(index, sp, o);
  if (!e) return e.error();
  return Certificate{e->er_sum, e->surface_covered, e->interior_covered,
                     std::max(e->max_surface_gap, e->max_interior_gap)};
}

// Whether `rest` is the skin's bind pose: the same triangles, every vertex within
// kBindPoseTolerance of the bind pose's diagonal.
Status checkBindPose(const Mesh& rest, const Mesh& bind) {
  if (bind.vertices.size() != rest.vertices.size())
    return Error{ErrorCode::kInvalidData,
                 "the rest mesh has " + std::to_string(rest.vertices.size()) +
                     " vertices, the skin's bind pose " + std::to_string(bind.vertices.size())};
  const double tol = kBindPoseTolerance * boundingBox(bind).diagonal();
  for (size_t i = 0; i < bind.vertices.size(); ++i)
    if (!((bind.vertices[i] - rest.vertices[i]).norm() <= tol))
      return Error{ErrorCode::kInvalidData,
                   "the rest mesh is not the skin's bind pose (vertex " + std::to_string(i) +
                       " differs); give the asset's bind pose as the rest mesh"};
  if (bind.triangles != rest.triangles)
    return Error{ErrorCode::kInvalidData,
                 "the rest mesh is not the skin's bind pose (its triangles differ); give the "
                 "asset's bind pose as the rest mesh"};
  return {};
}

// kAuto: the bone weights when a skin with bones is given (they kept sets tighter, see
// docs/benchmarks.md), else mean value coordinates.
CentreWeighting resolvedWeighting(const AnimateOptions& o, const SkinWeights* skin) {
  if (o.weighting != CentreWeighting::kAuto) return o.weighting;
  return skin && skin->bones > 0 ? CentreWeighting::kBones : CentreWeighting::kMeanValue;
}

// Every precondition of animateSpheres, before anything is allocated.
Status checkAnimateInputs(const Mesh& rest, const std::vector<Sphere>& spheres,
                          const std::vector<AnimationFrame>& frames, const AnimateOptions& o,
                          const SkinWeights* skin) {
  if (spheres.empty()) return Error{ErrorCode::kInvalidData, "no spheres to animate"};
  if (Status st = checkAnimateOptions(o); !st) return st;
  for (size_t i = 0; i < spheres.size(); ++i)
    if (!spheres[i].center.allFinite() || !(spheres[i].radius >= 0.0) ||
        !std::isfinite(spheres[i].radius))
      return Error{ErrorCode::kInvalidArgument,
                   "sphere " + std::to_string(i) + " is not finite or has a negative radius"};
  if (!(signedVolume(rest) > 0.0))
    return Error{ErrorCode::kNotSolid, "the rest mesh has no positive volume"};
  const bool bones = resolvedWeighting(o, skin) == CentreWeighting::kBones;
  const auto nv = static_cast<Eigen::Index>(rest.vertices.size());
  if (skin) {
    if (Status st = checkBindPose(rest, skin->bind_pose); !st) return st;
  }
  if (bones && (!skin || skin->bones <= 0 || skin->vertex_weights.rows() != nv))
    return Error{ErrorCode::kInvalidArgument,
                 "weighting bones needs the skin weights of the rest mesh's vertices (a skinned "
                 "asset)"};
  for (size_t f = 0; f < frames.size(); ++f) {
    const std::string frame =
        "frame " + std::to_string(f) + (frames[f].name.empty() ? "" : " (" + frames[f].name + ")");
    if (frames[f].vertices.size() != rest.vertices.size())
      return Error{ErrorCode::kInvalidData,
                   frame + " has " + std::to_string(frames[f].vertices.size()) +
                       " vertices, the rest mesh " + std::to_string(rest.vertices.size()) +
                       " (frames need the rest mesh's vertices in its order)"};
    if (!frames[f].triangles.empty() && frames[f].triangles != rest.triangles)
      return Error{ErrorCode::kInvalidData,
                   frame +
                       ": its triangles differ from the rest mesh's (frames need the rest "
                       "mesh's vertices in its order)"};
    if (bones && frames[f].bones.size() != static_cast<size_t>(skin->bones))
      return Error{ErrorCode::kInvalidArgument,
                   frame + " has " + std::to_string(frames[f].bones.size()) +
                       " bone transforms, the skin " + std::to_string(skin->bones)};
  }
  return {};
}

}  // namespace

Expected<Eigen::MatrixXd> pointBoneWeights(const Mesh& rest, const SkinWeights& skin,
                                           const std::vector<Vec3>& points, int neighbours) {
  if (skin.bones < 0 || skin.vertex_weights.cols() != skin.bones ||
      skin.vertex_weights.rows() != static_cast<Eigen::Index>(rest.vertices.size()))
    return Error{ErrorCode::kInvalidArgument,
                 "the skin has weights of " + std::to_string(skin.vertex_weights.rows()) +
                     " vertices over " + std::to_string(skin.vertex_weights.cols()) +
                     " bones, the rest mesh " + std::to_string(rest.vertices.size()) +
                     " vertices and the skin " + std::to_string(skin.bones) + " bones"};
  if (neighbours < 1)
    return Error{ErrorCode::kInvalidArgument,
                 "neighbours must be at least 1 (got " + std::to_string(neighbours) + ")"};
  for (size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      return Error{ErrorCode::kInvalidArgument,
                   "point " + std::to_string(i) + " is not finite (NaN or infinite)"};
  if (Status st = limits::checkArray("bone weights of " + std::to_string(points.size()) +
                                         " points over " + std::to_string(skin.bones) + " bones",
                                     static_cast<double>(points.size()),
                                     sizeof(double) * static_cast<double>(skin.bones));
      !st)
    return st.error();
  const auto np = static_cast<Eigen::Index>(points.size());
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(np, skin.bones);
  const size_t nv = rest.vertices.size();
  const auto k = static_cast<size_t>(std::clamp<int64_t>(neighbours, 1, int64_t(nv)));
  const double floor = kNearestFloorRel * boundingBox(rest).diagonal();
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, np), [&](const auto& r) {
    std::vector<std::pair<double, int32_t>> dist(nv);
    for (Eigen::Index i = r.begin(); i != r.end(); ++i) {
      const Vec3& p = points[static_cast<size_t>(i)];
      for (size_t j = 0; j < nv; ++j)
        dist[j] = {(rest.vertices[j] - p).squaredNorm(), static_cast<int32_t>(j)};
      std::partial_sort(dist.begin(), dist.begin() + static_cast<std::ptrdiff_t>(k), dist.end());
      Eigen::RowVectorXd w = Eigen::RowVectorXd::Zero(skin.bones);
      for (size_t q = 0; q < k; ++q)
        w += skin.vertex_weights.row(dist[q].second) / std::max(floor, std::sqrt(dist[q].first));
      const double sum = w.sum();
      if (sum > 0.0) out.row(i) = w / sum;
    }
  });
  return out;
}

Expected<std::vector<Vec3>> skinPoints(const std::vector<Vec3>& points,
                                       const Eigen::MatrixXd& weights,
                                       const std::vector<Eigen::Affine3d>& bones) {
  if (weights.rows() != static_cast<Eigen::Index>(points.size()) ||
      weights.cols() != static_cast<Eigen::Index>(bones.size()))
    return Error{ErrorCode::kInvalidArgument, "weights of " + std::to_string(weights.rows()) +
                                                  " points over " + std::to_string(weights.cols()) +
                                                  " bones, for " + std::to_string(points.size()) +
                                                  " points and " + std::to_string(bones.size()) +
                                                  " bone transforms"};
  std::vector<Vec3> out(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Matrix<double, 3, 4> m = Eigen::Matrix<double, 3, 4>::Zero();
    double sum = 0.0;
    for (size_t b = 0; b < bones.size(); ++b) {
      const double w = weights(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(b));
      if (w == 0.0) continue;
      m += w * bones[b].affine();
      sum += w;
    }
    out[i] = sum > 0.0 ? Vec3(m.leftCols<3>() * points[i] + m.col(3) + (1.0 - sum) * points[i])
                       : points[i];
  }
  return out;
}

Expected<AnimateResult> animateSpheres(const Mesh& rest, const std::vector<Sphere>& spheres,
                                       const std::vector<AnimationFrame>& frames,
                                       const AnimateOptions& options, const SkinWeights* skin) {
  const auto t0 = Clock::now();
  if (Status st = checkAnimateInputs(rest, spheres, frames, options, skin); !st) return st.error();
  const bool bones = resolvedWeighting(options, skin) == CentreWeighting::kBones;
  std::vector<Vec3> centres(spheres.size());
  for (size_t i = 0; i < spheres.size(); ++i) centres[i] = spheres[i].center;
  AnimateResult res;
  res.weighting = bones ? CentreWeighting::kBones : CentreWeighting::kMeanValue;
  const auto tw = Clock::now();
  MeanValueWeights mvc;
  Eigen::MatrixXd bone_w;
  if (bones) {
    auto bw = pointBoneWeights(rest, *skin, centres, options.bone_neighbours);
    if (!bw) return bw.error();
    bone_w = std::move(*bw);
  } else {
    auto w = meanValueWeights(rest, centres);
    if (!w) return w.error();
    mvc = std::move(*w);
  }
  res.weights_seconds = since(tw);

  const auto n = static_cast<Eigen::Index>(spheres.size());
  for (size_t f = 0; f < frames.size(); ++f) {
    const AnimationFrame& frame = frames[f];
    AnimateFrameResult fr;
    fr.time = frame.time;
    const auto tu = Clock::now();
    std::vector<Sphere> moved = spheres;
    // The inputs were checked above: these cannot fail.
    const std::vector<Vec3> moved_centres = bones ? skinPoints(centres, bone_w, frame.bones).value()
                                                  : meanValuePoints(mvc, frame.vertices).value();
    for (size_t i = 0; i < moved.size(); ++i) moved[i].center = moved_centres[i];
    fr.update_seconds = since(tu);

    const auto te = Clock::now();
    const Mesh deformed{frame.vertices, rest.triangles};
    if (!(signedVolume(deformed) > 0.0))
      return Error{ErrorCode::kNotSolid,
                   "frame " + std::to_string(f) + ": the deformed mesh has no positive volume"};
    if (options.max_crossings > 0) {
      SelfIntersectionOptions so;
      so.max_pairs = options.max_crossings;
      fr.crossings = static_cast<int64_t>(findSelfIntersections(deformed, so).pairs.size());
      if (fr.crossings > 0) ++res.frames_crossing;
    }
    const SolidIndex index(deformed);
    const auto certified = certify(index, moved, options.eval);
    if (!certified)
      return Error{certified.error().code,
                   "frame " + std::to_string(f) + ": " + certified.error().message};
    const Certificate& c = *certified;
    fr.er = c.er;
    fr.surface_covered = c.surface;
    fr.interior_covered = c.interior;
    fr.max_gap = c.gap;
    fr.eval_seconds = since(te);
    if (c.surface && c.interior) ++res.frames_covered;

    if (options.rebound) {
      const auto tr = Clock::now();
      BoundOptions bo;
      bo.interior_max_depth = options.eval.interior_max_depth;
      auto bounded = boundSpheres(index, moved, bo);
      if (!bounded)
        return Error{bounded.error().code,
                     "frame " + std::to_string(f) + ": " + bounded.error().message};
      std::vector<Sphere> grown = std::move(bounded).value();
      double sum_r = 0.0, sum_dr = 0.0;
      for (size_t i = 0; i < grown.size(); ++i) {
        const double dr = grown[i].radius - moved[i].radius;
        sum_r += moved[i].radius;
        sum_dr += dr;
        if (dr > 0.0) {
          ++fr.grown;
          if (moved[i].radius > 0.0)
            fr.max_radius_growth = std::max(fr.max_radius_growth, dr / moved[i].radius);
        }
      }
      fr.radius_growth = sum_r > 0.0 ? sum_dr / sum_r : 0.0;
      const auto regrown = certify(index, grown, options.eval);
      if (!regrown)
        return Error{regrown.error().code,
                     "frame " + std::to_string(f) + ": " + regrown.error().message};
      const Certificate& g = *regrown;
      fr.er_rebound = g.er;
      fr.rebound_covered = g.surface && g.interior;
      moved = std::move(grown);
      fr.rebound_seconds = since(tr);
    }
    if (options.fresh_fit) {
      const auto tf = Clock::now();
      FitOptions fo = options.fit;
      fo.num_spheres = static_cast<int>(n);
      fo.progress = nullptr;
      auto fit = fitSpheres(index, fo);
      if (!fit)
        return Error{fit.error().code, "frame " + std::to_string(f) + ": " + fit.error().message};
      fr.er_fresh = fit->energy / signedVolume(deformed);
      fr.fresh_seconds = since(tf);
    }
    fr.spheres = std::move(moved);
    res.frames.push_back(std::move(fr));
    if (options.progress) options.progress(static_cast<int>(f), static_cast<int>(frames.size()));
  }
  res.seconds = since(t0);
  return res;
}

}  // namespace sphereset

// Mean value coordinates for closed triangle meshes: Ju, Schaefer and Warren, "Mean value
// coordinates for closed triangular meshes", ACM Trans. Graph. 24(3), 2005 — the closed-form
// integral over each spherical triangle, with their robust evaluation near the surface (a
// point at a vertex takes that vertex, a point on a triangle its barycentric coordinates, a
// triangle seen edge-on from outside it contributes nothing). Points outside the solid are
// handled by the same signed formula.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "sphereset/animate.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {
namespace {

// A point closer to a vertex than this fraction of the mesh's bounding-box diagonal is that
// vertex.
constexpr double kVertexEpsRel = 1e-12;
// Half the arc sum of a spherical triangle within this many radians of π: the point lies on the
// triangle's plane inside it. π - h shrinks with the square of the distance to the triangle, and
// the closed form loses accuracy as 1/(π - h): this threshold treats points within about 1e-5
// of the triangle's size as on it (an error below that distance), and keeps the formula's
// error below about 1e-6 of that size elsewhere.
constexpr double kOnTriangleEps = 1e-10;
// An arc within this many radians of π: the point lies on that edge, between its ends. The
// arc's deficit grows linearly with the distance to the edge (about distance / length), so
// points within about 1e-6 of an edge's length snap to it; the closed form, which divides by
// the arc's sine, stays accurate to about 1e-7 of the size outside that band.
constexpr double kOnEdgeEps = 1e-6;
// |s_i| below this (dimensionless sine): the point lies in the triangle's plane outside it, and
// the triangle's spherical projection has no area.
// Rows of the per-frame update per parallel task.
constexpr Eigen::Index kRowsPerTask = 16;
// Weights (points × vertices) below which the update runs on one thread.
constexpr Eigen::Index kParallelProduct = Eigen::Index{1} << 20;
// Vertices per single-precision partial sum of the update (its rounding error grows with the
// chunk's length; the chunks are summed in double precision).
constexpr Eigen::Index kVerticesPerChunk = 512;
constexpr double kEdgeOnEps = 1e-10;

// Writes the coordinates into w (size vertices), using the scratch arrays d and u.
void coordinates(const Mesh& m, const Vec3& x, double vertex_eps, double* w, double* d, Vec3* u) {
  const size_t nv = m.vertices.size();
  for (size_t j = 0; j < nv; ++j) {
    const Vec3 r = m.vertices[j] - x;
    d[j] = r.norm();
    w[j] = 0.0;
    if (d[j] < vertex_eps) {
      w[j] = 1.0;
      for (size_t k = j + 1; k < nv; ++k) w[k] = 0.0;
      for (size_t k = 0; k < j; ++k) w[k] = 0.0;
      return;
    }
    u[j] = r / d[j];
  }
  for (const Triangle& t : m.triangles) {
    // The arcs opposite each vertex. Ju et al. write θ = 2 asin(|u_a - u_b| / 2), which loses
    // half the digits near π (a point close to an edge); the angle from its sine and cosine
    // keeps them all.
    double theta[3];
    for (int i = 0; i < 3; ++i) {
      const Vec3& ua = u[t[(i + 1) % 3]];
      const Vec3& ub = u[t[(i + 2) % 3]];
      theta[i] = std::atan2(ua.cross(ub).norm(), ua.dot(ub));
    }
    // Close to the inside of an edge (the arc opposite a vertex near π): the formula divides by
    // the arc's sine, so the point takes the edge's linear coordinates.
    for (int i = 0; i < 3; ++i)
      if (std::numbers::pi - theta[i] < kOnEdgeEps) {
        const int32_t a = t[(i + 1) % 3], b = t[(i + 2) % 3];
        std::fill(w, w + nv, 0.0);
        w[a] = d[b] / (d[a] + d[b]);
        w[b] = d[a] / (d[a] + d[b]);
        return;
      }
    const double h = 0.5 * (theta[0] + theta[1] + theta[2]);
    if (std::numbers::pi - h < kOnTriangleEps) {
      // On the triangle: 2D barycentric coordinates, nothing else.
      std::fill(w, w + nv, 0.0);
      double sum = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double b = std::sin(theta[i]) * d[t[(i + 2) % 3]] * d[t[(i + 1) % 3]];
        w[t[i]] = b;
        sum += b;
      }
      for (int i = 0; i < 3; ++i) w[t[i]] /= sum;
      return;
    }
    const double sign = u[t[0]].dot(u[t[1]].cross(u[t[2]])) >= 0.0 ? 1.0 : -1.0;
    double c[3], s[3];
    bool edge_on = false;
    for (int i = 0; i < 3; ++i) {
      const int ip = (i + 1) % 3, im = (i + 2) % 3;
      c[i] =
          2.0 * std::sin(h) * std::sin(h - theta[i]) / (std::sin(theta[ip]) * std::sin(theta[im])) -
          1.0;
      s[i] = sign * std::sqrt(std::max(0.0, 1.0 - c[i] * c[i]));
      if (!(std::abs(s[i]) > kEdgeOnEps)) edge_on = true;
    }
    if (edge_on) continue;
    for (int i = 0; i < 3; ++i) {
      const int ip = (i + 1) % 3, im = (i + 2) % 3;
      w[t[i]] += (theta[i] - c[ip] * theta[im] - c[im] * theta[ip]) /
                 (d[t[i]] * std::sin(theta[ip]) * s[im]);
    }
  }
  double sum = 0.0;
  for (size_t j = 0; j < nv; ++j) sum += w[j];
  for (size_t j = 0; j < nv; ++j) w[j] /= sum;
}

}  // namespace

std::vector<double> meanValueCoordinates(const Mesh& rest, const Vec3& x) {
  const size_t nv = rest.vertices.size();
  std::vector<double> w(nv), d(nv);
  std::vector<Vec3> u(nv);
  coordinates(rest, x, kVertexEpsRel * boundingBox(rest).diagonal(), w.data(), d.data(), u.data());
  return w;
}

namespace {

// The checks shared by meanValueMatrix and meanValueWeights: a mesh with vertices, finite
// points, and the matrix within the memory limit (`bytes` per weight).
Status checkWeightInputs(const Mesh& rest, const std::vector<Vec3>& points, double bytes) {
  if (rest.vertices.empty())
    return Error{ErrorCode::kInvalidArgument, "the rest mesh has no vertices"};
  for (size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      return Error{ErrorCode::kInvalidArgument,
                   "point " + std::to_string(i) + " is not finite (NaN or infinite)"};
  return limits::checkArray(
      "mean value weights of " + std::to_string(points.size()) + " points over " +
          std::to_string(rest.vertices.size()) + " vertices",
      static_cast<double>(points.size()), bytes * static_cast<double>(rest.vertices.size()));
}

// Row i of the coordinates (double precision) handed to `store(i, row)`, rows in parallel. A
// point whose coordinates are not finite numbers (so far from the mesh, 1e30 say, that the
// angles between its directions to the vertices round to zero) is an error naming the first
// such point, never a row of infinities.
template <class Store>
Status coordinateRows(const Mesh& rest, const std::vector<Vec3>& points, Store store) {
  const size_t nv = rest.vertices.size();
  const Aabb box = boundingBox(rest);
  const double eps = kVertexEpsRel * box.diagonal();
  std::atomic<size_t> first_bad{points.size()};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size()), [&](const auto& r) {
    std::vector<double> row(nv), d(nv);
    std::vector<Vec3> u(nv);
    for (size_t i = r.begin(); i != r.end(); ++i) {
      coordinates(rest, points[i], eps, row.data(), d.data(), u.data());
      bool finite = true;
      for (double w : row) finite = finite && std::isfinite(w);
      if (!finite) {
        size_t seen = first_bad.load();
        while (i < seen && !first_bad.compare_exchange_weak(seen, i)) {
        }
        continue;
      }
      store(static_cast<Eigen::Index>(i), row);
    }
  });
  if (const size_t bad = first_bad.load(); bad < points.size()) {
    const double far = (points[bad] - 0.5 * (box.min + box.max)).norm();
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  ": its mean value coordinates are not finite in double precision (it lies "
                  "%.3g from the mesh's centre, %.3g times the mesh's diagonal)",
                  far, far / std::max(box.diagonal(), std::numeric_limits<double>::min()));
    return Error{ErrorCode::kInvalidArgument, "point " + std::to_string(bad) + buf};
  }
  return {};
}

}  // namespace

Expected<Eigen::MatrixXd> meanValueMatrix(const Mesh& rest, const std::vector<Vec3>& points) {
  if (Status st = checkWeightInputs(rest, points, sizeof(double)); !st) return st.error();
  Eigen::MatrixXd out(static_cast<Eigen::Index>(points.size()),
                      static_cast<Eigen::Index>(rest.vertices.size()));
  if (Status st = coordinateRows(rest, points,
                                 [&](Eigen::Index i, const std::vector<double>& row) {
                                   for (size_t j = 0; j < row.size(); ++j)
                                     out(i, static_cast<Eigen::Index>(j)) = row[j];
                                 });
      !st)
    return st.error();
  return out;
}

Expected<MeanValueWeights> meanValueWeights(const Mesh& rest, const std::vector<Vec3>& points) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Status st = checkWeightInputs(rest, points, sizeof(float)); !st) return st.error();
  MeanValueWeights out;
  out.weights.resize(static_cast<Eigen::Index>(points.size()),
                     static_cast<Eigen::Index>(rest.vertices.size()));
  if (Status st = coordinateRows(rest, points,
                                 [&](Eigen::Index i, const std::vector<double>& row) {
                                   for (size_t j = 0; j < row.size(); ++j)
                                     out.weights(i, static_cast<Eigen::Index>(j)) =
                                         static_cast<float>(row[j]);
                                 });
      !st)
    return st.error();
  out.points = points;
  out.rest_vertices = rest.vertices;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

Expected<std::vector<Vec3>> meanValuePoints(const MeanValueWeights& w,
                                            const std::vector<Vec3>& deformed) {
  if (deformed.size() != w.rest_vertices.size() ||
      w.weights.cols() != static_cast<Eigen::Index>(deformed.size()) ||
      w.weights.rows() != static_cast<Eigen::Index>(w.points.size()))
    return Error{ErrorCode::kInvalidArgument,
                 "the deformed mesh has " + std::to_string(deformed.size()) +
                     " vertices, the weights are over " + std::to_string(w.rest_vertices.size())};
  const auto nv = static_cast<Eigen::Index>(deformed.size());
  Eigen::Matrix<float, Eigen::Dynamic, 3> disp(nv, 3);
  for (Eigen::Index j = 0; j < nv; ++j)
    disp.row(j) = (deformed[static_cast<size_t>(j)] - w.rest_vertices[static_cast<size_t>(j)])
                      .cast<float>()
                      .transpose();
  std::vector<Vec3> out = w.points;
  const auto np = static_cast<Eigen::Index>(out.size());
  // Small products run on the calling thread (waking workers would cost more than the work).
  // The simple partitioner always cuts the rows into the same blocks, so the products, and
  // their rounding, do not depend on the number of threads.
  const Eigen::Index grain =
      np * nv < kParallelProduct ? std::max<Eigen::Index>(np, 1) : kRowsPerTask;
  tbb::parallel_for(
      tbb::blocked_range<Eigen::Index>(0, np, grain),
      [&](const tbb::blocked_range<Eigen::Index>& r) {
        const Eigen::Index rows = r.end() - r.begin();
        Eigen::Matrix<double, Eigen::Dynamic, 3> acc =
            Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(rows, 3);
        // Single-precision products over chunks of vertices, summed in double
        // precision.
        for (Eigen::Index j0 = 0; j0 < nv; j0 += kVerticesPerChunk) {
          const Eigen::Index cols = std::min(kVerticesPerChunk, nv - j0);
          acc += (w.weights.block(r.begin(), j0, rows, cols) * disp.middleRows(j0, cols))
                     .cast<double>();
        }
        for (Eigen::Index i = 0; i < rows; ++i)
          out[static_cast<size_t>(r.begin() + i)] += acc.row(i).transpose();
      },
      tbb::simple_partitioner());
  return out;
}

}  // namespace sphereset

// A square bar along x, bent at its middle by two bones (shared by the animation tests).
#pragma once

#include <cmath>
#include <vector>

#include "sphereset/animate.hpp"

namespace sphereset::test {

struct BentBar {
  Mesh rest;
  SkinWeights skin;
};

// The bar [0, length] × [-0.5, 0.5]², `rings` cross-sections of 4·k vertices, end caps fanned
// around a centre vertex. Bone 0 holds x < joint - blend, bone 1 x > joint + blend, linear in
// between.
inline BentBar makeBentBar(double length = 4.0, int rings = 41, int k = 4, double blend = 0.1) {
  BentBar b;
  const int per = 4 * k;
  auto ringPoint = [&](int j) {
    const int side = j / k;
    const double s = static_cast<double>(j % k) / k;  // along the side, counter-clockwise
    switch (side) {
      case 0:
        return Eigen::Vector2d(-0.5 + s, -0.5);
      case 1:
        return Eigen::Vector2d(0.5, -0.5 + s);
      case 2:
        return Eigen::Vector2d(0.5 - s, 0.5);
      default:
        return Eigen::Vector2d(-0.5, 0.5 - s);
    }
  };
  for (int r = 0; r < rings; ++r) {
    const double x = length * r / (rings - 1);
    for (int j = 0; j < per; ++j) {
      const Eigen::Vector2d q = ringPoint(j);
      b.rest.vertices.emplace_back(x, q.x(), q.y());
    }
  }
  const auto c0 = static_cast<int32_t>(b.rest.vertices.size());
  b.rest.vertices.emplace_back(0.0, 0.0, 0.0);
  b.rest.vertices.emplace_back(length, 0.0, 0.0);
  auto at = [&](int r, int j) { return static_cast<int32_t>(r * per + (j % per)); };
  for (int r = 0; r + 1 < rings; ++r)
    for (int j = 0; j < per; ++j) {
      b.rest.triangles.push_back({at(r, j), at(r + 1, j + 1), at(r + 1, j)});
      b.rest.triangles.push_back({at(r, j), at(r, j + 1), at(r + 1, j + 1)});
    }
  for (int j = 0; j < per; ++j) {
    b.rest.triangles.push_back({c0, at(0, j + 1), at(0, j)});
    b.rest.triangles.push_back({c0 + 1, at(rings - 1, j), at(rings - 1, j + 1)});
  }
  const double joint = 0.5 * length;
  b.skin.bones = 2;
  b.skin.vertex_weights.resize(static_cast<Eigen::Index>(b.rest.vertices.size()), 2);
  for (size_t i = 0; i < b.rest.vertices.size(); ++i) {
    const double x = b.rest.vertices[i].x();
    const double w1 = std::clamp((x - (joint - blend)) / (2.0 * blend), 0.0, 1.0);
    b.skin.vertex_weights(static_cast<Eigen::Index>(i), 0) = 1.0 - w1;
    b.skin.vertex_weights(static_cast<Eigen::Index>(i), 1) = w1;
  }
  b.skin.bind_pose = b.rest;
  return b;
}

// The pose with bone 1 turned by `angle` radians about the z axis through the joint's inner
// edge (y = 0.5): the bar bends towards +y, its outer side stretches, and the inner side does
// not pass through itself.
inline AnimationFrame bendFrame(const BentBar& b, double angle, double length = 4.0) {
  AnimationFrame f;
  const Vec3 joint(0.5 * length, 0.5, 0.0);
  Eigen::Affine3d t1 = Eigen::Translation3d(joint) * Eigen::AngleAxisd(angle, Vec3::UnitZ()) *
                       Eigen::Translation3d(-joint);
  f.bones = {Eigen::Affine3d::Identity(), t1};
  f.vertices = skinPoints(b.rest.vertices, b.skin.vertex_weights, f.bones).value();
  return f;
}

}  // namespace sphereset::test

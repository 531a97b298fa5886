// Private: the cameras of a render, one per view.
#pragma once

#include <vector>

#include "sphereset/render.hpp"

namespace sphereset {

// A pinhole camera looking at the scene, drawing into one tile of the image.
struct Camera {
  Vec3 eye, forward, right, up;  // orthonormal frame
  double tan_half_fov = 0.0;
  int x0 = 0, y0 = 0, width = 0, height = 0;  // the tile
  // Pixel coordinates (column, row; may fall outside the tile) where p appears; false when p
  // is behind the camera.
  bool project(const Vec3& p, double* px, double* py) const;
};

// The cameras of a render: one per view, tiled 1x1, 2x1 or 2x2 (3 or 4 views), each as close
// as keeps the mesh's vertices (when given) and the spheres in its view (the corners of
// options.bounds when given).
std::vector<Camera> renderCameras(const SolidIndex* mesh, const std::vector<Sphere>& spheres,
                                  const RenderOptions& options);

}  // namespace sphereset

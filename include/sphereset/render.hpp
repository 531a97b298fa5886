// Pictures for checking a fit by eye: a CPU ray tracer that draws the mesh, the spheres
// translucent over it and a ground plane with the shadow, from several views in one image.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

enum class View { kFront, kSide, kTop, kThreeQuarter };

struct RenderOptions {
  int width = 1200, height = 900;  // the whole image; views are tiled in a grid
  std::vector<View> views = {View::kFront, View::kSide, View::kTop, View::kThreeQuarter};
  int up_axis = 1;              // 0 x, 1 y, 2 z
  double sphere_opacity = 0.3;  // per sphere surface crossed
  bool ground = true;           // ground plane under the object, with shadows
  double field_of_view = 30.0;  // degrees, vertical
};

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, top row first
  std::array<uint8_t, 3> at(int x, int y) const {
    const size_t i = 3 * (static_cast<size_t>(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

// A pinhole camera looking at the scene, drawing into one tile of the image.
struct Camera {
  Vec3 eye, forward, right, up;  // orthonormal frame
  double tan_half_fov = 0.0;
  int x0 = 0, y0 = 0, width = 0, height = 0;  // the tile
  // Pixel coordinates (column, row; may fall outside the tile) where p appears; false when p
  // is behind the camera.
  bool project(const Vec3& p, double* px, double* py) const;
};

// The cameras of a render: one per view, tiled 1x1, 2x1 or 2x2 (3 or 4 views), framing the
// mesh (when given) and the spheres.
std::vector<Camera> renderCameras(const SolidIndex* mesh, const std::vector<Sphere>& spheres,
                                  const RenderOptions& options);

// Renders the mesh (may be null: spheres only) and the spheres (may be empty: mesh only).
// Errors: kInvalidArgument for an empty scene, a size out of [16, 16384] or no views.
// Deterministic; rows are traced in parallel.
Expected<Image> renderScene(const SolidIndex* mesh, const std::vector<Sphere>& spheres,
                            const RenderOptions& options);

// Writes an 8-bit RGB PNG atomically.
Status writePng(const std::string& path, const Image& image);

}  // namespace sphereset

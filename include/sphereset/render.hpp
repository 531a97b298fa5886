// Pictures for checking a fit by eye: a CPU ray tracer that draws the mesh, the spheres
// translucent over it and a ground plane with the shadow, from several views in one image.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
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
  // The box the cameras frame, the ground lies under and the light scales with; unset: the
  // scene's own bounds. Frames of a motion share one box so that the motion shows. Each view's
  // camera looks at the box's centre from as close as keeps the scene whole in view (every mesh
  // vertex and sphere; the box's corners when the box is given), with a small margin.
  std::optional<Aabb> bounds;
};

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, top row first
  std::array<uint8_t, 3> at(int x, int y) const {
    const size_t i = 3 * (static_cast<size_t>(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

// Renders the mesh (may be null: spheres only) and the spheres (may be empty: mesh only).
// Errors: kInvalidArgument for an empty scene, a size out of [16, 16384] or no views.
// Deterministic; rows are traced in parallel.
Expected<Image> renderScene(const SolidIndex* mesh, const std::vector<Sphere>& spheres,
                            const RenderOptions& options);

// Writes an 8-bit RGB PNG atomically.
Status writePng(const std::string& path, const Image& image);

}  // namespace sphereset

// A small ray tracer for looking at sphere sets (the paper's Figs. 1, 8 and 16 show fits the
// same way: spheres drawn over the model). Per pixel: the mesh's first hit (SolidIndex
// raycast), the ground plane, and every sphere surface in front of them, composited back to
// front with a fixed opacity; Lambert shading with one key light and a hard shadow from it,
// plus ambient light.
#include "sphereset/render.hpp"

#include <png.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "io/atomic_write.hpp"
#include "render/camera.hpp"
#include "sphereset/export.hpp"
#include "sphereset/sphere_io.hpp"
#include "util/ray_sphere.hpp"

namespace sphereset {
namespace {

constexpr double kAmbient = 0.3;
// Hits closer than this fraction of the scene radius to a ray's origin are ignored, so that
// shadow rays do not hit the surface they leave.
constexpr double kRayOffsetRel = 1e-6;
// The visible ground is a square this many times the scene radius, centred under it.
constexpr double kGroundScale = 2.5;
// The scene fills a view up to this factor: its widest extent leaves about 4% of the tile free on
// each side.
constexpr double kFramingMargin = 1.08;
// The scene's radius at least this: only an empty scene (a point) gets it. Everything else is
// relative to the scene's size, so that a mesh of size 1e-30 renders like one of size 1 (an
// absolute floor of 1e-12 used to frame such a mesh as a speck: a blank picture).
constexpr double kMinSceneRadius = std::numeric_limits<double>::min();

struct Scene {
  const SolidIndex* mesh;
  const std::vector<Sphere>* spheres;
  Vec3 up, light;
  double ground, ground_half, radius;
  Vec3 centre;
  bool has_ground;
  double opacity;
};

Aabb sceneBounds(const SolidIndex* mesh, const std::vector<Sphere>& spheres) {
  Aabb b;
  if (mesh) {
    b.extend(mesh->bounds().min);
    b.extend(mesh->bounds().max);
  }
  for (const Sphere& s : spheres) {
    b.extend(Vec3(s.center.array() - s.radius));
    b.extend(Vec3(s.center.array() + s.radius));
  }
  return b;
}

bool shadowed(const Scene& sc, const Vec3& p) {
  const double eps = kRayOffsetRel * sc.radius;
  if (sc.mesh) return sc.mesh->occluded(p, sc.light, eps, 1e3 * sc.radius);
  double t0, t1;
  for (const Sphere& s : *sc.spheres)
    if (detail::lineSphere(s, p, sc.light, &t0, &t1) && t1 > eps) return true;
  return false;
}

Vec3 background(const Scene& sc, const Vec3& d) {
  const double h = 0.5 * (d.dot(sc.up) + 1.0);
  return (1.0 - h) * Vec3(0.93, 0.94, 0.96) + h * Vec3(0.75, 0.82, 0.92);
}

Vec3 trace(const Scene& sc, const Vec3& o, const Vec3& d) {
  // The opaque hit: mesh or ground.
  double t_opaque = std::numeric_limits<double>::infinity();
  Vec3 colour = background(sc, d);
  const double eps = kRayOffsetRel * sc.radius;
  RayHit hit;
  if (sc.mesh && sc.mesh->raycast(o, d, eps, t_opaque, &hit)) {
    t_opaque = hit.t;
    const Vec3 p = o + hit.t * d;
    Vec3 n = hit.normal;
    if (n.dot(d) > 0.0) n = -n;
    const double lambert = std::max(0.0, n.dot(sc.light)) * (shadowed(sc, p + eps * n) ? 0.0 : 1.0);
    colour = (kAmbient + (1.0 - kAmbient) * lambert) * Vec3(0.82, 0.80, 0.76);
  }
  if (sc.has_ground && d.dot(sc.up) < 0.0) {
    const double t = (sc.ground - o.dot(sc.up)) / d.dot(sc.up);
    if (t > 0.0 && t < t_opaque) {
      const Vec3 p = o + t * d;
      const Vec3 q = p - sc.centre;
      const Vec3 qh = q - q.dot(sc.up) * sc.up;
      if (qh.cwiseAbs().maxCoeff() <= sc.ground_half) {
        t_opaque = t;
        const double lambert =
            std::max(0.0, sc.up.dot(sc.light)) * (shadowed(sc, p + eps * sc.up) ? 0.0 : 1.0);
        colour = (kAmbient + (1.0 - kAmbient) * lambert) * Vec3(0.95, 0.95, 0.93);
      }
    }
  }
  // Sphere surfaces in front of it, far to near.
  struct Layer {
    double t;
    Vec3 c;
  };
  std::vector<Layer> layers;
  double t0, t1;
  for (size_t i = 0; i < sc.spheres->size(); ++i) {
    const Sphere& s = (*sc.spheres)[i];
    if (!detail::lineSphere(s, o, d, &t0, &t1) || t1 <= 0.0) continue;
    for (const double t : {t0, t1}) {
      if (t <= 0.0 || t >= t_opaque) continue;
      Vec3 n = (o + t * d - s.center) / std::max(s.radius, 1e-300);
      if (n.dot(d) > 0.0) n = -n;
      const double shade = kAmbient + (1.0 - kAmbient) * std::abs(n.dot(sc.light));
      const auto rgb = sphereColour(i);
      layers.push_back({t, shade / 255.0 * Vec3(rgb[0], rgb[1], rgb[2])});
    }
  }
  std::sort(layers.begin(), layers.end(), [](const Layer& a, const Layer& b) { return a.t > b.t; });
  for (const Layer& l : layers) colour = (1.0 - sc.opacity) * colour + sc.opacity * l.c;
  return colour;
}

// The least distance from the scene's centre, along a camera's backward axis, at which the
// camera sees every ball given to fit() (a point is a ball of radius 0) whole, with
// kFramingMargin to spare. A ball at lateral offset x (along the camera's right) and depth
// offset z towards the camera is inside the side plane of half-angle tangent t when the
// camera is at least z + (|x| + r·sqrt(1 + t²)) / t away (its distance to the plane is then at
// least r); likewise up. Framing the geometry itself, not its bounding sphere, lets a tall,
// thin robot fill the tile's height.
struct Framing {
  Vec3 centre;
  const Camera* cam;
  double tan_x, tan_y;  // the view's half-angle tangents, shrunk by the margin
  double dist = 0.0;
  void fit(const Vec3& p, double r) {
    const Vec3 v = p - centre;
    const double towards = -v.dot(cam->forward);
    dist = std::max(
        {dist, towards + (std::abs(v.dot(cam->right)) + r * std::sqrt(1.0 + tan_x * tan_x)) / tan_x,
         towards + (std::abs(v.dot(cam->up)) + r * std::sqrt(1.0 + tan_y * tan_y)) / tan_y});
  }
};

// The camera's distance for the scene: its mesh's vertices and its spheres, or the corners of
// the box the options give (the frames of a motion share it).
double framingDistance(const SolidIndex* mesh, const std::vector<Sphere>& spheres,
                       const RenderOptions& o, const Vec3& centre, const Camera& cam) {
  const double aspect = static_cast<double>(cam.width) / cam.height;
  Framing f{centre, &cam, cam.tan_half_fov * aspect / kFramingMargin,
            cam.tan_half_fov / kFramingMargin};
  if (o.bounds) {
    const Aabb& b = *o.bounds;
    for (int k = 0; k < 8; ++k)
      f.fit(Vec3((k & 1) ? b.max.x() : b.min.x(), (k & 2) ? b.max.y() : b.min.y(),
                 (k & 4) ? b.max.z() : b.min.z()),
            0.0);
    return f.dist;
  }
  if (mesh)
    for (const Vec3& v : mesh->mesh().vertices) f.fit(v, 0.0);
  for (const Sphere& s : spheres) f.fit(s.center, s.radius);
  return f.dist;
}

}  // namespace

bool Camera::project(const Vec3& p, double* px, double* py) const {
  const Vec3 v = p - eye;
  const double z = v.dot(forward);
  if (z <= 0.0) return false;
  const double aspect = static_cast<double>(width) / height;
  const double sx = v.dot(right) / (z * tan_half_fov * aspect);
  const double sy = v.dot(up) / (z * tan_half_fov);
  *px = x0 + 0.5 * (sx + 1.0) * width;
  *py = y0 + 0.5 * (1.0 - sy) * height;
  return true;
}

std::vector<Camera> renderCameras(const SolidIndex* mesh, const std::vector<Sphere>& spheres,
                                  const RenderOptions& o) {
  const Aabb b = o.bounds ? *o.bounds : sceneBounds(mesh, spheres);
  const Vec3 centre = b.center();
  const double radius = std::max(0.5 * b.diagonal(), kMinSceneRadius);
  const Vec3 up = Vec3::Unit(o.up_axis);
  const Vec3 a = Vec3::Unit((o.up_axis + 1) % 3), c = Vec3::Unit((o.up_axis + 2) % 3);
  const int nv = static_cast<int>(o.views.size());
  const int cols = nv == 1 ? 1 : 2, rows = nv <= 2 ? 1 : 2;
  const double thf = std::tan(0.5 * o.field_of_view * std::numbers::pi / 180.0);
  std::vector<Camera> cams;
  for (int k = 0; k < nv; ++k) {
    Camera cam;
    cam.x0 = (k % cols) * o.width / cols;
    cam.y0 = (k / cols) * o.height / rows;
    cam.width = (k % cols + 1) * o.width / cols - cam.x0;
    cam.height = (k / cols + 1) * o.height / rows - cam.y0;
    cam.tan_half_fov = thf;
    Vec3 from = a, cam_up = up;
    switch (o.views[k]) {
      case View::kFront:
        break;
      case View::kSide:
        from = c;
        break;
      case View::kTop:
        from = up;
        cam_up = -a;
        break;
      case View::kThreeQuarter:
        from = (a + c + 0.8 * up).normalized();
        break;
    }
    cam.forward = -from;
    cam.right = cam.forward.cross(cam_up).normalized();
    cam.up = cam.right.cross(cam.forward);
    double dist = framingDistance(mesh, spheres, o, centre, cam);
    if (!(dist > 0.0)) {  // a scene without extent across the view: frame its bounding sphere
      const double aspect = static_cast<double>(cam.width) / cam.height;
      const double fit = std::min(thf, thf * aspect);  // the tighter half-angle tangent
      dist = kFramingMargin * radius * std::sqrt(1.0 + 1.0 / (fit * fit));
    }
    cam.eye = centre + dist * from;
    cams.push_back(cam);
  }
  return cams;
}

Expected<Image> renderScene(const SolidIndex* mesh, const std::vector<Sphere>& spheres,
                            const RenderOptions& o) {
  if (!mesh && spheres.empty())
    return Error{ErrorCode::kInvalidArgument, "nothing to render: no mesh and no spheres"};
  if (o.width < 16 || o.height < 16 || o.width > 16384 || o.height > 16384)
    return Error{ErrorCode::kInvalidArgument, "image size must be between 16 and 16384 pixels"};
  if (o.views.empty() || o.views.size() > 4)
    return Error{ErrorCode::kInvalidArgument, "between one and four views"};
  if (o.up_axis < 0 || o.up_axis > 2 || !(o.sphere_opacity >= 0.0 && o.sphere_opacity <= 1.0))
    return Error{ErrorCode::kInvalidArgument, "render options out of range"};
  const Aabb b = o.bounds ? *o.bounds : sceneBounds(mesh, spheres);
  Scene sc;
  sc.mesh = mesh;
  sc.spheres = &spheres;
  sc.up = Vec3::Unit(o.up_axis);
  const Vec3 a = Vec3::Unit((o.up_axis + 1) % 3), c = Vec3::Unit((o.up_axis + 2) % 3);
  sc.light = (sc.up + 0.45 * a + 0.3 * c).normalized();
  sc.centre = b.center();
  sc.radius = std::max(0.5 * b.diagonal(), kMinSceneRadius);
  // The ground touches the object's lowest point (the mesh's, when there is one).
  sc.ground = (mesh && !o.bounds ? mesh->bounds().min : b.min).dot(sc.up);
  sc.ground_half = kGroundScale * sc.radius;
  sc.has_ground = o.ground;
  sc.opacity = o.sphere_opacity;
  const std::vector<Camera> cams = renderCameras(mesh, spheres, o);
  Image img;
  img.width = o.width;
  img.height = o.height;
  img.rgb.assign(3 * static_cast<size_t>(o.width) * o.height, 255);
  tbb::parallel_for(0, o.height, [&](int y) {
    for (const Camera& cam : cams) {
      if (y < cam.y0 || y >= cam.y0 + cam.height) continue;
      const double aspect = static_cast<double>(cam.width) / cam.height;
      for (int x = cam.x0; x < cam.x0 + cam.width; ++x) {
        const double sx = (2.0 * (x - cam.x0 + 0.5) / cam.width - 1.0) * cam.tan_half_fov * aspect;
        const double sy = (1.0 - 2.0 * (y - cam.y0 + 0.5) / cam.height) * cam.tan_half_fov;
        const Vec3 d = (cam.forward + sx * cam.right + sy * cam.up).normalized();
        const Vec3 col = trace(sc, cam.eye, d);
        const size_t i = 3 * (static_cast<size_t>(y) * o.width + x);
        for (int k = 0; k < 3; ++k)
          img.rgb[i + k] = static_cast<uint8_t>(std::lround(255.0 * std::clamp(col[k], 0.0, 1.0)));
      }
    }
  });
  // Thin separators between the tiles.
  for (const Camera& cam : cams) {
    for (int x = cam.x0; x < cam.x0 + cam.width; ++x)
      for (int y : {cam.y0, cam.y0 + cam.height - 1})
        for (int k = 0; k < 3; ++k) img.rgb[3 * (static_cast<size_t>(y) * o.width + x) + k] = 255;
    for (int y = cam.y0; y < cam.y0 + cam.height; ++y)
      for (int x : {cam.x0, cam.x0 + cam.width - 1})
        for (int k = 0; k < 3; ++k) img.rgb[3 * (static_cast<size_t>(y) * o.width + x) + k] = 255;
  }
  return img;
}

Status writePng(const std::string& path, const Image& image) {
  png_image pi{};
  pi.version = PNG_IMAGE_VERSION;
  pi.width = static_cast<png_uint_32>(image.width);
  pi.height = static_cast<png_uint_32>(image.height);
  pi.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&pi, nullptr, &size, 0, image.rgb.data(), 0, nullptr))
    return Error{ErrorCode::kWriteFailed, path + ": PNG encoding failed (" + pi.message + ")"};
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&pi, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr))
    return Error{ErrorCode::kWriteFailed, path + ": PNG encoding failed (" + pi.message + ")"};
  bytes.resize(size);
  return writeFileAtomically(path, bytes);
}

}  // namespace sphereset

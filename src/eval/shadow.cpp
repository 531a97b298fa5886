// Shadow comparison. Reference: Wang et al. 2006, Sec. 7 "Shadow Application": the sphere set
// stands in for the mesh when casting shadows of distant light on a ground plane under the
// object, and the two shadow images are compared as RMS error over the plane's pixels.
//
// Deviation: the paper lights the scene with an environment map through precomputed radiance
// transfer; here the light is a fixed set of K directional lights spread evenly (equal solid
// angle) over the upper hemisphere, traced exactly against both the mesh and the spheres.
// Two figures come out of the same visibility samples: uniform sky light (the irradiance
// Σ_k V_k cos θ_k / Σ_k cos θ_k, i.e. ambient occlusion of the plane) and each light on its
// own (the irradiance V_k cos θ_k), RMS over pixels and lights.
#include "eval/shadow.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "sphereset/evaluate.hpp"
#include "util/poll.hpp"
#include "util/ray_sphere.hpp"

namespace sphereset {
namespace {

// The plane sits this fraction of the diagonal below the lowest point of the mesh, so that
// rays from it do not start on the surface.
constexpr double kPlaneGapRel = 1e-6;
// The plane square is this many times the object's largest extent, centred under it.
constexpr double kPlaneScale = 3.0;

// Whether the ray x + t d, t > 0, enters or starts inside a sphere.
bool sphereBlocks(const std::vector<Sphere>& spheres, const Vec3& x, const Vec3& d) {
  double t0, t1;
  for (const Sphere& s : spheres)
    if (detail::lineSphere(s, x, d, &t0, &t1) && t1 > 0.0) return true;
  return false;
}

}  // namespace

std::vector<Vec3> hemisphereDirections(int count, const Vec3& up) {
  // A spiral with equal solid angle per direction: cos θ uniform in (0, 1).
  const Vec3 a = std::abs(up.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = up.cross(a).normalized(), e2 = up.cross(e1);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<Vec3> out(count);
  for (int k = 0; k < count; ++k) {
    const double z = 1.0 - (k + 0.5) / count;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * k;
    out[k] = z * up + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
  }
  return out;
}

ShadowResult compareShadows(const SolidIndex& index, const std::vector<Sphere>& spheres,
                            int up_axis, int resolution, int lights) {
  ShadowResult res;
  if (resolution < 1 || lights < 1 || up_axis < 0 || up_axis > 2) return res;
  const Aabb& b = index.bounds();
  const Vec3 up = Vec3::Unit(up_axis);
  const int ax1 = (up_axis + 1) % 3, ax2 = (up_axis + 2) % 3;
  const double extent = (b.max - b.min).maxCoeff();
  const double side = kPlaneScale * extent;
  const double ground = b.min[up_axis] - kPlaneGapRel * b.diagonal();
  const Vec3 centre = b.center();
  const std::vector<Vec3> dirs = hemisphereDirections(lights, up);
  double cos_sum = 0.0;
  for (const Vec3& d : dirs) cos_sum += d.dot(up);
  const double reach = 4.0 * (b.diagonal() + side);  // beyond everything above the plane
  const int np = resolution * resolution;
  std::vector<double> sky_err(np), light_err(np);
  tbb::parallel_for(0, np, [&](int p) {
    detail::pollCancel();
    Vec3 x = Vec3::Zero();
    x[up_axis] = ground;
    x[ax1] = centre[ax1] + side * ((p % resolution + 0.5) / resolution - 0.5);
    x[ax2] = centre[ax2] + side * ((p / resolution + 0.5) / resolution - 0.5);
    double sky_mesh = 0.0, sky_sph = 0.0, sq = 0.0;
    for (const Vec3& d : dirs) {
      const double c = d.dot(up);
      const double vm = index.occluded(x, d, 0.0, reach) ? 0.0 : c;
      const double vs = sphereBlocks(spheres, x, d) ? 0.0 : c;
      sky_mesh += vm;
      sky_sph += vs;
      sq += (vm - vs) * (vm - vs);
    }
    const double e = (sky_mesh - sky_sph) / cos_sum;
    sky_err[p] = e * e;
    light_err[p] = sq;
  });
  double s1 = 0.0, s2 = 0.0;
  for (int p = 0; p < np; ++p) {
    s1 += sky_err[p];
    s2 += light_err[p];
  }
  res.sky_rms = std::sqrt(s1 / np);
  res.lights_rms = std::sqrt(s2 / (static_cast<double>(np) * lights));
  res.pixels = np;
  res.lights = lights;
  return res;
}

}  // namespace sphereset

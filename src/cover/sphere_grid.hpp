// Private: spheres bucketed in a uniform grid, so that coverage tests look at the spheres near
// a point instead of all of them (the bounding step and the evaluation test every piece of the
// surface and every cube of the interior against the set).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "sphereset/sphere.hpp"

namespace sphereset::detail {

// A dense grid over the spheres' box, indexed by clamped coordinates: it shares the checked
// conversion of cell_key.hpp (util) with the hash grids, not their keys or hash.
class SphereGrid {
 public:
  // Each sphere is listed in every cell its bounding box (slightly widened) meets.
  explicit SphereGrid(const std::vector<Sphere>& spheres);

  const std::vector<Sphere>& spheres() const { return *spheres_; }

  // Calls f(i) for the spheres listed in the cell of p, in increasing index order: a superset
  // of the spheres that contain p (none if p lies outside the grid).
  template <class F>
  void forEachNear(const Vec3& p, F&& f) const {
    int64_t c[3];
    if (!cellOf(p, c)) return;
    const int64_t id = c[0] + dims_[0] * (c[1] + dims_[1] * c[2]);
    for (int32_t k = start_[id]; k < start_[id + 1]; ++k) f(members_[k]);
  }

  // Calls f(i) once for every sphere whose box meets the cube of half side `reach` about p:
  // every sphere within `reach` of p is among them.
  template <class F>
  void forEachWithin(const Vec3& p, double reach, F&& f) const {
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = clampedCell(p[a] - reach, a);
      hi[a] = clampedCell(p[a] + reach, a);
      if (p[a] + reach < origin_[a] || p[a] - reach > origin_[a] + dims_[a] * cell_) return;
    }
    for (int64_t z = lo[2]; z <= hi[2]; ++z)
      for (int64_t y = lo[1]; y <= hi[1]; ++y)
        for (int64_t x = lo[0]; x <= hi[0]; ++x) {
          const int64_t id = x + dims_[0] * (y + dims_[1] * z);
          for (int32_t k = start_[id]; k < start_[id + 1]; ++k) {
            // A sphere listed in several visited cells is reported from the first of them.
            const std::array<int32_t, 3>& first = first_cell_[members_[k]];
            if (x == std::max<int64_t>(lo[0], first[0]) &&
                y == std::max<int64_t>(lo[1], first[1]) && z == std::max<int64_t>(lo[2], first[2]))
              f(members_[k]);
          }
        }
  }

  // Whether the grid's cells all lie within the cube of half side `reach` about p.
  bool coveredBy(const Vec3& p, double reach) const;
  double cell() const { return cell_; }

 private:
  bool cellOf(const Vec3& p, int64_t* c) const;
  int64_t clampedCell(double x, int axis) const;

  const std::vector<Sphere>* spheres_;
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1.0;
  int64_t dims_[3] = {1, 1, 1};
  std::vector<int32_t> start_, members_;
  std::vector<std::array<int32_t, 3>> first_cell_;  // lowest cell of each sphere's box
};

// Whether one sphere holds all the points (then it holds their convex hull).
bool oneSphereHolds(const SphereGrid& grid, const Vec3* pts, int n);

// How many spheres (0, 1, or 2 meaning "two or more") hold all the points; *holder is the
// last one found in index order.
int holders(const SphereGrid& grid, const Vec3* pts, int n, int32_t* holder);

// Distance from p to the union of the spheres (0 inside).
double gapToUnion(const SphereGrid& grid, const Vec3& p);

// The `count` spheres (at most 8) that need the least radius increase to hold all the points,
// as (increase, index) in increasing order (ties: lower index); fewer if there are fewer
// spheres. Returns how many were written. The search looks within a reach of pts[0] that starts
// at `reach` (0: one grid cell) and doubles until it holds the answer, which is therefore the
// same from any start; a start at a known sphere's increase saves the doubling.
int leastGrowth(const SphereGrid& grid, const Vec3* pts, int n, int count,
                std::pair<double, int32_t>* out, double reach = 0.0);

}  // namespace sphereset::detail

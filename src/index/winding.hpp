// Private: the solid angle of a triangle and the winding number, the index's fallback
// point-in-solid test (and the nesting test of small shells).
#pragma once

#include "sphereset/solid_index.hpp"

namespace sphereset {

// Signed solid angle of triangle (a, b, c) seen from o (Van Oosterom–Strackee); positive when
// o lies behind the triangle (on the side opposite its counter-clockwise normal).
double triangleSolidAngle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o);

// Generalised winding number Σ Ω_t / 4π over all triangles (O(n)); classify() falls back on it.
double windingNumber(const SolidIndex& index, const Vec3& p);

}  // namespace sphereset

// The smallest ball enclosing a set of balls. Reference: K. Fischer, B. Gärtner, "The smallest
// enclosing ball of balls: combinatorial structure and algorithms", SoCG 2003 / IJCGA 2004.
//
// The minimal ball B(c, R) is unique and determined by a support set S of at most four
// input balls that it touches internally (|c - c_i| + r_i = R for i in S) with c in the
// affine hull of their centres. For a candidate S this is solved directly: writing
// c = c_0 + D λ (D = [c_i - c_0]), the differences of the tangency conditions are linear,
//   2 DᵀD λ = e + 2 R f,  e_i = |c_i - c_0|² - r_i² + r_0²,  f_i = r_i - r_0,
// so λ = α + R β, and |D λ|² = (R - r_0)² leaves a quadratic in R.
//
// Deviation: instead of Welzl-style recursion (which Fischer and Gärtner show can fail for
// balls) we pivot: keep a support set, find the ball sticking out farthest, and replace the
// support by the best support among the at most five balls (old support + violator), found
// by trying all their subsets. The radius increases strictly at each pivot, so the loop ends,
// and it ends at the global optimum because the final ball encloses everything and is the
// minimum for its own support.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "sphereset/sphere.hpp"

namespace sphereset {
namespace {

// Relative tolerances (of the problem's length scale) for "encloses" and for degenerate
// support sets whose centres are (nearly) affinely dependent.
constexpr double kEncloseRel = 1e-12;
constexpr double kDegenerateRel = 1e-14;
constexpr int kMaxPivots = 10000;

// The ball tangent internally to every ball of `s` (size 1..4) with its centre in the affine
// hull of their centres; the smallest valid root, or none.
std::optional<Sphere> tangentBall(const Sphere* const* s, int k, double scale) {
  if (k == 1) return *s[0];
  const Vec3& c0 = s[0]->center;
  const double r0 = s[0]->radius;
  Eigen::Matrix<double, 3, Eigen::Dynamic> d(3, k - 1);
  Eigen::VectorXd e(k - 1), f(k - 1);
  for (int i = 1; i < k; ++i) {
    d.col(i - 1) = s[i]->center - c0;
    e[i - 1] = d.col(i - 1).squaredNorm() - s[i]->radius * s[i]->radius + r0 * r0;
    f[i - 1] = s[i]->radius - r0;
  }
  const Eigen::MatrixXd g = d.transpose() * d;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(g);
  lu.setThreshold(kDegenerateRel);
  if (lu.rank() < k - 1 || std::abs(lu.determinant()) <
                               kDegenerateRel * std::pow(scale * scale, static_cast<double>(k - 1)))
    return std::nullopt;
  const Eigen::VectorXd alpha = lu.solve(0.5 * e);
  const Eigen::VectorXd beta = lu.solve(f);
  const Vec3 u = d * alpha, v = d * beta;
  // |u + R v|² = (R - r0)²  ->  a R² + b R + c = 0.
  const double a = v.squaredNorm() - 1.0;
  const double b = 2.0 * (u.dot(v) + r0);
  const double c = u.squaredNorm() - r0 * r0;
  double roots[2];
  int nroots = 0;
  if (std::abs(a) < kDegenerateRel) {
    if (b != 0.0) roots[nroots++] = -c / b;
  } else {
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return std::nullopt;
    const double sq = std::sqrt(disc);
    // Stable pair of roots.
    const double q = -0.5 * (b + std::copysign(sq, b));
    roots[nroots++] = q / a;
    if (q != 0.0) roots[nroots++] = c / q;
  }
  double rmax = 0.0;
  for (int i = 0; i < k; ++i) rmax = std::max(rmax, s[i]->radius);
  std::optional<Sphere> best;
  for (int i = 0; i < nroots; ++i) {
    const double r = roots[i];
    if (!std::isfinite(r) || r < rmax - kEncloseRel * scale) continue;
    if (best && r >= best->radius) continue;
    best = Sphere{c0 + u + r * v, r};
  }
  return best;
}

double excess(const Sphere& outer, const Sphere& inner) {
  return (inner.center - outer.center).norm() + inner.radius - outer.radius;
}

// The minimal ball of a small set (at most five balls), by trying every subset as support.
Sphere smallSetBall(const std::vector<const Sphere*>& set, double scale,
                    std::vector<const Sphere*>* support) {
  const int m = static_cast<int>(set.size());
  std::optional<Sphere> best;
  std::vector<const Sphere*> best_support;
  for (int mask = 1; mask < (1 << m); ++mask) {
    const int k = __builtin_popcount(mask);
    if (k > 4) continue;
    const Sphere* sub[4];
    int j = 0;
    for (int i = 0; i < m; ++i)
      if (mask & (1 << i)) sub[j++] = set[i];
    const auto ball = tangentBall(sub, k, scale);
    if (!ball || (best && ball->radius >= best->radius)) continue;
    bool encloses = true;
    for (const Sphere* s : set) encloses = encloses && excess(*ball, *s) <= kEncloseRel * scale;
    if (!encloses) continue;
    best = ball;
    best_support.assign(sub, sub + k);
  }
  if (!best) {
    // Only reachable through rounding in a degenerate configuration: fall back to the ball
    // about the largest input that reaches all others (still enclosing, maybe not minimal).
    Sphere b = *set[0];
    for (const Sphere* s : set)
      b.radius = std::max(b.radius, (s->center - b.center).norm() + s->radius);
    *support = {set[0]};
    return b;
  }
  *support = best_support;
  return *best;
}

}  // namespace

Sphere minimalEnclosingBall(std::span<const Sphere> balls) {
  if (balls.empty()) return {Vec3::Zero(), 0.0};
  // Length scale for the tolerances: the extent of the input.
  Aabb box;
  for (const Sphere& s : balls) {
    box.extend(Vec3(s.center.array() - s.radius));
    box.extend(Vec3(s.center.array() + s.radius));
  }
  const double scale = std::max(box.diagonal(), std::numeric_limits<double>::min());
  // Start from the largest ball as the support.
  const Sphere* largest = &balls[0];
  for (const Sphere& s : balls)
    if (s.radius > largest->radius) largest = &s;
  std::vector<const Sphere*> support{largest};
  Sphere ball = *largest;
  for (int pivot = 0; pivot < kMaxPivots; ++pivot) {
    const Sphere* worst = nullptr;
    double worst_excess = kEncloseRel * scale;
    for (const Sphere& s : balls) {
      const double x = excess(ball, s);
      if (x > worst_excess) {
        worst_excess = x;
        worst = &s;
      }
    }
    if (!worst) break;
    std::vector<const Sphere*> set = support;
    set.push_back(worst);
    ball = smallSetBall(set, scale, &support);
  }
  // Containment in floating point: the radius reaches every ball as computed from this centre.
  double r = ball.radius;
  for (const Sphere& s : balls) r = std::max(r, (s.center - ball.center).norm() + s.radius);
  ball.radius = std::nextafter(r, std::numeric_limits<double>::infinity());
  return ball;
}

}  // namespace sphereset

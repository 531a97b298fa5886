// Private: exact sums of many angles atan2(num, den) with few atan2 calls.
//
// The angles are accumulated as the argument of a running complex product Π (den + i num).
// While the product stays in the right half-plane its argument is the sum so far; when a
// factor or the product leaves it, the argument is flushed into a plain sum with one atan2
// (exact there, since the angle is then still inside (-π, π)). Magnitudes are rescaled to
// stay far from overflow. The result equals Σ atan2 to rounding (one ulp-level error per
// factor, as for a plain sum), at the cost of a complex multiply per term.
#pragma once

#include <cmath>

namespace sphereset::detail {

class AngleSum {
 public:
  void add(double num, double den) {
    if (num == 0.0 && den >= 0.0) return;  // angle 0 (also a degenerate 0/0 term)
    if (den < 0.0) {                       // |angle| > π/2: on its own
      total_ += std::atan2(num, den);
      return;
    }
    const double re = re_ * den - im_ * num;
    const double im = re_ * num + im_ * den;
    if (re <= 0.0) {  // the product would leave the right half-plane: flush it
      total_ += std::atan2(im, re);
      re_ = 1.0;
      im_ = 0.0;
      return;
    }
    re_ = re;
    im_ = im;
    const double mag = re_ + std::abs(im_);
    if (mag > kRescaleAbove || mag < kRescaleBelow) {
      re_ /= mag;
      im_ /= mag;
    }
  }
  double value() const { return total_ + std::atan2(im_, re_); }

 private:
  static constexpr double kRescaleAbove = 1e100, kRescaleBelow = 1e-100;
  double re_ = 1.0, im_ = 0.0, total_ = 0.0;
};

}  // namespace sphereset::detail

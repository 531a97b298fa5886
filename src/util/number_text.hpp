// A number as messages show it: whole numbers without a decimal point (as a user types a count
// or a limit), others with 6 significant digits.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace sphereset::detail {

inline std::string numberText(double v) {
  char buf[40];
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace sphereset::detail

// The size limits of limits.hpp and the one wording of their errors.
#include "sphereset/limits.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace sphereset::limits {
namespace {

// A number as a user typed it: integers without a decimal point, others with 6 digits.
std::string number(double v) {
  char buf[40];
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

Status checkRange(const std::string& what, double value, double lo, double hi) {
  if (value >= lo && value <= hi) return {};
  return Error{ErrorCode::kInvalidArgument,
               what + " must be from " + number(lo) + " to " + number(hi) + " (got " +
                   number(value) + ")"};
}

Status checkArray(const std::string& what, double count, double bytes_each, ErrorCode code) {
  const double bytes = count * bytes_each;
  if (bytes <= kMaxArrayBytes) return {};
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  char buf[96];
  std::snprintf(buf, sizeof buf, " would need %.3g GiB (more than the limit of %.3g GiB)",
                bytes / kGiB, kMaxArrayBytes / kGiB);
  return Error{code, what + buf};
}

}  // namespace sphereset::limits

// The size limits of limits.hpp and the one wording of their errors.
#include "sphereset/limits.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "util/number_text.hpp"

namespace sphereset::limits {

Status checkRange(const std::string& what, double value, double lo, double hi) {
  if (value >= lo && value <= hi) return {};
  return Error{ErrorCode::kInvalidArgument, what + " must be from " + detail::numberText(lo) +
                                                " to " + detail::numberText(hi) + " (got " +
                                                detail::numberText(value) + ")"};
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

Status checkCoordinates(const std::string& what, std::span<const double> values) {
  bool ok = true;
  for (double v : values) ok = ok && std::fabs(v) <= kMaxCoordinate;  // false for NaN
  if (ok) return {};
  std::string got;
  for (double v : values) {
    if (!got.empty()) got += ' ';
    got += detail::numberText(v);
  }
  return Error{ErrorCode::kInvalidArgument,
               what + " (" + got + "): coordinates must be finite and at most " +
                   detail::numberText(kMaxCoordinate) + " in magnitude"};
}

}  // namespace sphereset::limits

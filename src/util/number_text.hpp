// A number as messages show it: whole numbers without a decimal point (as a user types a count
// or a limit), others with 6 significant digits.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <system_error>

namespace sphereset::detail {

// The number at the start of [first, last), whatever the C locale: std::from_chars, which reads
// "0.5" under a comma-decimal locale too (strtod and stod would stop at the '.'), plus the
// leading '+' strtod takes; "nan", "inf" and "infinity" are read (callers refuse them where they
// must), hexadecimal is not. The characters read, 0 when there is no number; a value out of
// range is ±inf or 0, as strtod gives it.
inline size_t parseNumberPrefix(const char* first, const char* last, double* out) {
  if (first >= last) return 0;
  const char* p = first;
  if (p != last && *p == '+' && (p + 1 == last || p[1] != '-')) ++p;
  const auto [end, ec] = std::from_chars(p, last, *out);
  if (ec == std::errc::invalid_argument) return 0;
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves *out unchanged: the magnitude is beyond double (±inf) or below it (0).
    bool tiny = false;
    for (const char* c = p; c != end; ++c)
      if (*c == 'e' || *c == 'E') tiny = c + 1 != end && c[1] == '-';
    const bool negative = *p == '-';
    *out = tiny ? (negative ? -0.0 : 0.0) : (negative ? -HUGE_VAL : HUGE_VAL);
  }
  return static_cast<size_t>(end - first);
}

// The whole text as one number (parseNumberPrefix reading every character); false otherwise.
inline bool parseNumber(std::string_view text, double* out) {
  if (text.empty()) return false;
  return parseNumberPrefix(text.data(), text.data() + text.size(), out) == text.size();
}

inline std::string numberText(double v) {
  char buf[40];
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace sphereset::detail

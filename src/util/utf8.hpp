// Private: text that must be UTF-8 (JSON, YAML, Python strings) made from bytes that may not be
// (file names are bytes on Linux), and messages made one line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace sphereset::detail {

// The length of the well-formed UTF-8 sequence at s[i] (1 to 4), or 0 when the byte there
// starts none: no overlong forms, no surrogates, nothing above U+10FFFF.
inline size_t utf8SequenceAt(const unsigned char* s, size_t n, size_t i) {
  const unsigned char c = s[i];
  const size_t len = c < 0x80           ? 1
                     : (c >> 5) == 0x6  ? 2
                     : (c >> 4) == 0xe  ? 3
                     : (c >> 3) == 0x1e ? 4
                                        : 0;
  bool ok = len > 0 && i + len <= n;
  for (size_t k = 1; ok && k < len; ++k) ok = (s[i + k] & 0xc0) == 0x80;
  if (ok && len > 1) {
    const unsigned char d = s[i + 1];
    if (len == 2) ok = c >= 0xc2;
    if (len == 3) ok = !(c == 0xe0 && d < 0xa0) && !(c == 0xed && d >= 0xa0);
    if (len == 4) ok = !(c == 0xf0 && d < 0x90) && !(c == 0xf4 && d >= 0x90) && c <= 0xf4;
  }
  return ok ? len : 0;
}

// `bytes` with every byte that does not belong to a well-formed UTF-8 sequence replaced by
// U+FFFD (the replacement character), as nlohmann::json's "replace" error handler does; valid
// text is returned unchanged.
inline std::string validUtf8(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  const auto* s = reinterpret_cast<const unsigned char*>(bytes.data());
  for (size_t i = 0; i < bytes.size();) {
    if (const size_t len = utf8SequenceAt(s, bytes.size(), i)) {
      out.append(bytes.substr(i, len));
      i += len;
    } else {
      out += "\xef\xbf\xbd";
      ++i;
    }
  }
  return out;
}

// The offset of the first byte of `bytes` that is not well-formed UTF-8, or npos.
inline size_t firstInvalidUtf8(std::string_view bytes) {
  const auto* s = reinterpret_cast<const unsigned char*>(bytes.data());
  for (size_t i = 0; i < bytes.size();) {
    const size_t len = utf8SequenceAt(s, bytes.size(), i);
    if (len == 0) return i;
    i += len;
  }
  return std::string_view::npos;
}

// A message on one line, whatever the names or parser messages in it hold: line breaks become
// spaces, trailing spaces are dropped.
inline std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace sphereset::detail

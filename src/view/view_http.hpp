// Private: the HTTP/1.1 request head of the view's server, read as a pure function (RFC 9112,
// sections 2 to 6: request line, header fields, message body length), so that the server's
// socket code only moves bytes and enforces deadlines. Only what the page sends is accepted:
// origin-form targets, Content-Length bodies; anything else is a status to answer.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "sphereset/view.hpp"

namespace sphereset::detail {

// Bytes of a request head (request line and header fields) at most; 431 above.
inline constexpr size_t kMaxHttpHeadBytes = 16 * 1024;
// Header fields of one request at most; 431 above.
inline constexpr int kMaxHttpHeaders = 100;

struct HttpHead {
  ViewRequest request;  // method, path and query decoded, headers (names in lower case)
  int64_t content_length = 0;
  int status = 0;     // 0: read; otherwise the status to answer (400, 411, 413, 431, 505)
  std::string error;  // the answer's message when status != 0
};

// The end of the head in `bytes` (the offset just after the blank line), or npos while the
// head is not complete.
size_t httpHeadEnd(std::string_view bytes);

// The head `head` (up to and including its blank line) read: method, target (percent-decoded
// path; query split at '&' and '=', '+' a space, first value kept), header fields, and the body's
// length: a Transfer-Encoding, or a method with a body (not GET, HEAD, OPTIONS) without a
// Content-Length, is 411; a Content-Length that is not digits, or sent twice with different
// values, 400; one over limits::kMaxViewRequestBytes, 413 (with content_length set, so the body
// can be drained).
HttpHead parseHttpHead(std::string_view head);

// The reason phrase of a status the server sends.
const char* httpReason(int status);

}  // namespace sphereset::detail

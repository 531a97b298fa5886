// The view server's HTTP/1.1 request head (view_http.hpp). Reference: RFC 9112, "HTTP/1.1":
// sec. 3 (request line, origin-form target), sec. 5 (field lines; obsolete line folding
// refused), sec. 6.3 (message body length: Transfer-Encoding and Content-Length). Deviation:
// only Content-Length bodies are taken (411 otherwise), as the page sends them, so that every
// body has a size to check before it is read.
#include "view/view_http.hpp"

#include <algorithm>
#include <cctype>

#include "sphereset/limits.hpp"

namespace sphereset::detail {
namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// %XX decoded ('+' a space in a query); false for a '%' without two hexadecimal digits.
bool percentDecode(std::string_view in, bool plus_is_space, std::string* out) {
  out->clear();
  for (size_t i = 0; i < in.size(); ++i) {
    if (in[i] == '%') {
      if (i + 2 >= in.size()) return false;
      const int hi = hexValue(in[i + 1]), lo = hexValue(in[i + 2]);
      if (hi < 0 || lo < 0) return false;
      out->push_back(static_cast<char>(hi * 16 + lo));
      i += 2;
    } else {
      out->push_back(plus_is_space && in[i] == '+' ? ' ' : in[i]);
    }
  }
  return true;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool isToken(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u >= 0x7f ||
        std::string_view("()<>@,;:\\\"/[]?={}").find(c) != std::string_view::npos)
      return false;
  }
  return true;
}

HttpHead refused(HttpHead h, int status, std::string message) {
  h.status = status;
  h.error = std::move(message);
  return h;
}

// "METHOD SP TARGET SP HTTP/1.x" into `h`; false with h's status set otherwise.
bool readRequestLine(std::string_view line, HttpHead* h) {
  const size_t a = line.find(' ');
  const size_t b = a == std::string_view::npos ? a : line.find(' ', a + 1);
  if (b == std::string_view::npos || line.find(' ', b + 1) != std::string_view::npos) {
    *h = refused(std::move(*h), 400, "malformed request line");
    return false;
  }
  const std::string_view method = line.substr(0, a), target = line.substr(a + 1, b - a - 1),
                         version = line.substr(b + 1);
  if (version != "HTTP/1.1" && version != "HTTP/1.0") {
    *h = refused(std::move(*h), version.rfind("HTTP/", 0) == 0 ? 505 : 400,
                 "only HTTP/1.0 and HTTP/1.1 are spoken");
    return false;
  }
  if (!isToken(method) || target.empty() || target.front() != '/') {
    *h = refused(std::move(*h), 400, "malformed request line");
    return false;
  }
  h->request.method = std::string(method);
  const size_t q = target.find('?');
  if (!percentDecode(target.substr(0, q), false, &h->request.path)) {
    *h = refused(std::move(*h), 400, "malformed path");
    return false;
  }
  if (q == std::string_view::npos) return true;
  std::string_view query = target.substr(q + 1);
  while (!query.empty()) {
    const size_t amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    const size_t eq = pair.find('=');
    std::string key, value;
    if (!percentDecode(pair.substr(0, eq), true, &key) ||
        !percentDecode(eq == std::string_view::npos ? "" : pair.substr(eq + 1), true, &value)) {
      *h = refused(std::move(*h), 400, "malformed query");
      return false;
    }
    h->request.query.emplace(std::move(key), std::move(value));  // the first value is kept
    query = amp == std::string_view::npos ? std::string_view() : query.substr(amp + 1);
  }
  return true;
}

}  // namespace

size_t httpHeadEnd(std::string_view bytes) {
  const size_t end = bytes.find("\r\n\r\n");
  return end == std::string_view::npos ? end : end + 4;
}

HttpHead parseHttpHead(std::string_view head) {
  HttpHead h;
  if (head.size() > kMaxHttpHeadBytes) return refused(std::move(h), 431, "request head too large");
  size_t pos = head.find("\r\n");
  if (pos == std::string_view::npos) return refused(std::move(h), 400, "malformed request");
  if (!readRequestLine(head.substr(0, pos), &h)) return h;
  pos += 2;
  int fields = 0;
  bool has_length = false, chunked = false;
  while (pos < head.size()) {
    const size_t eol = head.find("\r\n", pos);
    if (eol == std::string_view::npos) return refused(std::move(h), 400, "malformed header");
    const std::string_view line = head.substr(pos, eol - pos);
    pos = eol + 2;
    if (line.empty()) break;
    if (++fields > kMaxHttpHeaders) return refused(std::move(h), 431, "too many header fields");
    if (line.front() == ' ' || line.front() == '\t')
      return refused(std::move(h), 400, "folded header lines are not accepted");
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos || !isToken(line.substr(0, colon)))
      return refused(std::move(h), 400, "malformed header");
    std::string name(line.substr(0, colon));
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::string value(trim(line.substr(colon + 1)));
    if (name == "transfer-encoding") chunked = true;
    if (name == "content-length") {
      constexpr size_t kMaxLengthDigits = 18;  // below 2^63
      if (value.empty() || value.size() > kMaxLengthDigits ||
          value.find_first_not_of("0123456789") != std::string::npos)
        return refused(std::move(h), 400, "malformed Content-Length");
      const int64_t n = std::stoll(value);
      if (has_length && n != h.content_length)
        return refused(std::move(h), 400, "two different Content-Length values");
      has_length = true;
      h.content_length = n;
    }
    h.request.headers.emplace_back(std::move(name), value);
  }
  const std::string& m = h.request.method;
  const bool may_have_body = m != "GET" && m != "HEAD" && m != "OPTIONS";
  if (chunked || (may_have_body && !has_length))
    return refused(std::move(h), 411, "a request body needs a Content-Length");
  if (h.content_length > limits::kMaxViewRequestBytes)
    return refused(std::move(h), 413,
                   "the body is over " + std::to_string(limits::kMaxViewRequestBytes) + " bytes");
  return h;
}

const char* httpReason(int status) {
  switch (status) {
    case 200:
      return "OK";
    case 400:
      return "Bad Request";
    case 401:
      return "Unauthorized";
    case 403:
      return "Forbidden";
    case 404:
      return "Not Found";
    case 405:
      return "Method Not Allowed";
    case 408:
      return "Request Timeout";
    case 411:
      return "Length Required";
    case 413:
      return "Content Too Large";
    case 431:
      return "Request Header Fields Too Large";
    case 500:
      return "Internal Server Error";
    case 503:
      return "Service Unavailable";
    case 505:
      return "HTTP Version Not Supported";
    default:
      return "Unknown";
  }
}

}  // namespace sphereset::detail

// The view server's request head as a pure function (src/view/view_http.cpp).
#include <gtest/gtest.h>

#include <string>

#include "sphereset/limits.hpp"
#include "view/view_http.hpp"

namespace sphereset::detail {
namespace {

TEST(HttpHead, ReadsTheRequestLineQueryAndHeaders) {
  const std::string text =
      "POST /api/ed%69t?solid=1&a=x+y%21&solid=2 HTTP/1.1\r\nHost: 127.0.0.1:80\r\n"
      "Content-Type:  application/json \r\nContent-Length: 12\r\n\r\n{\"solid\": 0}";
  const size_t end = httpHeadEnd(text);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(text.substr(end), "{\"solid\": 0}");
  const HttpHead h = parseHttpHead(std::string_view(text).substr(0, end));
  ASSERT_EQ(h.status, 0) << h.error;
  EXPECT_EQ(h.request.method, "POST");
  EXPECT_EQ(h.request.path, "/api/edit");
  EXPECT_EQ(h.request.query.at("solid"), "1");  // the first value
  EXPECT_EQ(h.request.query.at("a"), "x y!");
  EXPECT_EQ(h.content_length, 12);
  ASSERT_EQ(h.request.headers.size(), 3u);
  EXPECT_EQ(h.request.headers[1].first, "content-type");
  EXPECT_EQ(h.request.headers[1].second, "application/json");
  EXPECT_EQ(httpHeadEnd("GET / HTTP/1.1\r\nHost: x\r\n"), std::string::npos);
}

TEST(HttpHead, RefusesWhatThePageNeverSends) {
  const std::string cap = std::to_string(limits::kMaxViewRequestBytes + 1);
  const struct {
    std::string head;
    int status;
  } cases[] = {
      {"POST /api/edit HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n", 411},
      {"GET / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n", 411},
      {"POST /api/edit HTTP/1.1\r\nHost: x\r\n\r\n", 411},
      {"POST /api/edit HTTP/1.1\r\nContent-Length: -1\r\n\r\n", 400},
      {"POST /api/edit HTTP/1.1\r\nContent-Length: 1\r\nContent-Length: 2\r\n\r\n", 400},
      {"POST /api/edit HTTP/1.1\r\nContent-Length: 99999999999999999999\r\n\r\n", 400},
      {"POST /api/edit HTTP/1.1\r\nContent-Length: " + cap + "\r\n\r\n", 413},
      {"GET /a HTTP/2.0\r\n\r\n", 505},
      {"GET http://evil/ HTTP/1.1\r\n\r\n", 400},
      {"GET /%zz HTTP/1.1\r\n\r\n", 400},
      {"GET /?a=%4 HTTP/1.1\r\n\r\n", 400},
      {"GET / HTTP/1.1\r\nHost: x\r\n folded\r\n\r\n", 400},
      {"GET / HTTP/1.1\r\nNo colon\r\n\r\n", 400},
      {"GET  / HTTP/1.1\r\n\r\n", 400},
      {"GET / HTTP/1.1\r\n" + std::string(kMaxHttpHeadBytes, 'a') + "\r\n\r\n", 431},
  };
  for (const auto& c : cases) {
    const HttpHead h = parseHttpHead(c.head);
    EXPECT_EQ(h.status, c.status) << c.head.substr(0, 80) << " -> " << h.error;
    EXPECT_FALSE(h.error.empty());
  }
  std::string many = "GET / HTTP/1.1\r\n";
  for (int i = 0; i <= kMaxHttpHeaders; ++i) many += "X-" + std::to_string(i) + ": 1\r\n";
  EXPECT_EQ(parseHttpHead(many + "\r\n").status, 431);
  EXPECT_STREQ(httpReason(503), "Service Unavailable");
}

}  // namespace
}  // namespace sphereset::detail

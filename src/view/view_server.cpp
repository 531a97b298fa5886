// The view's API on a socket (cpp-httplib): every request, whatever its method and path, goes to
// handleViewRequest under one lock, so the scene sees one request at a time. A request that
// cannot have the scene within kBusyWait (another one, a Bound of a large set say, holds it) is
// answered 503 with Retry-After instead of waiting in a worker thread: the page says the server
// is busy, and the workers stay free for the requests that can be answered.
#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include "sphereset/limits.hpp"
#include "sphereset/view.hpp"

// After Eigen (through view.hpp): clang refuses Eigen's product kernels when the system headers
// httplib.h pulls in come first.
#include <httplib.h>

namespace sphereset {

struct ViewServer::Impl {
  ViewScene scene;
  ViewAccess access;
  mutable std::timed_mutex lock;
  httplib::Server http;
  std::thread thread;
  std::atomic<bool> ended{false};  // listen_after_bind returned
};

namespace {

// HTTP 411: a body without a Content-Length (docs/view.md); 503: the scene is busy.
constexpr int kLengthRequired = 411;
constexpr int kServiceUnavailable = 503;
// How long a request waits for the scene before it is answered 503, and the Retry-After sent.
constexpr auto kBusyWait = std::chrono::seconds(2);
constexpr const char* kRetryAfterSeconds = "1";

// The request as the API sees it: header names in lower case, the query's first values.
ViewRequest viewRequest(const httplib::Request& req) {
  ViewRequest r;
  r.method = req.method;
  r.path = req.path;
  for (const auto& [k, v] : req.params) r.query.emplace(k, v);
  for (const auto& [k, v] : req.headers) {
    std::string name = k;
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    // httplib adds these itself; they are not the client's.
    if (name == "remote_addr" || name == "remote_port" || name == "local_addr" ||
        name == "local_port")
      continue;
    r.headers.emplace_back(std::move(name), v);
  }
  r.body = req.body;
  return r;
}

}  // namespace

ViewServer::ViewServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ViewServer::~ViewServer() { stop(); }

Expected<std::unique_ptr<ViewServer>> ViewServer::start(ViewScene scene, const std::string& host,
                                                        int port) {
  auto impl = std::make_unique<Impl>();
  impl->scene = std::move(scene);
  impl->access.token = randomViewToken();
  impl->access.host = host;
  Impl* self = impl.get();
  const auto handler = [self](const httplib::Request& req, httplib::Response& res) {
    const ViewRequest r = viewRequest(req);
    ViewResponse answer;
    std::unique_lock<std::timed_mutex> guard(self->lock, kBusyWait);
    if (guard.owns_lock()) {
      answer = handleViewRequest(&self->scene, self->access, r);
      guard.unlock();
    } else {
      answer.status = kServiceUnavailable;
      answer.body = "{\"error\": \"the server is busy with another request; try again\"}";
      answer.headers = viewResponseHeaders();
      res.set_header("Retry-After", kRetryAfterSeconds);
    }
    res.status = answer.status;
    for (const auto& [name, value] : answer.headers) res.set_header(name.c_str(), value);
    res.set_content(std::move(answer.body), answer.content_type.c_str());
  };
  const std::string any = ".*";
  self->http.Get(any, handler);
  self->http.Post(any, handler);
  self->http.Put(any, handler);
  self->http.Patch(any, handler);
  self->http.Delete(any, handler);
  self->http.Options(any, handler);
  // httplib answers a Content-Length over the cap itself (413) after reading the headers; the
  // answer is sent once the body has been read and discarded, so a client is never left writing
  // into a closed socket. A body without a Content-Length (chunked, or read until the
  // connection closes) has no size to check before it is read: such requests are refused (411)
  // before httplib reads any of it.
  self->http.set_payload_max_length(static_cast<size_t>(limits::kMaxViewRequestBytes));
  self->http.set_pre_routing_handler([](const httplib::Request& req, httplib::Response& res) {
    const bool has_body = req.method != "GET" && req.method != "HEAD" && req.method != "OPTIONS";
    if (!req.has_header("Transfer-Encoding") && (!has_body || req.has_header("Content-Length")))
      return httplib::Server::HandlerResponse::Unhandled;
    res.status = kLengthRequired;
    res.set_content("{\"error\": \"a request body needs a Content-Length\"}", "application/json");
    return httplib::Server::HandlerResponse::Handled;
  });
  self->http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.body.empty())
      res.set_content("{\"error\": \"HTTP " + std::to_string(res.status) + "\"}",
                      "application/json");
  });
  const int bound = port == 0 ? self->http.bind_to_any_port(host)
                              : (self->http.bind_to_port(host, port) ? port : -1);
  if (bound <= 0)
    return Error{ErrorCode::kInvalidArgument, "cannot listen on " + host + ":" +
                                                  std::to_string(port) +
                                                  " (address in use or not this machine's)"};
  self->access.port = bound;
  self->thread = std::thread([self] {
    self->http.listen_after_bind();
    self->ended = true;
  });
  // stop() only stops a server that has begun listening: wait for that here (or for the
  // listening to have ended at once, which is a failure to serve).
  constexpr auto kStartPoll = std::chrono::milliseconds(1);
  while (!self->http.is_running() && !self->ended) std::this_thread::sleep_for(kStartPoll);
  if (!self->http.is_running()) {
    self->thread.join();
    return Error{ErrorCode::kInvalidArgument,
                 "cannot serve on " + host + ":" + std::to_string(self->access.port)};
  }
  return std::unique_ptr<ViewServer>(new ViewServer(std::move(impl)));
}

const ViewAccess& ViewServer::access() const { return impl_->access; }

std::string ViewServer::url() const {
  // Listening on every address (0.0.0.0, ::): the local one is one of them.
  const std::string& h = impl_->access.host;
  const bool any = h == "0.0.0.0" || h == "::";
  const bool v6 = h.find(':') != std::string::npos;
  const std::string host = any ? "127.0.0.1" : v6 ? "[" + h + "]" : h;
  return "http://" + host + ":" + std::to_string(impl_->access.port) +
         "/?token=" + impl_->access.token;
}

ViewScene ViewServer::scene() const {
  std::lock_guard<std::timed_mutex> guard(impl_->lock);
  return impl_->scene;
}

void ViewServer::stop() {
  if (!impl_) return;
  impl_->http.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

}  // namespace sphereset

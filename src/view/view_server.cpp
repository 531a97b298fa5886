// The view's API on a socket. Every request goes to handleViewRequest under one lock, so the
// scene sees one request at a time; this file only moves bytes, under limits that keep a slow or
// idle client from holding the server (a hostile local user once held all eight of a thread
// pool's workers by sending one header line every 4 s, and 200 idle connections delayed a
// user's request by more than 10 s):
//
// - each connection has a thread of its own, at most kMaxConnections at once and
//   kMaxConnectionsPerClient from one address; a connection beyond either is answered 503 with
//   Retry-After at once and closed, so the user's tab always gets an answer;
// - the first byte of a request must come within kFirstByteSeconds, the whole head within
//   kHeadSeconds and the body within kBodySeconds of the connection's start, the answer be
//   taken within kWriteSeconds: a connection over its deadline is closed;
// - one request per connection (Connection: close), so no connection idles between requests;
// - a request that cannot have the scene within kBusyWait (a Bound of a large set holds it) is
//   answered 503 with Retry-After instead of waiting.
//
// cpp-httplib 0.11 (Debian 12's), which served the API before, has a per-read timeout only: it
// cannot bound the time a request's head or body takes, nor cap connections per client. The
// head is read by view_http.cpp, a pure function the tests and the fuzzer drive.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>

#include "sphereset/limits.hpp"
#include "sphereset/view.hpp"
#include "view/view_http.hpp"

namespace sphereset {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxConnections = 64;           // connections served at once
constexpr int kMaxConnectionsPerClient = 32;  // from one address (a remote one with --host)
constexpr auto kFirstByteSeconds = std::chrono::seconds(2);
constexpr auto kHeadSeconds = std::chrono::seconds(5);
constexpr auto kBodySeconds = std::chrono::seconds(30);  // 4 MiB at 140 KiB/s
constexpr auto kWriteSeconds = std::chrono::seconds(30);
constexpr auto kBusyWait = std::chrono::seconds(2);
constexpr const char* kRetryAfterSeconds = "1";
// A body over the cap is read and dropped up to this many bytes so that the client, still
// writing, gets the 413 instead of a reset connection; beyond it the connection is closed.
constexpr int64_t kMaxDrainBytes = 4 * limits::kMaxViewRequestBytes;
// After its answer a connection is closed for writing and what the client still sends (a body
// refused unread) is read and dropped for up to kLingerSeconds and kMaxDrainBytes, so that the
// client reads the answer instead of a reset connection (a "lingering close").
constexpr auto kLingerSeconds = std::chrono::seconds(2);
// How long stop() waits for the requests being answered.
constexpr auto kStopWait = std::chrono::seconds(10);

std::string responseText(const ViewResponse& r, bool head_only, bool retry_after) {
  std::string out = "HTTP/1.1 " + std::to_string(r.status) + " " + detail::httpReason(r.status) +
                    "\r\nContent-Type: " + r.content_type +
                    "\r\nContent-Length: " + std::to_string(r.body.size()) +
                    "\r\nConnection: close\r\n";
  for (const auto& [name, value] : r.headers) out += name + ": " + value + "\r\n";
  if (retry_after) out += std::string("Retry-After: ") + kRetryAfterSeconds + "\r\n";
  out += "\r\n";
  if (!head_only) out += r.body;
  return out;
}

ViewResponse errorResponse(int status, const std::string& message) {
  ViewResponse r;
  r.status = status;
  std::string line;
  for (char c : message) line += (c == '"' || c == '\\') ? ' ' : c;
  r.body = "{\"error\": \"" + line + "\"}";
  r.headers = viewResponseHeaders();
  return r;
}

// Waits until `fd` is readable (or writable) or `deadline` passes; false on the deadline or
// when `stopping` is set.
bool waitFor(int fd, short events, Clock::time_point deadline, const std::atomic<bool>& stopping) {
  constexpr int kSliceMs = 200;  // how often a wait looks at `stopping`
  for (;;) {
    if (stopping) return false;
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, events, 0};
    const int rc = ::poll(&p, 1, static_cast<int>(std::min<int64_t>(left, kSliceMs)));
    if (rc > 0) return true;
    if (rc < 0 && errno != EINTR) return false;
  }
}

bool sendAll(int fd, std::string_view data, Clock::time_point deadline,
             const std::atomic<bool>& stopping) {
  while (!data.empty()) {
    const ssize_t w = ::send(fd, data.data(), data.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    if (w > 0) {
      data.remove_prefix(static_cast<size_t>(w));
      continue;
    }
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK) &&
        waitFor(fd, POLLOUT, deadline, stopping))
      continue;
    return false;
  }
  return true;
}

// Appends what `fd` has to `buf` (at most `most` bytes), waiting until `deadline`; false when
// the connection ends, fails or the deadline passes.
bool receiveSome(int fd, std::string* buf, size_t most, Clock::time_point deadline,
                 const std::atomic<bool>& stopping) {
  if (!waitFor(fd, POLLIN, deadline, stopping)) return false;
  char chunk[16384];
  ssize_t r;
  do r = ::recv(fd, chunk, std::min(sizeof chunk, most), MSG_DONTWAIT);
  while (r < 0 && errno == EINTR);
  if (r < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
  if (r <= 0) return false;
  buf->append(chunk, static_cast<size_t>(r));
  return true;
}

std::string peerAddress(const sockaddr_storage& a) {
  char host[NI_MAXHOST] = "";
  getnameinfo(reinterpret_cast<const sockaddr*>(&a), sizeof a, host, sizeof host, nullptr, 0,
              NI_NUMERICHOST);
  return host;
}

}  // namespace

struct ViewServer::Impl {
  ViewScene scene;
  ViewAccess access;
  mutable std::timed_mutex lock;  // the scene's
  int listen_fd = -1;
  int wake[2] = {-1, -1};  // stop() writes to wake[1] to end the accept loop
  std::thread acceptor;
  std::atomic<bool> stopping{false};
  std::mutex conn_mutex;  // guards the counts and the open connections
  std::condition_variable conn_done;
  int active = 0;
  std::map<std::string, int> per_client;
  std::set<int> open_fds;

  void acceptLoop();
  // One request read and answered; true when an answer was sent (the close then lingers).
  bool serve(int fd);
  bool answered(int fd, const ViewResponse& r, bool head_only, bool retry_after);
};

bool ViewServer::Impl::answered(int fd, const ViewResponse& r, bool head_only, bool retry_after) {
  return sendAll(fd, responseText(r, head_only, retry_after), Clock::now() + kWriteSeconds,
                 stopping);
}

bool ViewServer::Impl::serve(int fd) {
  const auto start = Clock::now();
  std::string buf;
  size_t head_end = std::string::npos;
  // The head: its first byte within kFirstByteSeconds, all of it within kHeadSeconds.
  while ((head_end = detail::httpHeadEnd(buf)) == std::string::npos) {
    if (buf.size() > detail::kMaxHttpHeadBytes)
      return answered(fd, errorResponse(431, "request head too large"), false, false);
    const auto deadline = start + (buf.empty() ? kFirstByteSeconds : kHeadSeconds);
    if (!receiveSome(fd, &buf, detail::kMaxHttpHeadBytes + 4 - buf.size(), deadline, stopping)) {
      if (buf.empty() || stopping) return false;  // idle, or stopped: nothing to linger for
      return answered(fd, errorResponse(408, "the request took too long"), false, false);
    }
  }
  detail::HttpHead head = detail::parseHttpHead(std::string_view(buf).substr(0, head_end));
  std::string body = buf.substr(head_end);
  const bool head_only = head.request.method == "HEAD";
  const auto body_deadline = start + kBodySeconds;
  if (head.status == 413 && head.content_length <= kMaxDrainBytes) {
    // Read and drop the body so that the client gets the answer.
    int64_t left = head.content_length - static_cast<int64_t>(body.size());
    while (left > 0) {
      std::string chunk;
      if (!receiveSome(fd, &chunk, static_cast<size_t>(std::min<int64_t>(left, 1 << 16)),
                       body_deadline, stopping))
        return false;
      left -= static_cast<int64_t>(chunk.size());
    }
  }
  if (head.status != 0)
    return answered(fd, errorResponse(head.status, head.error), head_only, false);
  while (static_cast<int64_t>(body.size()) < head.content_length)
    if (!receiveSome(fd, &body, static_cast<size_t>(head.content_length) - body.size(),
                     body_deadline, stopping)) {
      if (stopping) return false;
      return answered(fd, errorResponse(408, "the request took too long"), false, false);
    }
  body.resize(static_cast<size_t>(head.content_length));  // bytes after it are not read
  head.request.body = std::move(body);
  std::unique_lock<std::timed_mutex> guard(lock, kBusyWait);
  if (!guard.owns_lock())
    return answered(fd, errorResponse(503, "the server is busy with another request; try again"),
                    head_only, true);
  const ViewResponse r = handleViewRequest(&scene, access, head.request);
  guard.unlock();
  return answered(fd, r, head_only, false);
}

void ViewServer::Impl::acceptLoop() {
  for (;;) {
    pollfd p[2] = {{listen_fd, POLLIN, 0}, {wake[0], POLLIN, 0}};
    if (::poll(p, 2, -1) < 0 && errno != EINTR) break;
    if (stopping || (p[1].revents & POLLIN)) break;
    if (!(p[0].revents & POLLIN)) continue;
    sockaddr_storage peer{};
    socklen_t len = sizeof peer;
    const int fd = ::accept4(listen_fd, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_CLOEXEC);
    if (fd < 0) continue;
    const std::string client = peerAddress(peer);
    bool admitted = false;
    {
      std::lock_guard<std::mutex> g(conn_mutex);
      if (active < kMaxConnections && per_client[client] < kMaxConnectionsPerClient) {
        ++active;
        ++per_client[client];
        open_fds.insert(fd);
        admitted = true;
      }
    }
    if (!admitted) {
      // Over a cap: an answer at once (the user's tab shows it), without waiting for the
      // request; whatever the kernel cannot take at once is dropped.
      const std::string busy =
          responseText(errorResponse(503, "too many connections; try again"), false, true);
      (void)::send(fd, busy.data(), busy.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
      ::close(fd);
      continue;
    }
    std::thread([this, fd, client] {
      const bool linger_close = serve(fd);
      ::shutdown(fd, SHUT_WR);
      const auto linger = Clock::now() + kLingerSeconds;
      for (int64_t drained = 0; linger_close && drained < kMaxDrainBytes;) {
        std::string chunk;
        if (!receiveSome(fd, &chunk, 1 << 16, linger, stopping)) break;
        drained += static_cast<int64_t>(chunk.size());
      }
      ::shutdown(fd, SHUT_RDWR);
      std::lock_guard<std::mutex> g(conn_mutex);
      open_fds.erase(fd);
      ::close(fd);
      if (--per_client[client] == 0) per_client.erase(client);
      --active;
      conn_done.notify_all();
    }).detach();
  }
}

ViewServer::ViewServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ViewServer::~ViewServer() { stop(); }

Expected<std::unique_ptr<ViewServer>> ViewServer::start(ViewScene scene, const std::string& host,
                                                        int port) {
  auto cannot = [&] {
    return Error{ErrorCode::kInvalidArgument, "cannot listen on " + host + ":" +
                                                  std::to_string(port) +
                                                  " (address in use or not this machine's)"};
  };
  if (port < 0 || port > 65535) return cannot();
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0) return cannot();
  int fd = -1;
  for (addrinfo* a = found; a != nullptr && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    const int yes = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    constexpr int kBacklog = 128;
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, kBacklog) != 0) {
      ::close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(found);
  if (fd < 0) return cannot();
  sockaddr_storage bound{};
  socklen_t len = sizeof bound;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &len);
  const int bound_port = bound.ss_family == AF_INET6
                             ? ntohs(reinterpret_cast<const sockaddr_in6*>(&bound)->sin6_port)
                             : ntohs(reinterpret_cast<const sockaddr_in*>(&bound)->sin_port);
  auto impl = std::make_unique<Impl>();
  if (::pipe2(impl->wake, O_CLOEXEC) != 0) {
    ::close(fd);
    return Error{ErrorCode::kInvalidArgument,
                 "cannot serve on " + host + ":" + std::to_string(bound_port)};
  }
  impl->scene = std::move(scene);
  impl->access.token = randomViewToken();
  impl->access.host = host;
  impl->access.port = bound_port;
  impl->listen_fd = fd;
  Impl* self = impl.get();
  impl->acceptor = std::thread([self] { self->acceptLoop(); });
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
  if (!impl_ || impl_->listen_fd < 0) return;
  Impl& s = *impl_;
  s.stopping = true;
  const char byte = 0;
  (void)::write(s.wake[1], &byte, 1);
  if (s.acceptor.joinable()) s.acceptor.join();
  ::close(s.listen_fd);
  s.listen_fd = -1;
  std::unique_lock<std::mutex> g(s.conn_mutex);
  for (int fd : s.open_fds) ::shutdown(fd, SHUT_RDWR);  // ends their waits at once
  // A request being answered (a Bound) finishes first; the threads hold `s` until then.
  s.conn_done.wait_for(g, kStopWait, [&] { return s.active == 0; });
  const bool all_done = s.active == 0;
  g.unlock();
  ::close(s.wake[0]);
  ::close(s.wake[1]);
  if (!all_done) (void)impl_.release();  // still used by a thread: kept, not freed
}

}  // namespace sphereset

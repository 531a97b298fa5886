// The view's API over real HTTP: a ViewServer on a free port of 127.0.0.1 and cpp-httplib's
// client, as a page or a hostile page would talk to it.
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "sphereset/limits.hpp"
#include "view/view_fixture.hpp"

// After Eigen (through the fixture): clang refuses Eigen's product kernels when the system
// headers httplib.h pulls in come first.
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <chrono>
#include <thread>
#include <vector>

namespace sphereset::test {
namespace {

class ViewHttpTest : public ViewTest {
 public:
  void SetUp() override {
    // The server closes a connection whose body it refuses (413) while the client may still be
    // writing it: the client must see EPIPE, not die of SIGPIPE (seen once under load).
    std::signal(SIGPIPE, SIG_IGN);
    ViewTest::SetUp();
    auto server = ViewServer::start(boxScene(), "127.0.0.1", 0);
    ASSERT_TRUE(server.ok()) << server.error().message;
    server_ = std::move(server).value();
    client_ = std::make_unique<httplib::Client>("127.0.0.1", server_->access().port);
  }
  void TearDown() override {
    client_.reset();
    server_.reset();
    ViewTest::TearDown();
  }
  httplib::Headers token() const { return {{"X-Sphereset-Token", server_->access().token}}; }
  httplib::Result postJson(const std::string& path, const nlohmann::json& body,
                           httplib::Headers headers) {
    return client_->Post(path.c_str(), headers, body.dump(), "application/json");
  }
  int64_t version() const { return server_->scene().version; }

  std::unique_ptr<ViewServer> server_;
  std::unique_ptr<httplib::Client> client_;
};

TEST_F(ViewHttpTest, ServesTheSceneAndTheGeometry) {
  EXPECT_EQ(server_->url(), "http://127.0.0.1:" + std::to_string(server_->access().port) +
                                "/?token=" + server_->access().token);
  auto res = client_->Get("/api/scene", token());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  const nlohmann::json j = nlohmann::json::parse(res->body);
  EXPECT_EQ(j["solids"][0]["triangles"], 12);
  EXPECT_TRUE(j["solids"][0]["certificate"]["covered"].get<bool>());
  res = client_->Get("/api/geometry?solid=0", token());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->body.size(), 8u + 12u * 8u + 12u * 12u);
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/octet-stream");
  // The page: served with the token in the query when this build has it.
  res = client_->Get(("/?token=" + server_->access().token).c_str());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, viewPageAvailable() ? 200 : 500);
  res = client_->Get("/");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 401);
}

TEST_F(ViewHttpTest, EditBoundAndSave) {
  auto res = postJson(
      "/api/edit",
      {{"solid", 0}, {"edits", {{{"op", "set"}, {"index", 0}, {"sphere", {3, 0.5, 0.5, 0.2}}}}}},
      token());
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_FALSE(nlohmann::json::parse(res->body)["certificate"]["covered"].get<bool>());
  res = postJson("/api/bound", {{"solid", 0}}, token());
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const nlohmann::json bound = nlohmann::json::parse(res->body);
  EXPECT_TRUE(bound["certificate"]["covered"].get<bool>());
  EXPECT_EQ(bound["version"], 2);
  res = postJson("/api/save", nlohmann::json::object(), token());
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  auto saved = readSpheres(path("box.txt"));
  ASSERT_TRUE(saved.ok());
  expectSameSpheres(*saved, spheresOf(bound["spheres"]));
  // The saved file, evaluated on its own, agrees with the certificate.
  const ViewScene scene = server_->scene();
  const EvalResult e = coverageOnly(*scene.solids[0].index, *saved);
  EXPECT_TRUE(e.surface_covered && e.interior_covered);
}

TEST_F(ViewHttpTest, RefusesWhatIsNotThePage) {
  const nlohmann::json edit = {
      {"solid", 0}, {"edits", {{{"op", "set"}, {"index", 0}, {"sphere", {0, 0, 0, 1}}}}}};
  auto res = postJson("/api/edit", edit, {});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 401);
  res = postJson("/api/edit", edit, {{"X-Sphereset-Token", "ffffffffffffffffffffffffffffffff"}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 401);
  httplib::Headers h = token();
  h.emplace("Host", "attacker.example:" + std::to_string(server_->access().port));
  res = postJson("/api/edit", edit, h);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 403);
  h = token();
  h.emplace("Origin", "http://attacker.example");
  res = postJson("/api/edit", edit, h);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 403);
  res = client_->Post("/api/edit", token(), "{\"solid\":", "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  const std::string big(static_cast<size_t>(limits::kMaxViewRequestBytes) + 1, ' ');
  res = client_->Post("/api/edit", token(), big, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 413);
  // A chunked body has no length to check before it is read: refused before it is read, even
  // with the token (so a body of any size cannot fill the memory).
  size_t chunks_sent = 0;
  res = client_->Post(
      "/api/edit", token(),
      [&](size_t, httplib::DataSink& sink) {
        const std::string chunk(1 << 16, ' ');
        if (++chunks_sent > 256) {  // 16 MiB at most, four times the cap
          sink.done();
          return true;
        }
        return sink.write(chunk.data(), chunk.size());
      },
      "application/json");
  if (res) {  // or the connection was closed
    EXPECT_EQ(res->status, 411) << res->body;
  }
  res = client_->Get("/api/nothing", token());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 404);
  res = client_->Put("/api/edit", token(), edit.dump(), "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 405);
  res = postJson("/api/save", {{"path", path("other.txt")}}, token());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  EXPECT_FALSE(std::filesystem::exists(path("other.txt")));
  EXPECT_EQ(version(), 0);
  // The page's own Origin passes.
  h = token();
  h.emplace("Origin", "http://127.0.0.1:" + std::to_string(server_->access().port));
  res = postJson("/api/edit", edit, h);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(version(), 1);
}

// A raw connection to the server, for clients that misbehave on purpose.
int connectTo(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// Whether the server ends the connection (an answer then EOF, or EOF) within `seconds`.
bool closedWithin(int fd, int seconds) {
  timeval tv{seconds, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  char buf[4096];
  for (;;) {
    const ssize_t r = ::recv(fd, buf, sizeof buf, 0);
    if (r == 0) return true;
    if (r < 0) return errno == ECONNRESET;
  }
}

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Connections that send a request line and then one header line now and then once held all of
// a thread pool's workers (a user's request waited 91 s): they hold no one else's turn, and each
// is closed when its head is not complete within the head deadline.
TEST_F(ViewHttpTest, SlowClientsDoNotHoldTheServer) {
  const int port = server_->access().port;
  std::vector<int> slow;
  for (int i = 0; i < 16; ++i) {
    const int fd = connectTo(port);
    ASSERT_GE(fd, 0);
    const std::string line = "GET /api/scene HTTP/1.1\r\nHost: 127.0.0.1\r\n";
    ASSERT_EQ(::send(fd, line.data(), line.size(), MSG_NOSIGNAL),
              static_cast<ssize_t>(line.size()));
    slow.push_back(fd);
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto res = client_->Get("/api/scene", token());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_LT(secondsSince(t0), 2.0) << "the user's request waited for the slow clients";
  for (int fd : slow) {
    EXPECT_TRUE(closedWithin(fd, 10)) << "a slow client was kept past the head deadline";
    ::close(fd);
  }
}

// 200 idle connections once delayed a user's request by more than 10 s: the user gets an answer
// at once (the scene, or 503 "try again" while the connection cap is full), and the scene once
// the idle connections have been dropped at the first-byte deadline.
TEST_F(ViewHttpTest, IdleConnectionsAreDroppedAndTheUserIsAnswered) {
  const int port = server_->access().port;
  std::vector<int> idle;
  for (int i = 0; i < 200; ++i) {
    const int fd = connectTo(port);
    if (fd >= 0) idle.push_back(fd);
  }
  ASSERT_EQ(idle.size(), 200u);
  auto t0 = std::chrono::steady_clock::now();
  auto res = client_->Get("/api/scene", token());
  ASSERT_TRUE(res);
  EXPECT_TRUE(res->status == 200 || res->status == 503) << res->status;
  if (res->status == 503) {
    EXPECT_EQ(res->get_header_value("Retry-After"), "1");
  }
  EXPECT_LT(secondsSince(t0), 2.0);
  std::this_thread::sleep_for(std::chrono::seconds(3));
  res = client_->Get("/api/scene", token());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  for (int fd : idle) {
    EXPECT_TRUE(closedWithin(fd, 1));
    ::close(fd);
  }
}

TEST_F(ViewHttpTest, StopsCleanly) {
  server_->stop();
  auto res = client_->Get("/api/scene", token());
  EXPECT_FALSE(res);  // nobody listens any more
}

}  // namespace
}  // namespace sphereset::test

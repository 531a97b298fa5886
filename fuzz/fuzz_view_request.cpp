// Fuzz target: the view's HTTP API (handleViewRequest, view.hpp) on a scene loaded once (a unit
// box and two spheres), with requests a hostile page could send. The first byte of an input
// picks the path, the method and which of the token, Host and Origin are wrong; the rest is
// the body. Invariant checked on every input: a request answered with an error leaves the
// scene exactly as it was (the same JSON, the same version), and every status is one the
// contract lists (docs/view.md). The same bytes also go to the server's request-head reader
// (src/view/view_http.cpp), whose status must be one it may answer.
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <string_view>

#include "fuzz_input.hpp"
#include "sphereset/view.hpp"
#include "view/view_http.hpp"

namespace {

// The scene's files in a folder of their own, removed at exit.
struct SceneFiles {
  std::string dir;
  SceneFiles() {
    char tmpl[] = "/tmp/sphereset_fuzz_view_XXXXXX";
    const char* made = mkdtemp(tmpl);
    if (made == nullptr) {
      std::perror("mkdtemp");
      std::abort();
    }
    dir = made;
    std::ofstream(dir + "/box.off") << "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n"
                                       "1 1 1\n0 1 1\n3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n"
                                       "3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n"
                                       "3 3 0 4\n3 3 4 7\n";
    std::ofstream(dir + "/box.txt") << "0.5 0.5 0.5 0.9\n0.5 0.5 0.5 0.1\n";
  }
  ~SceneFiles() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

constexpr std::array<const char*, 8> kPaths = {"/api/edit",     "/api/bound", "/api/level",
                                               "/api/pose",     "/api/save",  "/api/scene",
                                               "/api/geometry", "/"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static SceneFiles files;
  static sphereset::ViewScene scene = [] {
    auto s = sphereset::loadViewScene(files.dir + "/box.off", files.dir + "/box.txt");
    if (!s) {
      std::fprintf(stderr, "fuzz_view_request: %s\n", s.error().message.c_str());
      std::abort();
    }
    return std::move(s).value();
  }();
  static const sphereset::ViewAccess access{"00112233445566778899aabbccddeeff", "127.0.0.1", 8080};
  if (size == 0) return 0;
  // The server's head reader on the raw bytes: a status it may answer, never a crash.
  {
    const std::string_view raw(reinterpret_cast<const char*>(data), size);
    const size_t end = sphereset::detail::httpHeadEnd(raw);
    const auto head = sphereset::detail::parseHttpHead(raw.substr(0, end));
    static const std::set<int> kHeadStatuses = {0, 400, 411, 413, 431, 505};
    if (!kHeadStatuses.count(head.status)) std::abort();
    if (head.status == 0 && (head.request.path.empty() || head.request.path[0] != '/'))
      std::abort();
  }
  const uint8_t pick = data[0];
  sphereset::ViewRequest r;
  r.path = kPaths[pick & 7];
  r.method = (pick & 8) ? "GET" : "POST";
  if (r.path == std::string("/api/geometry")) r.query["solid"] = (pick & 64) ? "x" : "0";
  if (r.path == std::string("/")) r.query["token"] = access.token;
  if (!(pick & 16)) r.headers.emplace_back("x-sphereset-token", access.token);
  r.headers.emplace_back("host", (pick & 32) ? "evil.example:8080" : "127.0.0.1:8080");
  if (pick & 128) r.headers.emplace_back("origin", "http://evil.example");
  r.headers.emplace_back("content-type", "application/json");
  r.body = sphereset::fuzz::asString(data + 1, size - 1);

  const std::string before = sphereset::viewSceneJson(scene);
  const int64_t version = scene.version;
  const sphereset::ViewResponse answer = sphereset::handleViewRequest(&scene, access, r);
  static const std::set<int> kStatuses = {200, 400, 401, 403, 404, 405, 413, 500};
  if (!kStatuses.count(answer.status)) {
    std::fprintf(stderr, "fuzz_view_request: status %d\n", answer.status);
    std::abort();
  }
  if (answer.status != 200 &&
      (scene.version != version || sphereset::viewSceneJson(scene) != before)) {
    std::fprintf(stderr, "fuzz_view_request: a refused request (%d) changed the scene\n",
                 answer.status);
    std::abort();
  }
  return 0;
}

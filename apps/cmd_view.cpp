// sphereset view: serves the interactive page (docs/view.md) for a mesh and its spheres, or a
// robot and its links' spheres, on this machine until interrupted; or, with --html, writes the
// page with the scene inlined and exits. The scene, the API and the server are the library's
// (view.hpp); this file translates the command line and waits for SIGINT/SIGTERM.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/view.hpp"

extern char** environ;

namespace sphereset::cli {
namespace {

struct ViewArgs {
  MeshArgs mesh;  // MESH or ROBOT.urdf, and the repair options
  std::string spheres_path, compare, host = "127.0.0.1", output, html, srdf;
  RobotLoadArgs load;
  TableArgs robot;  // the robot table's link_solid and link_solid_for rows
  int port = 0;
  int level = -1;
  bool no_open = false;
};

// The tokened address in a file only this user can read, in a folder of its own (0700, under
// $XDG_RUNTIME_DIR, else $TMPDIR or /tmp): a page that forwards the browser to the address. The
// browser is opened on that file, so the command lines of xdg-open and the browser, which every
// local user can read in ps, never hold the token. The folder is removed when the command ends.
class Launcher {
 public:
  explicit Launcher(const std::string& url) {
    const char* base = std::getenv("XDG_RUNTIME_DIR");
    if (base == nullptr || *base == '\0') base = std::getenv("TMPDIR");
    if (base == nullptr || *base == '\0') base = "/tmp";
    std::string tmpl = std::string(base) + "/sphereset-view.XXXXXX";
    if (mkdtemp(tmpl.data()) == nullptr) return;  // mode 0700
    dir_ = tmpl;
    const std::string page = dir_ + "/open.html";
    const int fd = ::open(page.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) return;
    const std::string html =
        "<!doctype html><meta charset=\"utf-8\"><meta name=\"referrer\" content=\"no-referrer\">"
        "<meta http-equiv=\"refresh\" content=\"0;url=" +
        url +
        "\"><title>sphereset view</title>"
        "<a href=\"" +
        url + "\">open sphereset view</a>\n";
    const bool written = ::write(fd, html.data(), html.size()) == static_cast<ssize_t>(html.size());
    if (::close(fd) == 0 && written) path_ = page;
  }
  ~Launcher() {
    if (dir_.empty()) return;
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  Launcher(const Launcher&) = delete;
  Launcher& operator=(const Launcher&) = delete;
  const std::string& path() const { return path_; }  // empty when it could not be written

 private:
  std::string dir_, path_;
};

// Opens the launcher page in the desktop's browser when xdg-open is there; whatever happens is
// ignored (a machine without a desktop just shows the printed address).
void openBrowser(const Launcher& launcher) {
  if (launcher.path().empty()) return;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::string program = "xdg-open", address = launcher.path();
  char* argv[] = {program.data(), address.data(), nullptr};
  pid_t pid = 0;
  if (posix_spawnp(&pid, "xdg-open", &actions, nullptr, argv, environ) == 0)
    std::thread([pid] { waitpid(pid, nullptr, 0); }).detach();
  posix_spawn_file_actions_destroy(&actions);
}

bool loopback(const std::string& host) {
  return host.rfind("127.", 0) == 0 || host == "localhost" || host == "::1";
}

// SIGINT and SIGTERM, taken by one thread of their own (blocked in every other thread, which
// inherit the mask from the main thread): while the scene loads or a page is written, a signal
// ends the command at once (nothing is written but atomically, so nothing is left half done);
// once the server runs, it stops the server and the command ends with 0.
class StopSignals {
 public:
  StopSignals() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGINT);
    sigaddset(&set_, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set_, nullptr);
    std::thread([this] {
      int number = 0;
      sigwait(&set_, &number);
      std::unique_lock<std::mutex> lock(mutex_);
      if (!serving_) {
        std::fprintf(stderr, "sphereset view: interrupted\n");
        std::_Exit(128 + number);
      }
      stopped_ = true;
      changed_.notify_all();
    }).detach();
  }
  // From now on a signal stops the server instead of the command.
  void serving() {
    std::lock_guard<std::mutex> lock(mutex_);
    serving_ = true;
  }
  void wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return stopped_; });
  }

 private:
  sigset_t set_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool serving_ = false, stopped_ = false;
};

int runView(const ViewArgs& a) {
  StopSignals signals;  // before any other thread starts
  ViewLoadOptions lo;
  auto repair = repairOptions(a.mesh);
  if (!repair) return fail(repair.error());
  lo.repair = *repair;
  RobotFitOptions ro;
  for (const auto& [name, text] : a.robot.given())
    if (Status st = setRobotFitOption(&ro, name, text); !st) return fail(st.error());
  lo.link_solid = ro.link_solid;
  lo.link_solid_for = ro.link_solid_for;
  lo.robot_load = robotLoadOptions(a.load);
  lo.level = a.level;
  lo.output = a.output;
  lo.page_file = !a.html.empty();
  lo.srdf = a.srdf;
  lo.compare = a.compare;
  if (!a.html.empty())
    if (Status st = checkOutputPath(a.html, {a.mesh.path, a.spheres_path, a.compare}); !st)
      return fail(st.error());
  auto scene = loadViewScene(a.mesh.path, a.spheres_path, lo);
  if (!scene) return fail(scene.error());
  // Checked after the inputs, so that a bad input gets its own message and exit code.
  if (int code = requirePage(); code != kOk) return code;
  if (!a.html.empty()) {
    auto page = viewStaticPage(*scene);
    if (!page) return fail(page.error());
    if (Status st = writeTextFile(a.html, *page); !st) return fail(st.error());
    std::cerr << "sphereset view: wrote " << a.html << '\n';
    return kOk;
  }
  if (!loopback(a.host))
    std::cerr << "sphereset view: warning: listening on " << a.host
              << ": anyone who can reach this address and learns the token can edit and save\n";
  auto server = ViewServer::start(std::move(scene).value(), a.host, a.port);
  if (!server) return fail(server.error());
  signals.serving();
  const std::string url = (*server)->url();
  std::cout << "sphereset view: " << url << std::endl;  // flushed: scripts wait for this line
  std::optional<Launcher> launcher;
  if (!a.no_open) openBrowser(launcher.emplace(url));
  signals.wait();
  (*server)->stop();
  return kOk;
}

}  // namespace

Command registerView(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Serve an interactive page of a mesh (or robot) and its spheres, certified live");
  cmd->add_option("mesh", a->mesh.path, "Mesh file, or a robot's URDF")->required();
  cmd->add_option("spheres", a->spheres_path,
                  "Sphere set or tree (.txt, .json, .sph, .yaml); for a URDF the links' spheres "
                  "(.yml from `robot`, or a URDF with sphere collisions)")
      ->required();
  cmd->add_option("compare", a->compare,
                  "A second sphere file of the same mesh or robot, shown beside or over the first "
                  "with its own certificate (read-only)");
  addRepairArgs(cmd, &a->mesh);
  addTableOptions(cmd, &a->robot, robotFitOptionTable(),
                  {"budget", "default_link_spheres", "link_spheres", "padding", "link_padding"});
  addRobotLoadArgs(cmd, &a->load, "With a robot: ");
  cmd->add_option("--port", a->port, "Port to listen on (default 0: any free port)")
      ->check(CLI::Range(0, 65535));
  cmd->add_option("--host", a->host, "Address to listen on (default 127.0.0.1: this machine only)");
  cmd->add_flag("--no-open", a->no_open, "Do not open the page in a browser");
  cmd->add_option("--output", a->output,
                  "Where Save writes (default: the sphere file itself), in its extension's format");
  cmd->add_option("--html", a->html,
                  "Write a static page with the scene inlined to this file and exit (no server)");
  cmd->add_option("--srdf", a->srdf,
                  "With a robot: MoveIt's SRDF, whose disabled pairs the page lists as allowed "
                  "(default: the adjacent links)");
  cmd->add_option("--level", a->level, "A tree's level shown first (default: the leaves)")
      ->check(CLI::NonNegativeNumber);
  return {cmd, [a] { return runView(*a); }};
}

}  // namespace sphereset::cli

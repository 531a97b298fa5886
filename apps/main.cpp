// sphereset: command-line front end. Builds the app, registers the subcommands and runs the
// one selected. Library errors become one line on stderr and an exit code (cli_common.hpp).
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <memory>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace sphereset::cli;
  CLI::App app{"sphereset: tight bounding sphere sets for solid triangle meshes"};
  app.require_subcommand(1);
  app.footer(sphereset::kExitCodesHelp);
  int threads = 0;
  app.add_option("--threads", threads, "Worker threads (default 0: all cores)")
      ->check(CLI::Range(0, 4096));
  // In the order of --help.
  const std::vector<Command> commands = {
      registerCheck(app), registerEval(app),   registerFit(app),     registerCurve(app),
      registerTree(app),  registerRender(app), registerExport(app),  registerQuery(app),
      registerRobot(app), registerBatch(app),  registerAnimate(app), registerView(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "sphereset: " << e.what() << " (see sphereset --help)\n";
    return kUsage;
  }
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  threads);
  try {
    for (const Command& c : commands)
      if (*c.app) return c.run();
  } catch (const std::exception& e) {
    std::cerr << "sphereset: internal error: " << e.what() << '\n';
    return kInternal;
  }
  return kUsage;
}

// The sphereset subcommands. Each register function adds its subcommand and options to the
// app and returns the subcommand with the function that runs it once the command line is
// parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace sphereset::cli {

struct Command {
  CLI::App* app = nullptr;   // selected when *app is true after parsing
  std::function<int()> run;  // returns the exit code
};

Command registerCheck(CLI::App& app);    // cmd_check.cpp
Command registerEval(CLI::App& app);     // cmd_eval.cpp
Command registerFit(CLI::App& app);      // cmd_fit.cpp
Command registerCurve(CLI::App& app);    // cmd_curve.cpp
Command registerTree(CLI::App& app);     // cmd_tree.cpp
Command registerRender(CLI::App& app);   // cmd_render.cpp
Command registerExport(CLI::App& app);   // cmd_export.cpp
Command registerQuery(CLI::App& app);    // cmd_query.cpp
Command registerRobot(CLI::App& app);    // cmd_robot.cpp
Command registerBatch(CLI::App& app);    // cmd_batch.cpp
Command registerAnimate(CLI::App& app);  // cmd_animate.cpp
Command registerView(CLI::App& app);     // cmd_view.cpp

}  // namespace sphereset::cli

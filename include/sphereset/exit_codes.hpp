// The exit codes of the project's commands (`sphereset` and `python3 -m sphereset.batch`): one
// table for every door, listed by --help and in the README. The library itself never exits;
// its errors carry an ErrorCode, which a door turns into a code with exitCodeFor.
#pragma once

#include "sphereset/status.hpp"

namespace sphereset {

enum ExitCode : int {
  kExitOk = 0,
  kExitInternal = 1,
  kExitUsage = 2,             // bad options (ErrorCode::kInvalidArgument)
  kExitUnreadable = 3,        // ErrorCode::kUnreadable
  kExitInvalid = 4,           // ErrorCode::kInvalidData
  kExitNotSolid = 5,          // ErrorCode::kNotSolid
  kExitWrite = 6,             // ErrorCode::kWriteFailed
  kExitUncovered = 7,         // fit, tree, batch: a result failed its own coverage check (written)
  kExitItemsFailed = 8,       // batch: some items failed (each is reported; the others are written)
  kExitNoPage = 9,            // view: this build has no page (web/ was not built)
  kExitToleranceNotMet = 10,  // fit, robot, batch: no count up to the cap meets the tolerance
};

constexpr int exitCodeFor(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument:
      return kExitUsage;
    case ErrorCode::kUnreadable:
      return kExitUnreadable;
    case ErrorCode::kInvalidData:
      return kExitInvalid;
    case ErrorCode::kNotSolid:
      return kExitNotSolid;
    case ErrorCode::kWriteFailed:
      return kExitWrite;
  }
  return kExitInternal;
}

// The footer of --help.
inline constexpr const char* kExitCodesHelp =
    "Exit codes: 0 success, 1 internal error, 2 bad options, 3 unreadable input,\n"
    "4 invalid data, 5 mesh is not a closed solid, 6 output could not be written,\n"
    "7 the result failed its own coverage check (fit, curve, tree: the file is still written),\n"
    "8 some items of a batch failed (batch: the others are written; see report.jsonl),\n"
    "9 this build has no page for `view` (web/ was not built),\n"
    "10 no count up to --max-spheres meets fit's tolerance (or a batch item's), or a robot\n"
    "link misses its protrusion limit (what was found is written only with --best-effort).";

}  // namespace sphereset

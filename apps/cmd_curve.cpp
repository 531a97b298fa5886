// sphereset curve: E_r and the certified protrusion against the sphere count from one run
// (fitCurve, evaluate.hpp), written as CSV: what a user reads to choose a count or a tolerance.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset::cli {
namespace {

struct CurveArgs {
  FitArgs fit;  // the mesh, its repair, the fit's options but n; out_path is the CSV
  std::string counts;
  bool counts_given = false;
  int max_spheres = CurveOptions{}.max_spheres;
  bool json = false;
};

// "1,2,4,8" as counts: digits only between the commas (no sign, space or empty item); the
// library checks their range and order (checkCurveOptions).
Expected<std::vector<int>> parseCounts(const std::string& text) {
  const Error bad{ErrorCode::kInvalidArgument,
                  "counts '" + text + "': expected integers separated by commas"};
  std::vector<int> counts;
  size_t start = 0;
  for (;;) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    if (item.empty() || item.size() > 9 ||
        item.find_first_not_of("0123456789") != std::string::npos)
      return bad;
    counts.push_back(std::stoi(item));
    if (end == text.size()) break;
    start = end + 1;
  }
  return counts;
}

int runCurve(const CurveArgs& c) {
  const FitArgs& a = c.fit;
  // Before any work: the options, and an output that is not the input.
  auto request = fitRequest(a);
  if (!request) return fail(request.error());
  CurveOptions o;
  o.max_spheres = c.max_spheres;
  if (c.counts_given) {
    auto counts = parseCounts(c.counts);
    if (!counts) return fail(counts.error());
    o.counts = std::move(counts).value();
  }
  if (Status st = checkFitRequest(*request); !st) return fail(st.error());
  if (Status st = checkCurveOptions(*request, o); !st) return fail(st.error());
  if (Status st = checkOutputPath(a.out_path, {a.mesh.path}); !st) return fail(st.error());
  auto m = loadSolid(a.mesh);
  if (!m) return fail(m.error());
  const SolidIndex index(m->repair.solid);
  o.original = m->original();
  o.walls = m->walls();
  const int64_t total = o.counts.empty() ? o.max_spheres : static_cast<int64_t>(o.counts.size());
  ProgressLine progress("curve");
  int64_t done = 0;
  if (!a.quiet)
    o.progress = [&](const CurvePoint& p) {
      char what[128];
      std::snprintf(what, sizeof what, "n %d: E_r %.4f, protrusion %.4g", p.n, p.er_sum,
                    p.protrusion);
      progress.show("counts", ++done, total, what);
    };
  auto r = fitCurve(index, *request, o);
  if (!r) return fail(Error{r.error().code, a.mesh.path + ": " + r.error().message});
  if (Status st = writeCurve(a.out_path, r->points); !st) return fail(st.error());
  int uncovered = 0;
  for (const CurvePoint& p : r->points) uncovered += p.covered ? 0 : 1;
  if (c.json) {
    nlohmann::json points = nlohmann::json::array();
    for (const CurvePoint& p : r->points) points.push_back(curvePointJson(p));
    std::cout << jsonText({{"mesh", a.mesh.path},
                           {"output", a.out_path},
                           {"progressive", r->progressive},
                           {"seconds", r->seconds},
                           {"diagonal", index.bounds().diagonal()},
                           {"curve", points}})
              << '\n';
  }
  if (!a.quiet)
    std::fprintf(stderr, "%s: %zu counts (%s) in %.1f s -> %s\n", a.mesh.path.c_str(),
                 r->points.size(), r->progressive ? "one progressive run" : "independent fits",
                 r->seconds, a.out_path.c_str());
  if (uncovered > 0) {
    std::fprintf(stderr, "sphereset: %s: %d counts failed the coverage check (written; see %s)\n",
                 a.mesh.path.c_str(), uncovered, a.out_path.c_str());
    return kUncovered;
  }
  return kOk;
}

}  // namespace

Command registerCurve(CLI::App& app) {
  auto c = std::make_shared<CurveArgs>();
  CLI::App* cmd = app.add_subcommand(
      "curve",
      "E_r and the certified protrusion at every count from 1 to N (or the counts given) from "
      "one progressive run, as CSV: n, er_sum, protrusion, covered, meets, seconds");
  FitArgs& a = c->fit;
  addMeshArgs(cmd, &a.mesh);
  cmd->add_option("-o,--output", a.out_path, "Output CSV, one row per count")->required();
  addFitTuningArgs(cmd, &a, false);
  // Both checked by the library (checkCurveOptions), in its words.
  auto* up_to = cmd->add_option("--max-spheres", c->max_spheres,
                                "The counts 1, 2, ..., N (at most 1024): each count's fit and "
                                "its check")
                    ->capture_default_str();
  cmd->add_option_function<std::string>(
         "--counts",
         [c](const std::string& text) {
           c->counts = text;
           c->counts_given = true;
         },
         "Only these counts, increasing, separated by commas (e.g. 1,2,4,8,16,32,64)")
      ->excludes(up_to);
  cmd->add_flag("--json", c->json, "Print the curve as one JSON object on stdout");
  cmd->add_flag("-q,--quiet", a.quiet, "No progress on stderr");
  return {cmd, [c] { return runCurve(*c); }};
}

}  // namespace sphereset::cli

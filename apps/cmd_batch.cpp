// sphereset batch: fits every mesh of a folder or a manifest as `sphereset fit` would, one sphere
// file per mesh under the output folder and one report line per item (batch.hpp). Items that
// are up to date are skipped; a failed item is reported and the batch goes on.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/batch.hpp"
#include "sphereset/view.hpp"

namespace sphereset::cli {
namespace {

struct BatchArgs {
  FitArgs fit;          // the fit options (mesh.path is the input, out_path the output folder)
  TableArgs tolerance;  // the rows of toleranceOptionTable(): every item's unless its line says
  std::string format = "json";
  int jobs = 1;
  bool force = false, dry_run = false, html = false;
  bool best_effort = false;  // BatchOptions::best_effort
};

// With --html, the view's static page of an item written beside its sphere file
// (OUT/a/b.json -> OUT/a/b.html): its solid made as the batch made it, its spheres and their
// certificate. An item skipped as up to date keeps a page it has.
Status writeItemPage(const BatchItem& item, const BatchItemReport& r, const std::string& out,
                     const RepairOptions& repair) {
  if (r.status == BatchStatus::kError) return {};
  const std::filesystem::path spheres = std::filesystem::path(out) / item.output;
  std::filesystem::path page = spheres;
  page.replace_extension(".html");
  if (r.status == BatchStatus::kSkipped && std::filesystem::exists(page)) return {};
  ViewLoadOptions lo;
  lo.repair = repair;
  auto scene = loadViewScene(item.mesh, spheres.string(), lo);
  if (!scene) return scene.error();
  auto text = viewStaticPage(*scene);
  if (!text) return text.error();
  return writeTextFile(page.string(), *text);
}

// "1 h 05 min", "4 min 10 s", "12 s".
std::string duration(double s) {
  char buf[48];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%d h %02d min", static_cast<int>(s / 3600),
                  static_cast<int>(s / 60) % 60);
  else if (s >= 60)
    std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s / 60),
                  static_cast<int>(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%.0f s", s);
  return buf;
}

// Counts of the items reported so far and the progress line.
class Progress {
 public:
  Progress(size_t total, bool quiet)
      : total_(total),
        quiet_(quiet),
        tty_(isatty(STDERR_FILENO) != 0),
        start_(std::chrono::steady_clock::now()) {}

  void add(const BatchItemReport& r) {
    countBatchItem(r, &totals_);
    if (quiet_) return;
    const double t = seconds();
    // Skipped items take no time: the rate counts the items fitted.
    const size_t run = totals_.items - totals_.skipped;
    const double rate = run > 0 && t > 0 ? 60.0 * static_cast<double>(run) / t : 0.0;
    const size_t left = total_ - totals_.items;
    std::string eta = left == 0 ? "done" : rate > 0 ? duration(60.0 * left / rate) + " left" : "";
    char item[512];
    if (r.status == BatchStatus::kError)
      std::snprintf(item, sizeof item, "error: %s", r.error.c_str());
    else
      std::snprintf(item, sizeof item, "%s -> %s %s, %d spheres, E_r %.4f%s%s (%.1f s)",
                    r.mesh.c_str(), r.output.c_str(), batchStatusName(r.status), r.spheres,
                    r.er_sum, r.covered ? "" : ", NOT covered",
                    r.tolerance_met ? "" : ", tolerance NOT met (best count)", r.seconds);
    char line[256];
    std::snprintf(line, sizeof line,
                  "batch: %zu/%zu items (%zu failed, %zu skipped), %.1f items/min, %s",
                  totals_.items, total_, totals_.failed, totals_.skipped, rate, eta.c_str());
    if (tty_)
      std::fprintf(stderr, "\r\033[K%s\n%s", item, line);
    else
      std::fprintf(stderr, "%s\n%s\n", item, line);
    if (tty_ && left == 0) std::fprintf(stderr, "\n");
  }

  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  const BatchTotals& totals() const { return totals_; }

 private:
  size_t total_;
  BatchTotals totals_;
  bool quiet_, tty_;
  std::chrono::steady_clock::time_point start_;
};

int runBatch(const BatchArgs& c) {
  const FitArgs& a = c.fit;
  BatchOptions options;
  auto request = fitRequest(a);
  if (!request) return fail(request.error());
  options.fit = std::move(request).value();
  for (const auto& [name, text] : c.tolerance.given())
    if (Status st = setToleranceOption(&options.tolerance, name, text); !st)
      return fail(st.error());
  auto repair = repairOptions(a.mesh);
  if (!repair) return fail(repair.error());
  options.repair = std::move(repair).value();
  options.format = c.format;
  options.resume = !c.force;
  options.best_effort = c.best_effort;
  auto items = listBatchItems(a.mesh.path, options);
  if (!items) return fail(items.error());
  const std::string& out = a.out_path;
  if (Status st = checkOutputFolder(out, {a.mesh.path}); !st) return fail(st.error());
  if (c.dry_run) {
    for (const BatchItem& it : *items)
      std::printf("%s -> %s n=%d %s\n", it.mesh.c_str(), it.output.c_str(), it.fit.num_spheres,
                  batchItemDone(it, out, options) ? "up to date" : "to fit");
    return kOk;
  }
  if (c.html)
    if (int code = requirePage(); code != kOk) return code;
  auto report = BatchReport::start(out);  // locks the folder for this run
  if (!report) return fail(report.error());
  if (items->empty()) {
    if (Status st = report->finish(); !st) return fail(st.error());
    if (!a.quiet) std::fprintf(stderr, "batch: %s: no meshes\n", a.mesh.path.c_str());
    return kOk;
  }

  // Workers take the items in order; the reports are appended in item order as soon as every
  // item before them is done.
  const size_t n = items->size();
  std::vector<std::optional<BatchItemReport>> reports(n);
  std::mutex mutex;
  std::atomic<size_t> next{0};
  size_t written = 0;
  std::optional<Error> write_error;
  std::vector<std::pair<size_t, Error>> page_errors;  // --html pages not written, by item
  Progress progress(n, a.quiet);
  const auto work = [&] {
    while (true) {
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (write_error) return;
      }
      const size_t i = next.fetch_add(1);
      if (i >= n) return;
      BatchItemReport r = processBatchItem((*items)[i], out, options);
      const Status page = c.html ? writeItemPage((*items)[i], r, out, options.repair) : Status{};
      std::lock_guard<std::mutex> lock(mutex);
      if (!page) page_errors.emplace_back(i, page.error());
      reports[i] = std::move(r);
      while (written < n && reports[written] && !write_error) {
        if (Status st = report->append(*reports[written]); !st) write_error = st.error();
        progress.add(*reports[written]);
        ++written;
      }
    }
  };
  const int jobs = static_cast<int>(std::min<size_t>(static_cast<size_t>(c.jobs), n));
  std::vector<std::thread> threads;
  for (int t = 1; t < jobs; ++t) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (write_error) return fail(*write_error);
  if (Status st = report->finish(); !st) return fail(st.error());

  const BatchEnd end = batchEnd(progress.totals(), a.mesh.path, out);
  if (!a.quiet)
    std::fprintf(stderr, "batch: %s in %s -> %s\n", end.summary.c_str(),
                 duration(progress.seconds()).c_str(), batchReportPath(out).c_str());
  if (!page_errors.empty()) {
    // In item order, whatever the order the workers finished in.
    std::sort(page_errors.begin(), page_errors.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [item, e] : page_errors) fail(e);
    std::fprintf(stderr, "sphereset: %s: %zu of %zu pages could not be written\n",
                 a.mesh.path.c_str(), page_errors.size(), n);
    return kWrite;
  }
  if (end.exit_code != kOk) std::fprintf(stderr, "sphereset: %s\n", end.message.c_str());
  return end.exit_code;
}

}  // namespace

Command registerBatch(CLI::App& app) {
  auto c = std::make_shared<BatchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "batch",
      "Fit every mesh of a folder (recursively) or of a manifest (.csv/.jsonl), one sphere file "
      "per mesh and a report line per item in OUT_DIR/report.jsonl; resumable");
  FitArgs& a = c->fit;
  cmd->add_option("input", a.mesh.path,
                  "A folder (every file assimp reads, recursively) or a manifest: .csv with a "
                  "header (mesh,n,output,quality,seed,...) or .jsonl with one object per line; "
                  "mesh paths relative to the manifest's folder")
      ->required();
  cmd->add_option("-o,--output", a.out_path,
                  "Output folder: the sphere files mirror the input's layout, and report.jsonl")
      ->required();
  cmd->add_option("--format", c->format, "Sphere files written: json, txt, sph or yaml")
      ->capture_default_str()
      ->check(CLI::IsMember({"json", "txt", "sph", "yaml"}));
  addRepairArgs(cmd, &a.mesh);
  // The fit's options (n included) are the defaults of items whose manifest line gives none.
  addFitTuningArgs(cmd, &a, true);
  // A tolerance instead of n (the fewest spheres that meet it), every item's unless its line
  // gives another.
  addTableOptions(cmd, &c->tolerance, toleranceOptionTable());
  cmd->add_option("-j,--jobs", c->jobs,
                  "Items fitted at once (each fit is parallel already; more can help with many "
                  "small meshes)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  cmd->add_flag("--html", c->html,
                "Also write each item's page beside its sphere file (OUT/a/b.html): its solid, "
                "spheres and certificate, as `sphereset view --html` writes it");
  cmd->add_flag("--best-effort", c->best_effort,
                "An item whose tolerance no count up to its cap meets: write the best count found "
                "(report: tolerance_met false; exit 10) instead of failing the item");
  cmd->add_flag("--force", c->force, "Fit every item again, even those up to date");
  cmd->add_flag("--dry-run", c->dry_run,
                "List the items (mesh -> output, n, up to date or not) on stdout and stop");
  cmd->add_flag("-q,--quiet", a.quiet, "No progress on stderr");
  return {cmd, [c] { return runBatch(*c); }};
}

}  // namespace sphereset::cli

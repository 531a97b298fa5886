// Fitting whole collections of meshes: the items of a batch (a folder of meshes or a manifest),
// one item fitted exactly as `sphereset fit` fits it, its line of the report, and resuming a
// batch that was stopped.
//
// Every function works on one item at a time, so that a batch can be spread over processes or
// machines: `sphereset batch` runs the items in order in one process; a distributed runner
// calls processBatchItem (or runBatchItem) once per item in its workers and appends the reports
// in item order itself. Both write the same files and the same report.
//
// Layout of the output folder OUT:
//   OUT/<item.output>                      the sphere file of each item that succeeded
//   OUT/report.jsonl                       one reportLine per item, in item order
//   OUT/.sphereset-batch/<item.output>.json  the record of each item that succeeded: its report
//                                          line with the fingerprint of its options and input
//                                          and a digest of the sphere file (used to resume)
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// Options of the whole batch; each item may override the fit request (BatchItem::fit).
struct BatchOptions {
  // The fit of every item unless its manifest line says otherwise (n, quality, seed, ...).
  FitRequest fit;
  // A tolerance for every item unless its manifest line says otherwise (max_protrusion,
  // max_er, max_spheres; evaluate.hpp): when one is set, an item's count is the fewest that
  // meet it (fitToTolerance), not n. Its original and walls are the item's own.
  ToleranceOptions tolerance;
  // An item whose tolerance no count up to its cap meets: false, the item is an error and
  // nothing is written; true, the best count found is written (status ok, tolerance_met false)
  // and the run ends with kExitToleranceNotMet (`sphereset batch --best-effort`).
  bool best_effort = false;
  // How a mesh that is not a clean solid is made one, as `sphereset fit --repair ...` does. The
  // union and the wrapping (operations) are not part of the core library: callers that link
  // sphereset_repair set them to cgalSolidOperations() (repair_cgal.hpp), as the CLI does;
  // without them the meshes that need them fail with kNotSolid.
  RepairOptions repair;
  // Extension of the sphere files written, which sets their format (sphere_io.hpp): "json",
  // "txt", "sph" or "yaml" (a cuRobo file with one link named after the mesh's stem).
  std::string format = "json";
  // processBatchItem skips items whose output is up to date (batchItemDone); false fits every
  // item again.
  bool resume = true;
  // Worker threads of one item's fit and evaluation: 0 uses the process's TBB default; k > 0
  // runs the item in a TBB arena of k threads (e.g. one per worker process). The result does
  // not depend on it.
  int threads = 0;
};

// One mesh to fit.
struct BatchItem {
  // Path of the mesh file: relative to the current directory or absolute (listBatchItems joins
  // the input folder or the manifest's folder in front of the names it finds).
  std::string mesh;
  // Path of the sphere file relative to the output folder, with forward slashes, e.g.
  // "robots/arm/link1.json". Never absolute, never with "..".
  std::string output;
  // The fit of this item: BatchOptions::fit with the manifest line's values applied.
  FitRequest fit;
  // Where the item came from, for messages: "folder/a.obj" or "list.csv:7".
  std::string origin;
  // Its tolerance: BatchOptions::tolerance with the line's values applied.
  ToleranceOptions tolerance;
};

// The items of a batch, in the order they are run and reported. `input` is
//   - a folder: every regular file below it (recursively, entries whose names start with '.'
//     skipped) whose extension assimp imports (case-insensitive; Assimp::Importer's list),
//     sorted by their path relative to the folder (byte order, '/' separators). The output is
//     the relative path with the extension replaced by options.format ("a/b.obj" ->
//     "a/b.json"); when two meshes would share an output (a/b.obj and a/b.stl), each keeps its
//     extension ("a/b.obj.json", "a/b.stl.json").
//   - a manifest: a .csv file (a header line naming the columns, then one item per line; fields
//     may be quoted with "..." and "" inside; empty lines and lines starting with '#' skipped)
//     or a .jsonl file (one JSON object per line; empty lines skipped). Columns / keys:
//       mesh        required: path of the mesh, relative to the manifest's folder (or absolute)
//       n           number of spheres (default options.fit.num_spheres)
//       output      sphere file relative to the output folder (default: the mesh path relative
//                   to the manifest's folder with its extension replaced, as for a folder; a
//                   mesh outside that folder gives its file name)
//       quality, seed, points, iterations, restarts, decimation, padding, optimizer, init,
//       method      the options of `sphereset fit` of the same names (an empty CSV field or a
//                   JSON null keeps the batch's value)
//       max_protrusion, max_er, max_spheres
//                   a tolerance (toleranceOptionTable, `sphereset fit --max-protrusion ...`):
//                   the item's count is the fewest that meet it; a line may not give n with one,
//                   nor a cap without one (checkToleranceRequest, the batch's values included)
//     In the manifest, items are run in line order.
// Errors: kUnreadable (input missing, not a folder, .csv or .jsonl, or unreadable),
// kInvalidData (a bad manifest line: unknown column, missing mesh, a value out of range or not
// a number, bad JSON, two items writing the same output; the message names the file and the
// line; a line against checkToleranceRequest), kInvalidArgument (options.format unknown,
// options.fit out of range; for a folder, options against checkToleranceRequest). An empty folder
// or manifest gives no items (not an error).
Expected<std::vector<BatchItem>> listBatchItems(const std::string& input,
                                                const BatchOptions& options);

enum class BatchStatus {
  kOk,       // fitted and written (the coverage may still have failed: see `covered`)
  kError,    // nothing written; `error` says why
  kSkipped,  // up to date from an earlier run (figures from that run's record)
};

// "ok", "error", "skipped".
const char* batchStatusName(BatchStatus status);

// What became of one item: one line of report.jsonl.
struct BatchItemReport {
  std::string mesh;    // BatchItem::mesh
  std::string output;  // BatchItem::output
  BatchStatus status = BatchStatus::kError;
  int num_spheres = 0;  // asked for (the request's n; 0 when a tolerance chose the count)
  int spheres = 0;      // written (0 on error)
  // E_r summed: Σ outside volume of the spheres / volume of the solid (exact), as er_sum of
  // `sphereset fit --json`; and E_r of their union (Monte Carlo). NaN on error.
  double er_sum = 0.0;
  double er_union = 0.0;
  // Eval's coverage certificate: surface, interior and (after a repair) the original triangles
  // covered, as `sphereset fit` checks before exiting 0.
  bool covered = false;
  // The certified protrusion of the spheres written (evaluate.hpp; NaN on error), and whether the
  // item's tolerance was met (true without one; an item whose tolerance no count meets is an
  // error and writes nothing, unless BatchOptions::best_effort writes its best count).
  double protrusion = 0.0;
  bool tolerance_met = true;
  std::string repair;  // repairName of what made the solid ("none", "welded", ...); "" on error
  // Wall time of the item: load, repair, fit, write, evaluation (of the run that fitted it).
  double seconds = 0.0;
  std::string error;  // status kError: one line naming the mesh and the problem; else ""
  // Status kError only; not part of the report line (parseReportLine gives kInvalidData).
  ErrorCode error_code = ErrorCode::kInvalidData;
  // batchFingerprint of the item (16 hex digits); "" when the mesh could not be read.
  std::string fingerprint;
};

// The item's line of report.jsonl: one JSON object without the newline, keys in this order:
// mesh, output, status, n, spheres, er_sum, er_union, covered, protrusion, tolerance_met,
// repair, seconds, error, fingerprint (er_sum, er_union and protrusion null on error).
std::string reportLine(const BatchItemReport& report);

// Reads a line written by reportLine. Errors: kInvalidData naming what is wrong.
Expected<BatchItemReport> parseReportLine(const std::string& line);

// The counts of a run's items, as every batch door reports them.
struct BatchTotals {
  size_t items = 0, fitted = 0, skipped = 0, failed = 0;
  size_t uncovered = 0;  // written (fitted or skipped) but not covered
  size_t unmet = 0;      // written (BatchOptions::best_effort) but missing their tolerance
};

// Counts one item. An item skipped as up to date keeps its recorded coverage: a resumed batch
// ends as the first run did.
void countBatchItem(const BatchItemReport& report, BatchTotals* totals);

// How a run ends: its summary ("12 items: 10 fitted, 1 skipped, 1 failed"), and the exit code
// of exit_codes.hpp with, when it is not kExitOk, the one line that says why, naming the input
// and the report: kExitItemsFailed when some item failed (the others are written), else
// kExitToleranceNotMet when some item written with best_effort missed its tolerance, else
// kExitUncovered when some item failed its coverage check (written anyway).
struct BatchEnd {
  std::string summary;
  int exit_code = 0;
  std::string message;  // "" with kExitOk
};
BatchEnd batchEnd(const BatchTotals& totals, const std::string& input, const std::string& out_dir);

// Fingerprint of what determines an item's sphere file: the fit options the request resolves to
// (fitOptionsFor), the repair options (and whether the union and the wrapping are available),
// the output's format and the bytes of the mesh file. 16 hex digits (FNV-1a, 64 bits).
// Errors: kUnreadable when the mesh file cannot be read.
Expected<std::string> batchFingerprint(const BatchItem& item, const BatchOptions& options);

// Fits one item as `sphereset fit` does with the same options (loadSolid with options.repair,
// fitOptionsFor(item.fit) with the original triangles, fitCheckEvalOptions for the check), so
// the spheres are those of `sphereset fit MESH -n N ... -o OUT/<output>`: writes the sphere file
// atomically (creating the folders of item.output), then the item's record. Never throws for
// bad data and never stops at a bad mesh: any failure gives status kError with the message.
// The item's record is removed first, so a failed run never leaves the item up to date: a
// failure before the sphere file is written leaves an earlier file of the same output as it
// was; one after it (writing the record) leaves the new file. Thread-safe for distinct
// outputs.
BatchItemReport runBatchItem(const BatchItem& item, const std::string& out_dir,
                             const BatchOptions& options);

// Whether the item is up to date in `out_dir`: its sphere file exists, its record exists with
// status ok (and its tolerance met, unless options.best_effort), the record's fingerprint equals
// batchFingerprint(item, options), the sphere file still has the digest recorded, and so has every
// file the mesh referenced when it was fitted (LoadReport::files: a glTF's .bin buffers, an OBJ's
// .mtl).
bool batchItemDone(const BatchItem& item, const std::string& out_dir, const BatchOptions& options);

// The report of an up-to-date item (status kSkipped, figures and seconds from its record), or
// nothing when batchItemDone is false.
std::optional<BatchItemReport> skippedBatchItem(const BatchItem& item, const std::string& out_dir,
                                                const BatchOptions& options);

// What a batch does with one item: skippedBatchItem when options.resume and the item is up to
// date, else runBatchItem. The unit of work of a distributed batch.
BatchItemReport processBatchItem(const BatchItem& item, const std::string& out_dir,
                                 const BatchOptions& options);

// OUT/report.jsonl.
std::string batchReportPath(const std::string& out_dir);

// One run's report and its hold on the output folder.
// - start() creates `out_dir` (and its parents), locks it for this run (OUT/.sphereset-batch/
//   lock: an advisory lock that the system releases when the process ends, however it ends,
//   holding the run's pid and start time) and starts OUT/report.jsonl.partial. A second run on
//   the same folder, in any process, fails here with kWriteFailed naming the run that holds it,
//   before it fits anything.
// - append() adds reportLine(report) and a newline to the partial report in one write (call it
//   in item order), so the partial report holds whole lines only.
// - finish() renames the partial report over OUT/report.jsonl and releases the lock: report.jsonl
//   is always the whole report of the last run that finished; a run that is killed leaves the
//   previous report as it was, and its own lines in report.jsonl.partial.
// Errors: kWriteFailed naming the path. Move-only; destruction releases the lock.
class BatchReport {
 public:
  static Expected<BatchReport> start(const std::string& out_dir);
  Status append(const BatchItemReport& report);
  Status finish();

  BatchReport(BatchReport&& other) noexcept;
  BatchReport& operator=(BatchReport&& other) noexcept;
  BatchReport(const BatchReport&) = delete;
  BatchReport& operator=(const BatchReport&) = delete;
  ~BatchReport();

 private:
  BatchReport() = default;
  void release();
  std::string out_dir_;
  int lock_fd_ = -1;
};

// OUT/report.jsonl.partial: the report of the run in progress (BatchReport).
std::string batchPartialReportPath(const std::string& out_dir);

}  // namespace sphereset

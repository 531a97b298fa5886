// One item of a batch (batch.hpp): loaded, repaired, fitted (Wang et al. 2006, Sec. 5, through
// fitSpheres) and evaluated exactly as `sphereset fit` does, its sphere file and its record
// written; and the check that lets a batch skip the items that are up to date.
#include <tbb/task_arena.h>

#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "batch/batch_internal.hpp"
#include "io/json_text.hpp"
#include "sphereset/batch.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"
#include "util/read_file.hpp"

namespace sphereset {
namespace fs = std::filesystem;
namespace {

// Bumped when the meaning of the fingerprint's fields changes.
constexpr int kFingerprintVersion = 2;

// Folder of the item records inside the output folder.
constexpr const char* kRecordDir = detail::kBatchStateFolder;

std::string outputPath(const std::string& out_dir, const BatchItem& item) {
  return (fs::path(out_dir) / item.output).string();
}

std::string recordPath(const std::string& out_dir, const BatchItem& item) {
  return (fs::path(out_dir) / kRecordDir / (item.output + ".json")).string();
}

std::string real(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The fingerprint from the mesh file's bytes.
std::string fingerprintOf(const std::string& mesh_bytes, const BatchItem& item,
                          const BatchOptions& options) {
  const FitOptions f = fitOptionsFor(item.fit);
  const RepairOptions& r = options.repair;
  std::string s = "sphereset batch " + std::to_string(kFingerprintVersion);
  s += "\nfit n=" + std::to_string(f.num_spheres) + " method=" + fitMethodName(f.method) +
       " seed=" + std::to_string(f.seed) + " points=" + std::to_string(f.target_points) +
       " interior_share=" + real(f.interior_share) +
       " iterations=" + std::to_string(f.max_iterations) + " tolerance=" + real(f.tolerance) +
       " failed_teleports=" + std::to_string(f.max_failed_teleports) +
       " init=" + fitInitName(f.init) + " optimizer=" + sphereOptimizerName(f.optimizer) +
       " evaluations=" + std::to_string(f.optimizer_evaluations) + " padding=" + real(f.padding) +
       " shrink_passes=" + std::to_string(f.shrink_passes) + " decimation=" + real(f.decimation) +
       " restarts=" + std::to_string(f.restarts);
  const ToleranceOptions& t = item.tolerance;
  if (t.active())
    s += "\ntolerance max_protrusion=" + real(t.max_protrusion) +
         " max_protrusion_fraction=" + real(t.max_protrusion_fraction) +
         " max_er=" + real(t.max_er) + " max_spheres=" + std::to_string(t.max_spheres);
  s += "\nrepair enabled=" + std::to_string(r.enabled) + " weld=" + real(r.weld_tolerance) +
       " fill_cavities=" + std::to_string(r.fill_cavities) + " wrap_alpha=" + real(r.wrap_alpha) +
       " wrap_offset=" + real(r.wrap_offset) +
       " unite=" + std::to_string(static_cast<bool>(r.operations.unite)) +
       " wrap=" + std::to_string(static_cast<bool>(r.operations.wrap));
  s += "\noutput " + fs::path(item.output).extension().string();
  s += "\nmesh " + detail::hex64(detail::fnv1a(mesh_bytes));
  return detail::hex64(detail::fnv1a(s));
}

// The digest of a file's bytes, or nothing when it cannot be read.
std::optional<std::string> fileDigest(const std::string& path) {
  auto bytes = detail::readFileText(path);
  if (!bytes) return std::nullopt;
  return detail::hex64(detail::fnv1a(*bytes));
}

// What a fit wrote and read besides the mesh: the digest of its sphere file, and the files the
// mesh references (a glTF's .bin, an OBJ's .mtl) with their digests. Resuming compares both:
// the fingerprint covers the mesh file's own bytes only.
struct ItemFiles {
  std::string output_digest;
  std::vector<std::pair<std::string, std::string>> companions;  // (path as read, digest)
};

// The record of an item: its report line with the digests of ItemFiles.
Status writeRecord(const std::string& out_dir, const BatchItem& item, const BatchItemReport& report,
                   const ItemFiles& files) {
  const std::string path = recordPath(out_dir, item);
  std::error_code ec;
  fs::create_directories(fs::path(path).parent_path(), ec);
  if (ec)
    return Error{ErrorCode::kWriteFailed,
                 path + ": cannot create the folder (" + ec.message() + ")"};
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(reportLine(report));
  j["output_digest"] = files.output_digest;
  nlohmann::ordered_json companions = nlohmann::ordered_json::object();
  for (const auto& [file, digest] : files.companions) companions[file] = digest;
  j["companions"] = companions;
  return writeTextFile(path, detail::jsonText(j) + "\n");
}

// The fitting itself; fills `rep` (status ok) or returns the error.
Status fitItem(const BatchItem& item, const std::string& out_dir, const BatchOptions& options,
               BatchItemReport* rep, ItemFiles* files) {
  if (Status st = checkBatchOptions(options); !st) return st;
  auto format = sphereFormatFromPath(item.output);
  if (!format) return format.error();
  auto bytes = detail::readFileText(item.mesh);
  if (!bytes) return bytes.error();
  rep->fingerprint = fingerprintOf(*bytes, item, options);
  bytes = std::string();  // loadSolid reads the file itself

  auto solid = loadSolid(item.mesh, options.repair);
  if (!solid) return solid.error();
  rep->repair = repairName(solid->repair.kind);
  const std::vector<std::string>& read = solid->loaded.report.files;
  for (size_t i = 1; i < read.size(); ++i) {
    auto d = fileDigest(read[i]);
    if (!d)
      return Error{ErrorCode::kUnreadable,
                   read[i] + ": cannot be read (referenced by " + item.mesh + ")"};
    files->companions.emplace_back(read[i], *d);
  }
  FitOptions fo = fitOptionsFor(item.fit);
  fo.original = solid->original();
  const SolidIndex index(solid->repair.solid);
  // The spheres and eval's check of them: a fit of n, or the fewest that meet the tolerance.
  std::vector<Sphere> spheres;
  double energy = 0.0;
  std::optional<EvalResult> tolerance_check;
  if (item.tolerance.active()) {
    ToleranceOptions t = item.tolerance;
    t.original = solid->original();
    t.walls = solid->walls();
    t.progress = nullptr;
    auto found = fitToTolerance(index, item.fit, t);
    if (!found) return Error{found.error().code, item.mesh + ": " + found.error().message};
    if (!found->met && !options.best_effort) {
      char what[200];
      std::snprintf(what, sizeof what,
                    ": no count up to %d meets the tolerance (best: n = %d, protrusion %.6g, "
                    "E_r %.4f)",
                    t.max_spheres, found->n, found->eval.protrusion, found->eval.er_sum);
      return Error{ErrorCode::kInvalidArgument, item.mesh + what};
    }
    rep->tolerance_met = found->met;  // false only with best_effort: its best count is written
    spheres = std::move(found->fit.spheres);
    energy = found->fit.energy;
    tolerance_check = std::move(found->eval);
  } else {
    auto fit = fitSpheres(index, fo);
    if (!fit) return Error{fit.error().code, item.mesh + ": " + fit.error().message};
    spheres = std::move(fit->spheres);
    energy = fit->energy;
  }

  const std::string out = outputPath(out_dir, item);
  std::error_code ec;
  fs::create_directories(fs::path(out).parent_path(), ec);
  if (ec)
    return Error{ErrorCode::kWriteFailed,
                 out + ": cannot create the folder (" + ec.message() + ")"};
  SphereFileMeta meta;
  meta.name = fs::path(item.mesh).stem().string();
  meta.source_mesh = item.mesh;
  if (Status st = writeSpheres(out, spheres, meta); !st) return st;
  auto d = fileDigest(out);
  if (!d) return Error{ErrorCode::kWriteFailed, out + ": cannot read back the file written"};
  files->output_digest = *d;

  if (!tolerance_check) {
    auto checked = evaluateSpheres(index, spheres,
                                   fitCheckEvalOptions(fo.seed, solid->original(), solid->walls()));
    if (!checked) return Error{checked.error().code, item.mesh + ": " + checked.error().message};
    tolerance_check = std::move(checked).value();
  }
  const EvalResult& ev = *tolerance_check;
  rep->spheres = static_cast<int>(spheres.size());
  rep->er_sum = energy / ev.mesh_volume;
  rep->protrusion = ev.protrusion;
  rep->er_union = ev.er_union;
  rep->covered = ev.surface_covered && ev.interior_covered && ev.original_covered;
  rep->status = BatchStatus::kOk;
  return {};
}

// The item's record when it is up to date, else nothing.
std::optional<BatchItemReport> upToDate(const BatchItem& item, const std::string& out_dir,
                                        const BatchOptions& options) {
  std::error_code ec;
  if (!fs::is_regular_file(outputPath(out_dir, item), ec)) return std::nullopt;
  auto text = detail::readFileText(recordPath(out_dir, item));
  if (!text) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("output_digest") ||
      !j["output_digest"].is_string())
    return std::nullopt;
  std::string line = *text;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  auto rec = parseReportLine(line);
  if (!rec || rec->status != BatchStatus::kOk || rec->output != item.output) return std::nullopt;
  // A best-effort set is up to date only for a run that would write it again.
  if (!rec->tolerance_met && !options.best_effort) return std::nullopt;
  auto bytes = detail::readFileText(item.mesh);
  if (!bytes || fingerprintOf(*bytes, item, options) != rec->fingerprint) return std::nullopt;
  if (fileDigest(outputPath(out_dir, item)) != j["output_digest"].get<std::string>())
    return std::nullopt;
  // The files the mesh referenced when it was fitted must be unchanged too. A record without
  // the list (an older run) is not up to date.
  if (!j.contains("companions") || !j["companions"].is_object()) return std::nullopt;
  for (const auto& [path, digest] : j["companions"].items())
    if (!digest.is_string() || fileDigest(path) != digest.get<std::string>()) return std::nullopt;
  BatchItemReport r = std::move(rec).value();
  r.mesh = item.mesh;
  r.num_spheres = item.tolerance.active() ? 0 : item.fit.num_spheres;
  r.status = BatchStatus::kSkipped;
  return r;
}

}  // namespace

Expected<std::string> batchFingerprint(const BatchItem& item, const BatchOptions& options) {
  auto bytes = detail::readFileText(item.mesh);
  if (!bytes) return bytes.error();
  return fingerprintOf(*bytes, item, options);
}

BatchItemReport runBatchItem(const BatchItem& item, const std::string& out_dir,
                             const BatchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  BatchItemReport rep;
  rep.mesh = item.mesh;
  rep.output = item.output;
  rep.num_spheres = item.tolerance.active() ? 0 : item.fit.num_spheres;
  rep.er_sum = rep.er_union = rep.protrusion = std::numeric_limits<double>::quiet_NaN();
  ItemFiles files;
  Status st;
  const auto body = [&] {
    // The record goes first: a sphere file rewritten by an unfinished run is never taken as up
    // to date.
    std::error_code ec;
    fs::remove(recordPath(out_dir, item), ec);
    st = fitItem(item, out_dir, options, &rep, &files);
  };
  try {
    if (options.threads > 0) {
      tbb::task_arena arena(options.threads);
      arena.execute(body);
    } else {
      body();
    }
  } catch (const std::exception& e) {
    st = Error{ErrorCode::kInvalidData, item.mesh + ": internal error: " + e.what()};
  }
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (st.ok()) {
    try {
      st = writeRecord(out_dir, item, rep, files);
    } catch (const std::exception& e) {
      st = Error{ErrorCode::kWriteFailed, item.output + ": record not written: " + e.what()};
    }
  }
  if (!st.ok()) {
    rep.status = BatchStatus::kError;
    rep.error = st.error().message;
    rep.error_code = st.error().code;
    rep.spheres = 0;
    rep.covered = false;
    rep.repair.clear();
    rep.er_sum = rep.er_union = rep.protrusion = std::numeric_limits<double>::quiet_NaN();
    rep.tolerance_met = !item.tolerance.active();
  }
  return rep;
}

bool batchItemDone(const BatchItem& item, const std::string& out_dir, const BatchOptions& options) {
  return skippedBatchItem(item, out_dir, options).has_value();
}

std::optional<BatchItemReport> skippedBatchItem(const BatchItem& item, const std::string& out_dir,
                                                const BatchOptions& options) {
  try {
    return upToDate(item, out_dir, options);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

BatchItemReport processBatchItem(const BatchItem& item, const std::string& out_dir,
                                 const BatchOptions& options) {
  if (options.resume)
    if (auto done = skippedBatchItem(item, out_dir, options)) return *std::move(done);
  return runBatchItem(item, out_dir, options);
}

}  // namespace sphereset

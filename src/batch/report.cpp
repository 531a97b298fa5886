// The batch's report (batch.hpp): one JSON line per item, read back for resuming, and the
// report file of a run: the folder locked for the run, the lines appended whole to a partial
// report that replaces the last run's report only when the run finishes.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <utility>

#include "batch/batch_internal.hpp"
#include "sphereset/batch.hpp"
#include "sphereset/exit_codes.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset {
namespace {

constexpr const char* kStatusNames[] = {"ok", "error", "skipped"};

// NaN and infinities are not JSON: null.
nlohmann::ordered_json number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

namespace detail {
std::string hex64(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}
}  // namespace detail

const char* batchStatusName(BatchStatus status) { return kStatusNames[static_cast<int>(status)]; }

std::string reportLine(const BatchItemReport& r) {
  nlohmann::ordered_json j;
  j["mesh"] = r.mesh;
  j["output"] = r.output;
  j["status"] = batchStatusName(r.status);
  j["n"] = r.num_spheres;
  j["spheres"] = r.spheres;
  j["er_sum"] = number(r.er_sum);
  j["er_union"] = number(r.er_union);
  j["covered"] = r.covered;
  j["protrusion"] = number(r.protrusion);
  j["tolerance_met"] = r.tolerance_met;
  j["repair"] = r.repair;
  j["seconds"] = number(r.seconds);
  j["error"] = r.error;
  j["fingerprint"] = r.fingerprint;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

Expected<BatchItemReport> parseReportLine(const std::string& line) {
  const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    return Error{ErrorCode::kInvalidData, "report line: not a JSON object"};
  BatchItemReport r;
  const auto str = [&](const char* key, std::string* out) {
    if (!j.contains(key) || !j[key].is_string()) return false;
    *out = j[key].get<std::string>();
    return true;
  };
  // Numbers; null stands for NaN.
  const auto real = [&](const char* key, double* out) {
    if (!j.contains(key)) return false;
    if (j[key].is_null()) {
      *out = std::numeric_limits<double>::quiet_NaN();
      return true;
    }
    if (!j[key].is_number()) return false;
    *out = j[key].get<double>();
    return true;
  };
  const auto integer = [&](const char* key, int* out) {
    if (!j.contains(key) || !j[key].is_number_integer()) return false;
    *out = j[key].get<int>();
    return true;
  };
  std::string status;
  const char* bad = nullptr;
  if (!str("mesh", &r.mesh))
    bad = "mesh";
  else if (!str("output", &r.output))
    bad = "output";
  else if (!str("status", &status))
    bad = "status";
  else if (!integer("n", &r.num_spheres))
    bad = "n";
  else if (!integer("spheres", &r.spheres))
    bad = "spheres";
  else if (!real("er_sum", &r.er_sum))
    bad = "er_sum";
  else if (!real("er_union", &r.er_union))
    bad = "er_union";
  else if (!j.contains("covered") || !j["covered"].is_boolean())
    bad = "covered";
  else if (!real("protrusion", &r.protrusion))
    bad = "protrusion";
  else if (!j.contains("tolerance_met") || !j["tolerance_met"].is_boolean())
    bad = "tolerance_met";
  else if (!str("repair", &r.repair))
    bad = "repair";
  else if (!real("seconds", &r.seconds))
    bad = "seconds";
  else if (!str("error", &r.error))
    bad = "error";
  else if (!str("fingerprint", &r.fingerprint))
    bad = "fingerprint";
  if (bad)
    return Error{ErrorCode::kInvalidData,
                 std::string("report line: \"") + bad + "\" is missing or of the wrong type"};
  r.covered = j["covered"].get<bool>();
  r.tolerance_met = j["tolerance_met"].get<bool>();
  bool known = false;
  for (int s = 0; s < 3; ++s)
    if (status == kStatusNames[s]) {
      r.status = static_cast<BatchStatus>(s);
      known = true;
    }
  if (!known) return Error{ErrorCode::kInvalidData, "report line: unknown status '" + status + "'"};
  return r;
}

std::string batchReportPath(const std::string& out_dir) {
  return (std::filesystem::path(out_dir) / "report.jsonl").string();
}

void countBatchItem(const BatchItemReport& r, BatchTotals* t) {
  ++t->items;
  if (r.status == BatchStatus::kSkipped) ++t->skipped;
  if (r.status == BatchStatus::kError) ++t->failed;
  if (r.status == BatchStatus::kOk) ++t->fitted;
  if (r.status != BatchStatus::kError && !r.covered) ++t->uncovered;
  if (r.status != BatchStatus::kError && !r.tolerance_met) ++t->unmet;
}

BatchEnd batchEnd(const BatchTotals& t, const std::string& input, const std::string& out_dir) {
  BatchEnd end;
  end.summary = std::to_string(t.items) + " items: " + std::to_string(t.fitted) + " fitted, " +
                std::to_string(t.skipped) + " skipped, " + std::to_string(t.failed) + " failed";
  const std::string of = " of " + std::to_string(t.items) + " items ";
  const std::string report = batchReportPath(out_dir);
  if (t.failed > 0) {
    end.exit_code = kExitItemsFailed;
    end.message = input + ": " + std::to_string(t.failed) + of + "failed" +
                  (t.unmet > 0 ? ", " + std::to_string(t.unmet) + " more missed their tolerance"
                               : std::string()) +
                  " (see " + report + ")";
  } else if (t.unmet > 0) {
    end.exit_code = kExitToleranceNotMet;
    end.message = input + ": " + std::to_string(t.unmet) + of +
                  "missed their tolerance (the best count found written; see " + report + ")";
  } else if (t.uncovered > 0) {
    end.exit_code = kExitUncovered;
    end.message = input + ": " + std::to_string(t.uncovered) + of +
                  "failed the coverage check (written anyway; see " + report + ")";
  }
  return end;
}

std::string batchPartialReportPath(const std::string& out_dir) {
  return batchReportPath(out_dir) + ".partial";
}

namespace {

// Appends `text` in one write (retried until whole).
Status appendToFile(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    return Error{ErrorCode::kWriteFailed, path + ": cannot open (" + std::strerror(errno) + ")"};
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
    if (w <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      return Error{ErrorCode::kWriteFailed, path + ": cannot write (" + why + ")"};
    }
    done += static_cast<size_t>(w);
  }
  if (::close(fd) != 0)
    return Error{ErrorCode::kWriteFailed, path + ": cannot write (" + std::strerror(errno) + ")"};
  return {};
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", &tm);
  return buf;
}

}  // namespace

Expected<BatchReport> BatchReport::start(const std::string& out_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path state = fs::path(out_dir) / detail::kBatchStateFolder;
  fs::create_directories(state, ec);
  if (ec)
    return Error{ErrorCode::kWriteFailed,
                 out_dir + ": cannot create the folder (" + ec.message() + ")"};
  const std::string lock_path = (state / "lock").string();
  BatchReport r;
  r.out_dir_ = out_dir;
  r.lock_fd_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (r.lock_fd_ < 0)
    return Error{ErrorCode::kWriteFailed,
                 lock_path + ": cannot open (" + std::strerror(errno) + ")"};
  if (::flock(r.lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = errno == EWOULDBLOCK;
    const std::string why = std::strerror(errno);
    if (!busy) return Error{ErrorCode::kWriteFailed, lock_path + ": cannot lock (" + why + ")"};
    char holder[128] = {};
    const ssize_t got = ::pread(r.lock_fd_, holder, sizeof holder - 1, 0);
    std::string who = got > 0 ? std::string(holder, static_cast<size_t>(got)) : "";
    while (!who.empty() && (who.back() == '\n' || who.back() == '\r')) who.pop_back();
    return Error{ErrorCode::kWriteFailed,
                 out_dir + ": another batch run" + (who.empty() ? "" : " (" + who + ")") +
                     " is writing to this folder; wait for it to end or choose another folder"};
  }
  const std::string me = "pid " + std::to_string(::getpid()) + ", started " + utcNow() + "\n";
  if (::ftruncate(r.lock_fd_, 0) != 0 || ::pwrite(r.lock_fd_, me.data(), me.size(), 0) < 0)
    return Error{ErrorCode::kWriteFailed,
                 lock_path + ": cannot write (" + std::strerror(errno) + ")"};
  if (Status st = writeTextFile(batchPartialReportPath(out_dir), ""); !st) return st.error();
  return r;
}

Status BatchReport::append(const BatchItemReport& report) {
  return appendToFile(batchPartialReportPath(out_dir_), reportLine(report) + "\n");
}

Status BatchReport::finish() {
  const std::string from = batchPartialReportPath(out_dir_), to = batchReportPath(out_dir_);
  if (std::rename(from.c_str(), to.c_str()) != 0)
    return Error{ErrorCode::kWriteFailed, to + ": cannot write (" + std::strerror(errno) + ")"};
  release();
  return {};
}

void BatchReport::release() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // closing the descriptor releases the flock
  lock_fd_ = -1;
}

BatchReport::BatchReport(BatchReport&& other) noexcept
    : out_dir_(std::move(other.out_dir_)), lock_fd_(std::exchange(other.lock_fd_, -1)) {}

BatchReport& BatchReport::operator=(BatchReport&& other) noexcept {
  if (this != &other) {
    release();
    out_dir_ = std::move(other.out_dir_);
    lock_fd_ = std::exchange(other.lock_fd_, -1);
  }
  return *this;
}

BatchReport::~BatchReport() { release(); }

}  // namespace sphereset

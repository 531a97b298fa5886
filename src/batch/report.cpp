// The batch's report (batch.hpp): one JSON line per item, read back for resuming, and the
// report file, appended one whole line per write so a killed batch leaves whole lines only.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>

#include "batch/batch_internal.hpp"
#include "sphereset/batch.hpp"
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

Status startBatchReport(const std::string& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec)
    return Error{ErrorCode::kWriteFailed,
                 out_dir + ": cannot create the folder (" + ec.message() + ")"};
  return writeTextFile(batchReportPath(out_dir), "");
}

Status appendBatchReport(const std::string& out_dir, const BatchItemReport& report) {
  const std::string path = batchReportPath(out_dir);
  const std::string line = reportLine(report) + "\n";
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    return Error{ErrorCode::kWriteFailed, path + ": cannot open (" + std::strerror(errno) + ")"};
  size_t done = 0;
  while (done < line.size()) {
    const ssize_t w = ::write(fd, line.data() + done, line.size() - done);
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

}  // namespace sphereset

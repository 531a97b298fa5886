// The items of a batch (batch.hpp): the meshes of a folder that assimp can import, or the lines
// of a CSV or JSONL manifest with per-item fit options. Not from the paper: the batch runs its
// fit (Wang et al. 2006) over collections.
#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "batch/batch_internal.hpp"
#include "sphereset/batch.hpp"
#include "sphereset/sphere_io.hpp"
#include "util/read_file.hpp"

namespace sphereset {
namespace fs = std::filesystem;
namespace {

// The manifest's columns: the mesh, its output, and the rows of the fit's option table.
std::string columnList() {
  return "mesh, output, " + optionNames(fitRequestOptions()) + ", " +
         optionNames(toleranceOptionTable());
}

bool knownColumn(const std::string& name) {
  return name == "mesh" || name == "output" || findOption(fitRequestOptions(), name) != nullptr ||
         findOption(toleranceOptionTable(), name) != nullptr;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// A relative path with '/' separators, no "." or ".." parts, not empty.
bool cleanRelativePath(const std::string& p) {
  if (p.empty() || p.front() == '/' || p.back() == '/') return false;
  size_t start = 0;
  while (start <= p.size()) {
    size_t end = p.find('/', start);
    if (end == std::string::npos) end = p.size();
    const std::string part = p.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") return false;
    start = end + 1;
  }
  return true;
}

// Sets the option `key` of the item from `text`; an error message (without the location) when
// the value is bad.
std::string applyValue(const std::string& key, const std::string& text, BatchItem* item,
                       bool* output_given) {
  const std::string quoted = key + " '" + text + "'";
  if (key == "mesh") {
    if (text.empty()) return "the mesh path is empty";
    item->mesh = text;
  } else if (key == "output") {
    if (!cleanRelativePath(text))
      return quoted + ": expected a relative path without '.' or '..' parts";
    if (!sphereFormatFromPath(text))
      return quoted + ": the extension must be .txt, .xyzr, .json, .sph, .yaml or .yml";
    item->output = text;
    *output_given = true;
  } else if (findOption(toleranceOptionTable(), key) != nullptr) {
    if (Status st = setToleranceOption(&item->tolerance, key, text); !st) return st.error().message;
  } else {
    // The fit's options: parsed and checked by the library's table, as the command line's.
    if (Status st = setFitRequestOption(&item->fit, key, text); !st) return st.error().message;
  }
  return {};
}

// An item read from a manifest: the mesh path as written, whether an output was given.
struct ManifestItem {
  BatchItem item;
  bool output_given = false;
};

// The fields of one CSV line; fields may be quoted ("a, b" with "" for a quote). Empty message
// on success.
std::string splitCsv(const std::string& line, std::vector<std::string>* fields) {
  fields->clear();
  size_t i = 0;
  while (true) {
    std::string field;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i < line.size() && line[i] == '"') {
      ++i;
      bool closed = false;
      while (i < line.size()) {
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          closed = true;
          break;
        }
        field += line[i++];
      }
      if (!closed) return "unterminated quoted field";
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      if (i < line.size() && line[i] != ',') return "text after a quoted field";
    } else {
      const size_t end = std::min(line.find(',', i), line.size());
      field = trim(line.substr(i, end - i));
      i = end;
    }
    fields->push_back(std::move(field));
    if (i >= line.size()) break;
    ++i;  // the comma
  }
  return {};
}

// The lines of a text, without their '\n' and a trailing '\r'.
std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

Error lineError(const std::string& path, size_t line, const std::string& what) {
  return Error{ErrorCode::kInvalidData, path + ":" + std::to_string(line) + ": " + what};
}

Expected<std::vector<ManifestItem>> readCsv(const std::string& path, const std::string& text,
                                            const BatchOptions& defaults) {
  const std::vector<std::string> lines = splitLines(text);
  std::vector<std::string> header, fields;
  std::vector<ManifestItem> items;
  for (size_t ln = 0; ln < lines.size(); ++ln) {
    const std::string t = trim(lines[ln]);
    if (t.empty() || t.front() == '#') continue;
    const std::string bad = splitCsv(lines[ln], &fields);
    if (!bad.empty()) return lineError(path, ln + 1, bad);
    if (header.empty()) {
      for (const std::string& f : fields) {
        const std::string name = lower(f);
        if (!knownColumn(name))
          return lineError(path, ln + 1,
                           "unknown column '" + f + "' (expected " + columnList() + ")");
        if (std::find(header.begin(), header.end(), name) != header.end())
          return lineError(path, ln + 1, "column '" + f + "' given twice");
        header.push_back(name);
      }
      if (std::find(header.begin(), header.end(), "mesh") == header.end())
        return lineError(path, ln + 1, "the header has no 'mesh' column");
      continue;
    }
    if (fields.size() != header.size())
      return lineError(path, ln + 1,
                       "expected " + std::to_string(header.size()) +
                           " fields as in the header, found " + std::to_string(fields.size()));
    ManifestItem mi;
    mi.item.fit = defaults.fit;
    mi.item.tolerance = defaults.tolerance;
    mi.item.tolerance.max_spheres_given = false;  // the batch's cap binds the lines with a limit
    mi.item.origin = path + ":" + std::to_string(ln + 1);
    for (size_t c = 0; c < header.size(); ++c) {
      if (fields[c].empty() && header[c] != "mesh") continue;  // the batch's value
      const std::string err = applyValue(header[c], fields[c], &mi.item, &mi.output_given);
      if (!err.empty()) return lineError(path, ln + 1, err);
    }
    if (Status st = checkToleranceRequest(mi.item.fit, mi.item.tolerance); !st)
      return lineError(path, ln + 1, st.error().message);
    items.push_back(std::move(mi));
  }
  return items;
}

Expected<std::vector<ManifestItem>> readJsonl(const std::string& path, const std::string& text,
                                              const BatchOptions& defaults) {
  const std::vector<std::string> lines = splitLines(text);
  std::vector<ManifestItem> items;
  for (size_t ln = 0; ln < lines.size(); ++ln) {
    if (trim(lines[ln]).empty()) continue;
    const nlohmann::json j = nlohmann::json::parse(lines[ln], nullptr, false);
    if (j.is_discarded()) return lineError(path, ln + 1, "not valid JSON");
    if (!j.is_object()) return lineError(path, ln + 1, "expected a JSON object");
    if (!j.contains("mesh")) return lineError(path, ln + 1, "no \"mesh\" key");
    ManifestItem mi;
    mi.item.fit = defaults.fit;
    mi.item.tolerance = defaults.tolerance;
    mi.item.tolerance.max_spheres_given = false;  // the batch's cap binds the lines with a limit
    mi.item.origin = path + ":" + std::to_string(ln + 1);
    for (const auto& [key, value] : j.items()) {
      if (!knownColumn(key))
        return lineError(path, ln + 1,
                         "unknown key \"" + key + "\" (expected " + columnList() + ")");
      if (value.is_null() && key != "mesh") continue;  // the batch's value
      std::string v;
      if (value.is_string())
        v = value.get<std::string>();
      else if (value.is_number())
        v = value.dump();
      else
        return lineError(path, ln + 1, "\"" + key + "\": expected a string or a number");
      const std::string err = applyValue(key, v, &mi.item, &mi.output_given);
      if (!err.empty()) return lineError(path, ln + 1, err);
    }
    if (Status st = checkToleranceRequest(mi.item.fit, mi.item.tolerance); !st)
      return lineError(path, ln + 1, st.error().message);
    items.push_back(std::move(mi));
  }
  return items;
}

// "a/b.obj" -> "a/b.json".
std::string replaceExtension(const std::string& rel, const std::string& format) {
  return fs::path(rel).replace_extension("." + format).generic_string();
}

// Gives each item without an output one derived from `rel` (its path relative to the input),
// keeping the mesh's extension where two would meet; then checks that no two outputs are the
// same.
Status assignOutputs(std::vector<ManifestItem>* items, const std::vector<std::string>& rel,
                     const std::string& format) {
  std::map<std::string, int> count;
  for (size_t i = 0; i < items->size(); ++i)
    if (!(*items)[i].output_given) ++count[replaceExtension(rel[i], format)];
  for (size_t i = 0; i < items->size(); ++i) {
    ManifestItem& mi = (*items)[i];
    if (mi.output_given) continue;
    const std::string plain = replaceExtension(rel[i], format);
    mi.item.output = count[plain] > 1 ? rel[i] + "." + format : plain;
  }
  std::map<std::string, const BatchItem*> seen;
  for (const ManifestItem& mi : *items) {
    auto [it, fresh] = seen.emplace(mi.item.output, &mi.item);
    if (!fresh)
      return Error{ErrorCode::kInvalidData, mi.item.origin + ": writes " + mi.item.output + " as " +
                                                it->second->origin +
                                                " does; give each an 'output'"};
  }
  return {};
}

Expected<std::vector<BatchItem>> listFolder(const std::string& input, const BatchOptions& options) {
  const Assimp::Importer importer;
  std::vector<std::string> rel;
  std::error_code ec;
  const fs::path root(input);
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
  if (ec)
    return Error{ErrorCode::kUnreadable, input + ": cannot read the folder (" + ec.message() + ")"};
  for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec)
      return Error{ErrorCode::kUnreadable,
                   input + ": cannot read the folder (" + ec.message() + ")"};
    const fs::path& p = it->path();
    if (p.filename().string().front() == '.') {
      if (it->is_directory(ec)) it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file(ec)) continue;
    const std::string ext = detail::extensionOf(p.string());
    if (ext.size() < 2 || !importer.IsExtensionSupported(ext)) continue;
    rel.push_back(p.lexically_relative(root).generic_string());
  }
  std::sort(rel.begin(), rel.end());
  std::vector<ManifestItem> items(rel.size());
  for (size_t i = 0; i < rel.size(); ++i) {
    items[i].item.mesh = (root / rel[i]).string();
    items[i].item.fit = options.fit;
    items[i].item.tolerance = options.tolerance;
    items[i].item.origin = items[i].item.mesh;
  }
  if (Status st = assignOutputs(&items, rel, options.format); !st) return st.error();
  std::vector<BatchItem> out;
  out.reserve(items.size());
  for (ManifestItem& mi : items) out.push_back(std::move(mi.item));
  return out;
}

// What the batch's cap and best effort need: a limit (checkToleranceRequest's rule for the cap).
Status checkTolerancePurpose(const BatchOptions& options) {
  FitRequest none;  // n is checked apart (the batch's, then each line's)
  if (Status st = checkToleranceRequest(none, options.tolerance); !st) return st;
  return checkBestEffort(options.best_effort, options.tolerance);
}

Expected<std::vector<BatchItem>> listManifest(const std::string& input, const std::string& ext,
                                              const BatchOptions& options) {
  auto text = detail::readFileText(input);
  if (!text) return text.error();
  // A byte order mark, as spreadsheet programs write, is not part of the first column's name.
  if (text->rfind("\xEF\xBB\xBF", 0) == 0) text->erase(0, 3);
  auto items = ext == ".csv" ? readCsv(input, *text, options) : readJsonl(input, *text, options);
  if (!items) return items.error();
  // The batch's cap or best effort with a limit on no line would change nothing: refused.
  const bool limited = std::any_of(items->begin(), items->end(), [](const ManifestItem& mi) {
    return mi.item.tolerance.active();
  });
  if (!items->empty() && !limited)
    if (Status st = checkTolerancePurpose(options); !st)
      return Error{st.error().code, input + ": " + st.error().message + " (no line gives one)"};
  const fs::path dir = fs::path(input).parent_path();
  std::vector<std::string> rel;
  for (ManifestItem& mi : *items) {
    const fs::path written(mi.item.mesh);
    const fs::path mesh = written.is_absolute() ? written : dir / written;
    mi.item.mesh = mesh.string();
    // The mesh's path below the manifest's folder, or its file name when it is elsewhere.
    const std::string r =
        written.is_absolute() ? std::string() : written.lexically_normal().generic_string();
    rel.push_back(cleanRelativePath(r) ? r : mesh.filename().string());
  }
  if (Status st = assignOutputs(&*items, rel, options.format); !st) return st.error();
  std::vector<BatchItem> out;
  out.reserve(items->size());
  for (ManifestItem& mi : *items) out.push_back(std::move(mi.item));
  return out;
}

}  // namespace

Status checkBatchOptions(const BatchOptions& options) {
  if (auto f = sphereFormatFromName(options.format); !f) return f.error();
  if (Status st = checkFitRequest(options.fit); !st) return st;
  if (options.threads < 0) return Error{ErrorCode::kInvalidArgument, "threads must be >= 0"};
  return {};
}

Expected<std::vector<BatchItem>> listBatchItems(const std::string& input,
                                                const BatchOptions& options) {
  if (Status st = checkBatchOptions(options); !st) return st.error();
  std::error_code ec;
  const fs::file_status s = fs::status(input, ec);
  if (ec || !fs::exists(s))
    return Error{ErrorCode::kUnreadable, input + ": no such file or folder"};
  // n with a limit, both the batch's, whatever the input (a manifest's lines are checked each).
  ToleranceOptions limits_only = options.tolerance;
  limits_only.max_spheres_given = false;
  if (Status st = checkToleranceRequest(options.fit, limits_only); !st) return st.error();
  if (fs::is_directory(s)) {
    // Every item takes the batch's tolerance: its cap and best effort need its limit.
    if (Status st = checkTolerancePurpose(options); !st) return st.error();
    return listFolder(input, options);
  }
  const std::string ext = detail::extensionOf(input);
  if (ext == ".csv" || ext == ".jsonl") return listManifest(input, ext, options);
  return Error{ErrorCode::kUnreadable,
               input + ": expected a folder of meshes or a manifest (.csv or .jsonl)"};
}

}  // namespace sphereset

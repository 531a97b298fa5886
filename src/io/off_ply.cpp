// Readers for OFF (the Geomview format: header, counts, vertices, polygons) and PLY 1.0 (Turk's
// Stanford polygon format: ascii and binary, with elements and typed properties declared in the
// header). They produce raw vertex and triangle arrays; welding, degenerate removal and
// orientation happen in cleanMesh like for every other format.
#include "io/off_ply.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

#include "util/number_text.hpp"
#include "util/read_file.hpp"

namespace sphereset::detail {

namespace {

// The shortest text that reads back as `x` ("7", "1.5", "1e+30", "nan").
std::string shortest(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// A whole token as an integer (an optional sign, then digits only).
bool parseInteger(std::string_view t, int64_t* out) {
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), *out);
  return ec == std::errc() && end == t.data() + t.size() && !t.empty();
}

}  // namespace

Expected<RawMesh> readOff(const std::string& path) {
  auto text = readFileText(path);
  if (!text) return text.error();
  return parseOff(*text, path);
}

Expected<RawMesh> parseOff(const std::string& text, const std::string& name) {
  size_t pos = 0;
  int64_t lineno = 0;
  std::vector<std::string_view> tok;
  // Next non-empty line with comments removed, split into tokens.
  auto next = [&]() {
    while (pos < text.size()) {
      size_t e = text.find('\n', pos);
      if (e == std::string::npos) e = text.size();
      std::string_view line(text.data() + pos, e - pos);
      pos = std::min(e + 1, text.size());
      ++lineno;
      const size_t hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
      tok.clear();
      size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const size_t b = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > b) tok.push_back(line.substr(b, i - b));
      }
      if (!tok.empty()) return true;
    }
    return false;
  };
  auto bad = [&](const std::string& what) {
    return Error{ErrorCode::kUnreadable, name + ":" + std::to_string(lineno) + ": " + what};
  };
  if (!next() || tok[0].find("OFF") == std::string_view::npos)
    return bad("not an OFF file (no OFF header)");
  tok.erase(tok.begin());
  if (tok.empty() && !next()) return bad("missing vertex and face counts");
  int64_t nv = 0, nf = 0;
  if (tok.size() < 2 || !parseInteger(tok[0], &nv) || !parseInteger(tok[1], &nf))
    return bad("malformed vertex and face counts");
  if (nv < 0 || nf < 0 || nv > (int64_t{1} << 31) - 1 || nf > (int64_t{1} << 31) - 1)
    return bad("vertex or face count out of range");
  // Each vertex takes a line of at least 6 bytes ("0 0 0\n") and each face one of at least 2:
  // the counts reserve no more than what the rest of the file can hold.
  const int64_t rest = static_cast<int64_t>(text.size() - pos);
  std::vector<Vec3> verts;
  verts.reserve(static_cast<size_t>(std::min(nv, rest / 6 + 1)));
  std::string number;
  for (int64_t i = 0; i < nv; ++i) {
    if (!next())
      return bad("expected a vertex \"x y z\", found the end of the file after " +
                 std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if (tok.size() < 3) return bad("expected a vertex \"x y z\"");
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      number.assign(tok[k]);
      if (!detail::parseNumber(number, &p[k])) return bad("malformed vertex coordinate");
    }
    verts.push_back(p);
  }
  std::vector<Triangle> tris;
  tris.reserve(static_cast<size_t>(std::min(nf, static_cast<int64_t>(text.size() - pos) / 2 + 1)));
  std::vector<int64_t> idx;
  for (int64_t f = 0; f < nf; ++f) {
    if (!next())
      return bad("expected a face, found the end of the file after " + std::to_string(f) + " of " +
                 std::to_string(nf) + " faces");
    int64_t k = 0;
    if (!parseInteger(tok[0], &k) || k < 0 || static_cast<uint64_t>(k) + 1 > tok.size())
      return bad("malformed face");
    idx.resize(static_cast<size_t>(k));
    for (int64_t j = 0; j < k; ++j)
      if (!parseInteger(tok[1 + j], &idx[j])) return bad("malformed face");
    for (int64_t v : idx)
      if (v < 0 || v >= nv)
        return Error{ErrorCode::kInvalidData, name + ":" + std::to_string(lineno) +
                                                  ": face references vertex " + std::to_string(v) +
                                                  " of " + std::to_string(nv)};
    for (int64_t j = 1; j + 1 < k; ++j)
      tris.push_back({static_cast<int32_t>(idx[0]), static_cast<int32_t>(idx[j]),
                      static_cast<int32_t>(idx[j + 1])});
  }
  return RawMesh{std::move(verts), std::move(tris)};
}

namespace {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64, kBad };

PlyType plyType(const std::string& t) {
  if (t == "char" || t == "int8") return PlyType::kInt8;
  if (t == "uchar" || t == "uint8") return PlyType::kUint8;
  if (t == "short" || t == "int16") return PlyType::kInt16;
  if (t == "ushort" || t == "uint16") return PlyType::kUint16;
  if (t == "int" || t == "int32") return PlyType::kInt32;
  if (t == "uint" || t == "uint32") return PlyType::kUint32;
  if (t == "float" || t == "float32") return PlyType::kFloat32;
  if (t == "double" || t == "float64") return PlyType::kFloat64;
  return PlyType::kBad;
}

int plySize(PlyType t) {
  switch (t) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
    case PlyType::kBad:
      return 0;
  }
  return 0;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kBad;
  bool list = false;
  PlyType count_type = PlyType::kBad;
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  std::vector<PlyProperty> props;
};

// Cursor over the file's data section, ascii or binary.
class PlyData {
 public:
  PlyData(const std::string& buf, size_t pos, int format) : buf_(buf), pos_(pos), format_(format) {}
  bool ok() const { return ok_; }
  size_t remaining() const { return buf_.size() - std::min(pos_, buf_.size()); }

  double read(PlyType t) {
    if (!ok_) return 0.0;
    if (format_ == 0) {
      // Blanks before the number, as strtod skipped them; the number read whatever the locale.
      while (pos_ < buf_.size() && std::isspace(static_cast<unsigned char>(buf_[pos_]))) ++pos_;
      double v = 0.0;
      const size_t used =
          detail::parseNumberPrefix(buf_.data() + pos_, buf_.data() + buf_.size(), &v);
      if (used == 0) {
        ok_ = false;
        return 0.0;
      }
      pos_ += used;
      return v;
    }
    const int n = plySize(t);
    if (pos_ + n > buf_.size()) {
      ok_ = false;
      return 0.0;
    }
    unsigned char b[8];
    std::memcpy(b, buf_.data() + pos_, n);
    pos_ += n;
    const bool swap = (format_ == 2) == (std::endian::native == std::endian::little);
    if (swap)
      for (int i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
      case PlyType::kInt8: {
        int8_t v;
        std::memcpy(&v, b, 1);
        return v;
      }
      case PlyType::kUint8: {
        uint8_t v;
        std::memcpy(&v, b, 1);
        return v;
      }
      case PlyType::kInt16: {
        int16_t v;
        std::memcpy(&v, b, 2);
        return v;
      }
      case PlyType::kUint16: {
        uint16_t v;
        std::memcpy(&v, b, 2);
        return v;
      }
      case PlyType::kInt32: {
        int32_t v;
        std::memcpy(&v, b, 4);
        return v;
      }
      case PlyType::kUint32: {
        uint32_t v;
        std::memcpy(&v, b, 4);
        return v;
      }
      case PlyType::kFloat32: {
        float v;
        std::memcpy(&v, b, 4);
        return v;
      }
      case PlyType::kFloat64: {
        double v;
        std::memcpy(&v, b, 8);
        return v;
      }
      case PlyType::kBad:
        break;
    }
    ok_ = false;
    return 0.0;
  }

 private:
  const std::string& buf_;
  size_t pos_;
  int format_;  // 0 ascii, 1 binary little endian, 2 binary big endian
  bool ok_ = true;
};

// The header: format, elements and their properties, and where the data starts.
struct PlyHeader {
  int format = -1;  // 0 ascii, 1 binary little endian, 2 binary big endian
  std::vector<PlyElement> elements;
  size_t data_start = 0;
};

Expected<PlyHeader> parsePlyHeader(const std::string& buf, const std::string& path) {
  auto bad = [&](const std::string& what) {
    return Error{ErrorCode::kUnreadable, path + ": " + what};
  };
  size_t pos = 0;
  auto line = [&](std::string* out) {
    if (pos >= buf.size()) return false;
    size_t e = buf.find('\n', pos);
    if (e == std::string::npos) e = buf.size();
    *out = buf.substr(pos, e - pos);
    if (!out->empty() && out->back() == '\r') out->pop_back();
    pos = e < buf.size() ? e + 1 : buf.size();  // never past the end: the data starts there
    return true;
  };
  std::string l;
  if (!line(&l) || l != "ply") return bad("not a PLY file (no 'ply' magic)");
  int format = -1;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (line(&l)) {
    std::istringstream is(l);
    std::string kw;
    is >> kw;
    if (kw == "format") {
      std::string f;
      is >> f;
      format = f == "ascii"                  ? 0
               : f == "binary_little_endian" ? 1
               : f == "binary_big_endian"    ? 2
                                             : -1;
      if (format < 0) return bad("unknown PLY format '" + f + "'");
    } else if (kw == "element") {
      PlyElement e;
      if (!(is >> e.name >> e.count) || e.count < 0 || e.count > (int64_t{1} << 31))
        return bad("malformed element line '" + l + "'");
      elements.push_back(e);
    } else if (kw == "property") {
      if (elements.empty()) return bad("property before any element");
      PlyProperty p;
      std::string t;
      is >> t;
      if (t == "list") {
        std::string ct, it;
        is >> ct >> it >> p.name;
        p.list = true;
        p.count_type = plyType(ct);
        p.type = plyType(it);
        if (p.count_type == PlyType::kBad) return bad("unknown PLY type '" + ct + "'");
      } else {
        p.type = plyType(t);
        is >> p.name;
      }
      if (p.type == PlyType::kBad) return bad("unknown PLY property type in '" + l + "'");
      elements.back().props.push_back(p);
    } else if (kw == "end_header") {
      ended = true;
      break;
    }  // comment, obj_info and blank lines are ignored
  }
  if (!ended || format < 0) return bad("incomplete PLY header");
  return PlyHeader{format, std::move(elements), pos};
}

// Vertex indices of one face or strip, each checked before its conversion to an integer:
// indices may be stored as floating-point values, and a NaN or out-of-range value would make
// the conversion undefined. -1 (a restart) is allowed in strips. `where` names the item.
Status checkedIndices(const std::vector<double>& values, int64_t nv, bool strip,
                      const std::string& where, std::vector<int64_t>* list) {
  list->resize(values.size());
  for (size_t j = 0; j < values.size(); ++j) {
    const double x = values[j];
    if (!std::isfinite(x) || x != std::floor(x))
      return Error{ErrorCode::kInvalidData,
                   where + ": vertex index " + shortest(x) + " is not an integer"};
    if (x >= static_cast<double>(nv) || (x < 0.0 && !(strip && x == -1.0)))
      return Error{ErrorCode::kInvalidData, where + " references vertex " + shortest(x) + " of " +
                                                std::to_string(std::max<int64_t>(nv, 0))};
    (*list)[j] = static_cast<int64_t>(x);
  }
  return {};
}

// The triangles of a face (a fan from its first vertex) or of a triangle strip: triangle j is
// (s_j, s_j+1, s_j+2), with the first two swapped on odd j so that all triangles keep the
// strip's orientation; -1 restarts the strip.
void addPolygon(const std::vector<int64_t>& list, bool strip, std::vector<Triangle>* out) {
  if (!strip) {
    for (size_t j = 1; j + 1 < list.size(); ++j)
      out->push_back({static_cast<int32_t>(list[0]), static_cast<int32_t>(list[j]),
                      static_cast<int32_t>(list[j + 1])});
    return;
  }
  size_t begin = 0;
  for (size_t j = 0; j <= list.size(); ++j) {
    if (j < list.size() && list[j] >= 0) continue;
    for (size_t a = begin; a + 2 < j; ++a) {
      const bool odd = (a - begin) % 2 == 1;
      const int32_t s0 = static_cast<int32_t>(list[a]), s1 = static_cast<int32_t>(list[a + 1]),
                    s2 = static_cast<int32_t>(list[a + 2]);
      out->push_back(odd ? Triangle{s1, s0, s2} : Triangle{s0, s1, s2});
    }
    begin = j + 1;
  }
}

}  // namespace

Expected<RawMesh> readPly(const std::string& path) {
  auto text = readFileText(path);
  if (!text) return text.error();
  return parsePly(*text, path);
}

Expected<RawMesh> parsePly(const std::string& buf, const std::string& path) {
  auto bad = [&](const std::string& what) {
    return Error{ErrorCode::kUnreadable, path + ": " + what};
  };
  auto header = parsePlyHeader(buf, path);
  if (!header) return header.error();
  const int format = header->format;
  RawMesh out;
  PlyData data(buf, header->data_start, format);
  int64_t nv = -1;
  std::vector<double> values;
  std::vector<int64_t> list;
  for (const PlyElement& e : header->elements) {
    const bool is_vertex = e.name == "vertex";
    const bool is_face = e.name == "face";
    const bool is_strip = e.name == "tristrips";
    int ix = -1, iy = -1, iz = -1, iidx = -1;
    for (size_t k = 0; k < e.props.size(); ++k) {
      const std::string& n = e.props[k].name;
      if (n == "x") ix = static_cast<int>(k);
      if (n == "y") iy = static_cast<int>(k);
      if (n == "z") iz = static_cast<int>(k);
      if (e.props[k].list && (n == "vertex_indices" || n == "vertex_index"))
        iidx = static_cast<int>(k);
    }
    if (is_vertex) {
      if (ix < 0 || iy < 0 || iz < 0) return bad("vertex element without x, y and z");
      nv = e.count;
      // Reserve no more items than the rest of the file can hold: in binary each takes the
      // bytes of its scalars and list counts, in ascii two characters per property at least.
      int64_t item_bytes = 0;
      for (const PlyProperty& pr : e.props)
        item_bytes += format == 0 ? 2 : plySize(pr.list ? pr.count_type : pr.type);
      const int64_t fit = static_cast<int64_t>(data.remaining()) / std::max<int64_t>(item_bytes, 1);
      out.vertices.reserve(static_cast<size_t>(std::min(e.count, fit + 1)));
    }
    if (e.props.empty()) continue;  // nothing to read, whatever the count
    for (int64_t i = 0; i < e.count; ++i) {
      Vec3 p = Vec3::Zero();
      for (size_t k = 0; k < e.props.size(); ++k) {
        const PlyProperty& pr = e.props[k];
        if (!pr.list) {
          const double v = data.read(pr.type);
          if (static_cast<int>(k) == ix) p.x() = v;
          if (static_cast<int>(k) == iy) p.y() = v;
          if (static_cast<int>(k) == iz) p.z() = v;
          continue;
        }
        // A count is a whole number, and every item takes at least one byte of what is left.
        const double cnt = data.read(pr.count_type);
        if (!data.ok() || !(cnt >= 0.0 && cnt <= 1e7) || cnt != std::floor(cnt) ||
            cnt > static_cast<double>(data.remaining()))
          return bad("malformed list in element '" + e.name + "'");
        values.resize(static_cast<size_t>(cnt));
        for (double& x : values) x = data.read(pr.type);
        if (static_cast<int>(k) != iidx || !(is_face || is_strip)) continue;
        const Status st = checkedIndices(values, nv, is_strip,
                                         path + ": " + e.name + " " + std::to_string(i), &list);
        if (!st) return st.error();
        addPolygon(list, is_strip, &out.triangles);
      }
      if (!data.ok())
        return bad("truncated data in element '" + e.name + "' at item " + std::to_string(i));
      if (is_vertex) out.vertices.push_back(p);
    }
  }
  if (nv < 0) return bad("no vertex element");
  return out;
}

}  // namespace sphereset::detail

// A robot description's XML text, read and checked before any XML library sees it
// (xml_text.hpp): the checks every robot reader shares.
#include "robot/xml_text.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sphereset/limits.hpp"
#include "util/utf8.hpp"

namespace sphereset::detail {

int xmlDepth(const std::string& xml, int limit) {
  int depth = 0, deepest = 0;
  size_t i = 0;
  auto skipPast = [&](const char* end) {
    const size_t e = xml.find(end, i);
    i = e == std::string::npos ? xml.size() : e + std::strlen(end);
  };
  while (i < xml.size() && deepest <= limit) {
    if (xml[i] != '<') {
      ++i;
      continue;
    }
    if (xml.compare(i, 4, "<!--") == 0) {
      skipPast("-->");
    } else if (xml.compare(i, 9, "<![CDATA[") == 0) {
      skipPast("]]>");
    } else if (i + 1 < xml.size() && (xml[i + 1] == '?' || xml[i + 1] == '!')) {
      skipPast(">");
    } else if (i + 1 < xml.size() && xml[i + 1] == '/') {
      --depth;
      skipPast(">");
    } else {
      // An opening tag: to its '>' outside quotes; "/>" closes it at once.
      char quote = 0;
      size_t j = i + 1;
      for (; j < xml.size(); ++j) {
        if (quote != 0) {
          if (xml[j] == quote) quote = 0;
        } else if (xml[j] == '"' || xml[j] == '\'') {
          quote = xml[j];
        } else if (xml[j] == '>') {
          break;
        }
      }
      if (j >= xml.size() || xml[j - 1] != '/') deepest = std::max(deepest, ++depth);
      i = j + 1;
    }
  }
  return deepest;
}

Expected<std::string> readXmlText(const std::string& path, const char* kind) {
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path, ec)) {
    return Error{ErrorCode::kUnreadable, path + ": cannot open the " + kind + " file"};
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string xml = buffer.str();
  if (const size_t bad = firstInvalidUtf8(xml); bad != std::string::npos) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned char>(xml[bad]));
    return Error{ErrorCode::kInvalidData, path + ": not UTF-8 text (byte " + hex + " at offset " +
                                              std::to_string(bad) + ")"};
  }
  if (xmlDepth(xml, limits::kMaxXmlDepth) > limits::kMaxXmlDepth)
    return Error{ErrorCode::kInvalidData, path + ": elements nested more than " +
                                              std::to_string(limits::kMaxXmlDepth) +
                                              " deep (the limit)"};
  // A document type declaration (internal entities, as in "billion laughs", or external ones):
  // no robot description needs one and the XML readers do not expand entities, so the file is
  // refused by name instead of failing later on a missing element.
  if (xml.find("<!DOCTYPE") != std::string::npos || xml.find("<!ENTITY") != std::string::npos)
    return Error{ErrorCode::kInvalidData, path +
                                              ": a document type declaration (<!DOCTYPE> or "
                                              "<!ENTITY>): entities are not read in a " +
                                              kind};
  return xml;
}

}  // namespace sphereset::detail

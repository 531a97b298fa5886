// Private: a robot description's XML text, read and checked before any XML library sees it.
#pragma once

#include <string>

#include "sphereset/status.hpp"

namespace sphereset::detail {

// The file's text. Errors (one line, naming the file; `kind` is "URDF" or "MJCF"): the file
// missing, a folder or unreadable (kUnreadable); not UTF-8 (TinyXML 2.6 steps over its buffer on
// some malformed sequences); elements nested deeper than limits::kMaxXmlDepth (the XML readers
// recurse once per level); a document type declaration (entities are not read) (kInvalidData).
Expected<std::string> readXmlText(const std::string& path, const char* kind);

// The deepest nesting of elements in `xml` (a scan that skips comments, CDATA, declarations and
// quoted attribute values), stopping once it passes `limit`.
int xmlDepth(const std::string& xml, int limit);

}  // namespace sphereset::detail

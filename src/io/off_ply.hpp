// Private: readers for the formats parsed without assimp (see load.cpp for why), from a file
// or from its contents in memory (the fuzzers).
#pragma once

#include <string>
#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

struct RawMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;  // indices checked against the vertex count
};

// OFF / COFF / NOFF with '#' comments anywhere; polygons are fanned into triangles.
Expected<RawMesh> readOff(const std::string& path);
// The same on a file's contents held in memory; `name` is used in error messages.
Expected<RawMesh> parseOff(const std::string& text, const std::string& name);

// PLY 1.0, ascii and binary (little and big endian): vertex x/y/z of any scalar type, faces
// as index lists (fanned), triangle strips ("tristrips", -1 restarts, alternating winding).
// Other elements and properties are skipped.
Expected<RawMesh> readPly(const std::string& path);
Expected<RawMesh> parsePly(const std::string& text, const std::string& name);

}  // namespace sphereset::detail
